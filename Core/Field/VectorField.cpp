// SPDX-License-Identifier: BSD-3-Clause
#include "VectorField.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>

namespace bp
{

std::string GridGeometry::validate() const
{
  std::ostringstream err;
  for (int a = 0; a < 3; ++a)
  {
    if (this->dims[a] < 1)
    {
      return "the field has no points";
    }
  }
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (this->dims[a] > 1)
    {
      ++axes;
      if (!(std::isfinite(this->spacing[a]) && this->spacing[a] > 0.0))
      {
        err << "the field's spacing along axis "
            << "XYZ"[a] << " is " << this->spacing[a] << "; it must be positive";
        return err.str();
      }
    }
    if (!std::isfinite(this->origin[a]))
    {
      return "the field's origin is not finite";
    }
  }
  if (axes == 0)
  {
    return "the field has a single point; it needs at least two points along one axis";
  }
  for (int a = 0; a < 3; ++a)
  {
    const std::vector<double>& c = this->coordinates[a];
    if (c.empty())
    {
      continue;
    }
    if (c.size() != std::size_t(this->dims[a]))
    {
      err << "the field has " << c.size() << " coordinates along axis "
          << "XYZ"[a] << " for " << this->dims[a] << " points";
      return err.str();
    }
    for (std::size_t i = 0; i < c.size(); ++i)
    {
      if (!std::isfinite(c[i]) || (i > 0 && !(c[i] > c[i - 1])))
      {
        err << "the field's coordinates along axis "
            << "XYZ"[a] << " must be finite and strictly increasing (point " << i << " is at "
            << c[i] << (i > 0 ? ", after " + std::to_string(c[i - 1]) : std::string()) << ")";
        return err.str();
      }
    }
  }
  for (int a = 0; a < 3; ++a)
  {
    // Cell indices are computed in float, exact up to 2^24.
    if (this->dims[a] > (1 << 24))
    {
      err << "the field has " << this->dims[a] << " points along axis "
          << "XYZ"[a] << "; at most 16777216 are supported";
      return err.str();
    }
  }
  return this->checkScale();
}

double GridGeometry::smallestCell(int a) const
{
  if (this->dims[a] < 2)
  {
    return 0.0;
  }
  const std::vector<double>& c = this->coordinates[a];
  if (c.empty())
  {
    return this->spacing[a];
  }
  double smallest = c[1] - c[0];
  for (std::size_t i = 2; i < c.size(); ++i)
  {
    smallest = std::min(smallest, c[i] - c[i - 1]);
  }
  return smallest;
}

std::string GridGeometry::checkScale() const
{
  // The engine computes in float: positions relative to the grid's first
  // point, cell widths and their inverses, and squared distances.
  std::ostringstream err;
  for (int a = 0; a < 3; ++a)
  {
    if (std::abs(this->origin[a]) > MaxCoordinate)
    {
      err << "the field's first point lies at " << this->origin[a] << " along "
          << "XYZ"[a] << ", beyond the " << MaxCoordinate
          << " the engine's arithmetic supports; translate or rescale the data";
      return err.str();
    }
    if (this->dims[a] < 2)
    {
      continue;
    }
    const double length = this->coordinate(a, this->dims[a] - 1) - this->coordinate(a, 0);
    const double cell = this->smallestCell(a);
    if (!(length <= MaxCoordinate))
    {
      err << "the field spans " << length << " along "
          << "XYZ"[a] << ", beyond the " << MaxCoordinate
          << " the engine's arithmetic supports; rescale the coordinates";
      return err.str();
    }
    // The output's world coordinates are doubles: far enough from the world
    // origin, points a cell apart become one (1e25 + 1 == 1e25).
    const double far = std::max(std::abs(this->origin[a]), std::abs(this->origin[a] + length));
    if (!(cell >= far * MinCellWidthPerDistance))
    {
      err << "the field lies at " << far << " along "
          << "XYZ"[a] << ", too far from the world origin for its cells of " << cell
          << ": double-precision coordinates there cannot tell its points apart; translate the "
             "data nearer the origin";
      return err.str();
    }
    if (!(cell >= MinCellWidth) || !(cell >= length * MinRelativeCellWidth))
    {
      err << "the field's cells along "
          << "XYZ"[a] << " are as narrow as " << cell << " in a span of " << length
          << ", finer than the engine's float positions resolve (cells must be at least "
          << MinCellWidth << " wide and " << MinRelativeCellWidth
          << " of the span); rescale the coordinates";
      return err.str();
    }
  }
  return std::string();
}

void GridGeometry::setCoordinates(int a, std::vector<double> values)
{
  this->dims[a] = int(values.size());
  if (!values.empty())
  {
    this->origin[a] = values.front();
    this->spacing[a] =
      values.size() > 1 ? (values.back() - values.front()) / double(values.size() - 1) : 1.0;
  }
  this->coordinates[a] = std::move(values);
}

double GridGeometry::coordinate(int a, int i) const
{
  return this->isRectilinear(a) ? this->coordinates[a][std::size_t(i)]
                                : this->origin[a] + i * this->spacing[a];
}

void GridGeometry::translate(const std::array<double, 3>& shift)
{
  for (int a = 0; a < 3; ++a)
  {
    this->origin[a] -= shift[a];
    for (double& c : this->coordinates[a])
    {
      c -= shift[a];
    }
  }
}

bool GridGeometry::sameAs(const GridGeometry& other, double tolerance) const
{
  if (this->dims != other.dims)
  {
    return false;
  }
  for (int a = 0; a < 3; ++a)
  {
    for (int i = 0; i < this->dims[a]; ++i)
    {
      if (!(std::abs(this->coordinate(a, i) - other.coordinate(a, i)) <= tolerance))
      {
        return false;
      }
    }
  }
  return true;
}

std::array<double, 6> GridGeometry::bounds() const
{
  std::array<double, 6> b;
  for (int a = 0; a < 3; ++a)
  {
    b[2 * a] = this->coordinate(a, 0);
    b[2 * a + 1] = this->coordinate(a, std::max(this->dims[a] - 1, 0));
  }
  return b;
}

double GridGeometry::diagonal() const
{
  const auto b = this->bounds();
  double d2 = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    d2 += (b[2 * a + 1] - b[2 * a]) * (b[2 * a + 1] - b[2 * a]);
  }
  return std::sqrt(d2);
}

double GridGeometry::cellLength() const
{
  double sum = 0.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    if (this->dims[a] > 1)
    {
      sum += std::abs(this->spacing[a]);
      ++axes;
    }
  }
  return axes > 0 ? sum / axes : 1.0;
}

VectorField::VectorField(const GridGeometry& grid, FieldSlice slice)
  : VectorField(grid, std::move(slice), FieldSlice())
{
}

VectorField::VectorField(const GridGeometry& grid, FieldSlice first, FieldSlice second)
  : Grid(grid)
  , First(std::move(first))
  , Second(std::move(second))
{
  this->FirstData = this->First.velocity ? this->First.velocity->data() : nullptr;
  this->SecondData = this->Second.velocity ? this->Second.velocity->data() : nullptr;
  // A mask that does not fit the grid is ignored (validate() says so).
  auto outside = [&grid](const FieldSlice& s) -> const std::uint8_t*
  {
    return s.outsideCells && s.outsideCells->size() == grid.pointCount() ? s.outsideCells->data()
                                                                         : nullptr;
  };
  this->FirstOutside = outside(this->First);
  this->SecondOutside = this->SecondData ? outside(this->Second) : nullptr;
  std::size_t stride = 1;
  for (int a = 0; a < 3; ++a)
  {
    this->Degenerate[a] = grid.dims[a] <= 1;
    this->Origin[a] = float(grid.origin[a] - grid.firstIndex[a] * grid.spacing[a]);
    this->IndexShift[a] = grid.firstIndex[a];
    this->InverseSpacing[a] = this->Degenerate[a] ? 0.0f : float(1.0 / grid.spacing[a]);
    this->MaxIndex[a] = float(std::max(grid.dims[a] - 1, 0));
    this->LowIndex[a] = float(grid.firstIndex[a]);
    this->HighIndex[a] = float(grid.firstIndex[a] + std::max(grid.dims[a] - 1, 0));
    this->LastCell[a] = grid.firstIndex[a] + std::max(grid.dims[a] - 2, 0);
    this->Rectilinear[a] = false;
    this->Lower[a] = float(grid.coordinate(a, 0));
    this->Upper[a] = float(grid.coordinate(a, std::max(grid.dims[a] - 1, 0)));
    this->Bounds.lower[a] = this->Lower[a];
    this->Bounds.upper[a] = this->Upper[a];
    this->Bounds.degenerate[a] = this->Degenerate[a];
    this->Periodic[a] = grid.periodic[a] && !this->Degenerate[a];
    this->Bounds.periodic[a] = this->Periodic[a];
    // A plane repeats its single layer: the "next" corner is the same point.
    this->Stride[a] = this->Degenerate[a] ? 0 : stride;
    stride *= std::size_t(std::max(grid.dims[a], 1));
    if (grid.isRectilinear(a) && !this->Degenerate[a] &&
      grid.coordinates[a].size() == std::size_t(grid.dims[a]))
    {
      // Widths are taken in double before rounding, so that nearly equal
      // float coordinates still give a finite, accurate weight.
      const std::vector<double>& c = grid.coordinates[a];
      std::vector<float>& table = this->AxisTable[a];
      table.resize(2 * c.size());
      this->Rectilinear[a] = true;
      for (std::size_t i = 0; i < c.size(); ++i)
      {
        table[2 * i] = float(c[i]);
        table[2 * i + 1] = i + 1 < c.size() ? float(1.0 / (c[i + 1] - c[i])) : 0.0f;
      }
    }
  }
}

void VectorField::locateRectilinear(int a, float x, std::size_t& cell, float& fraction) const
{
  // The last cell whose first point is at or below x, by binary search.
  // bp_common.glsl's bpLocate finds the same cell on the same table without
  // a search: a table of uniform bins, each at most half the narrowest cell,
  // gives the cell of the bin's start, then at most three compares correct it.
  const std::vector<float>& table = this->AxisTable[a];
  x = std::min(std::max(x, this->Lower[a]), this->Upper[a]);
  int lo = 0, hi = int(table.size() / 2) - 2;
  while (lo < hi)
  {
    const int mid = (lo + hi + 1) / 2;
    if (table[2 * mid] <= x)
    {
      lo = mid;
    }
    else
    {
      hi = mid - 1;
    }
  }
  cell = std::size_t(lo);
  fraction = std::min((x - table[2 * lo]) * table[2 * lo + 1], 1.0f);
}

std::string VectorField::validate() const
{
  const std::string gridError = this->Grid.validate();
  if (!gridError.empty())
  {
    return gridError;
  }
  const std::size_t expected = 3 * this->Grid.pointCount();
  float largest = 0.0f; // over both time steps, for the scale check
  for (const FieldSlice* s : { &this->First, &this->Second })
  {
    if (s == &this->Second && !s->velocity)
    {
      continue;
    }
    if (!s->velocity || s->velocity->size() != expected)
    {
      return "the vector array does not have one 3-component tuple per grid point";
    }
    if (s->outsideCells && s->outsideCells->size() != this->Grid.pointCount())
    {
      return "the domain mask does not have one value per grid point";
    }
    const std::vector<float>& v = *s->velocity;
    for (std::size_t i = 0; i < v.size(); ++i)
    {
      largest = std::max(largest, std::abs(v[i])); // NaN leaves it, and is caught below
      if (!std::isfinite(v[i]))
      {
        std::ostringstream err;
        err << "the vector array has a non-finite value (" << v[i] << ") at point " << i / 3
            << " of the time step at t = " << s->time
            << "; replace NaN/Inf values first (e.g. with the Calculator)";
        return err.str();
      }
    }
  }
  const std::string scaleError = this->checkVelocityScale(largest);
  if (!scaleError.empty())
  {
    return scaleError;
  }
  if (this->Second.velocity && !(this->Second.time > this->First.time))
  {
    return "the field's two time steps are not in increasing time order";
  }
  return std::string();
}

std::string VectorField::checkVelocityScale(float largest) const
{
  std::ostringstream err;
  if (largest > MaxVelocity)
  {
    err << "the vector array holds values up to " << largest << ", beyond the " << MaxVelocity
        << " the engine's float arithmetic supports (speeds are squared); check the data's "
           "byte order and units";
    return err.str();
  }
  double cell = HUGE_VAL;
  for (int a = 0; a < 3; ++a)
  {
    if (this->Grid.dims[a] > 1)
      cell = std::min(cell, this->Grid.smallestCell(a));
  }
  if (double(largest) / cell > MaxGradient)
  {
    err << "the field's velocities (up to " << largest << ") change over cells as narrow as "
        << cell << ", so its gradients (the Vorticity array) would overflow float; rescale the "
        << "coordinates or the velocities";
    return err.str();
  }
  return std::string();
}

VectorField::SamplingConstants VectorField::samplingConstants() const
{
  SamplingConstants c;
  for (int a = 0; a < 3; ++a)
  {
    c.origin[a] = this->Origin[a];
    c.inverseSpacing[a] = this->InverseSpacing[a];
    c.maxIndex[a] = this->MaxIndex[a];
    c.lower[a] = this->Lower[a];
    c.upper[a] = this->Upper[a];
    c.degenerate[a] = this->Degenerate[a];
    c.rectilinear[a] = !this->AxisTable[a].empty();
    c.periodic[a] = this->Periodic[a];
  }
  return c;
}

bool VectorField::outsideCellOf(const float p[3], float weight) const
{
  const std::size_t base = this->cellIndexAt(p);
  return (this->FirstOutside && this->FirstOutside[base]) ||
    (weight > 0.0f && this->SecondOutside && this->SecondOutside[base]);
}

bool VectorField::outsideCellIndexed(const int c[3], float weight) const
{
  const std::size_t base = std::size_t(c[0]) * this->Stride[0] +
    std::size_t(c[1]) * this->Stride[1] + std::size_t(c[2]) * this->Stride[2];
  return (this->FirstOutside && this->FirstOutside[base]) ||
    (weight > 0.0f && this->SecondOutside && this->SecondOutside[base]);
}

float VectorField::pointCoordinate(int a, int i) const
{
  return this->Rectilinear[a]
    ? this->AxisTable[a][2 * std::size_t(i)]
    : this->Origin[a] + float(i + this->IndexShift[a]) / this->InverseSpacing[a];
}

float VectorField::timeWeight(double t) const
{
  if (!this->Second.velocity)
  {
    return 0.0f;
  }
  const double w = (t - this->First.time) / (this->Second.time - this->First.time);
  return float(std::min(std::max(w, 0.0), 1.0));
}

void VectorField::gradient(
  const float* data, std::size_t base, const float f[3], const float w[3], float d[3][3]) const
{
  const auto [c000, c100, c010, c110, c001, c101, c011, c111] = this->cornersOf(data, base);
  for (int k = 0; k < 3; ++k)
  {
    // Along x: the four x edges' differences, interpolated in y then z.
    const float x0 = (c100[k] - c000[k]) + f[1] * ((c110[k] - c010[k]) - (c100[k] - c000[k]));
    const float x1 = (c101[k] - c001[k]) + f[1] * ((c111[k] - c011[k]) - (c101[k] - c001[k]));
    d[0][k] = (x0 + f[2] * (x1 - x0)) * w[0];
    // Along y: the y edges, interpolated in x then z.
    const float y0 = (c010[k] - c000[k]) + f[0] * ((c110[k] - c100[k]) - (c010[k] - c000[k]));
    const float y1 = (c011[k] - c001[k]) + f[0] * ((c111[k] - c101[k]) - (c011[k] - c001[k]));
    d[1][k] = (y0 + f[2] * (y1 - y0)) * w[1];
    // Along z: the z edges, interpolated in x then y.
    const float z0 = (c001[k] - c000[k]) + f[0] * ((c101[k] - c100[k]) - (c001[k] - c000[k]));
    const float z1 = (c011[k] - c010[k]) + f[0] * ((c111[k] - c110[k]) - (c011[k] - c010[k]));
    d[2][k] = (z0 + f[1] * (z1 - z0)) * w[2];
  }
}

float VectorField::sampleWithVorticity(const float p[3], float weight, float v[3]) const
{
  float curl[3];
  this->sampleWithCurl(p, weight, v, curl);
  return std::sqrt(curl[0] * curl[0] + curl[1] * curl[1] + curl[2] * curl[2]);
}

void VectorField::sampleWithCurl(const float p[3], float weight, float v[3], float curl[3]) const
{
  std::size_t base = 0;
  float f[3], w[3];
  this->locateWithSlopes(p, base, f, w);
  this->sampleCell(base, f, weight, v); // the cell is found once for both
  // d[a][k] = d v_k / d x_a
  float d[3][3];
  this->blendedGradient(base, f, w, weight, d);
  curl[0] = d[1][2] - d[2][1];
  curl[1] = d[2][0] - d[0][2];
  curl[2] = d[0][1] - d[1][0];
}

void VectorField::blendedGradient(
  std::size_t base, const float f[3], const float w[3], float weight, float d[3][3]) const
{
  const bool blend = this->SecondData && weight > 0.0f;
#if BOUNDPARTICLES_SSE2
  if (this->Stride[0] == 1)
  {
    __m128 lanes[3];
    this->gradientLanes(this->FirstData, base, f, w, lanes);
    if (blend)
    {
      __m128 second[3];
      this->gradientLanes(this->SecondData, base, f, w, second);
      blendLanes(lanes, second, weight);
    }
    storeLanes(lanes, d);
  }
  else
#endif
  {
    this->gradient(this->FirstData, base, f, w, d);
    if (blend)
    {
      float d1[3][3];
      this->gradient(this->SecondData, base, f, w, d1);
      for (int a = 0; a < 3; ++a)
      {
        for (int k = 0; k < 3; ++k)
        {
          d[a][k] += weight * (d1[a][k] - d[a][k]);
        }
      }
    }
  }
}

float VectorField::vorticityMagnitude(const float p[3], double t) const
{
  float v[3];
  return this->sampleWithVorticity(p, this->timeWeight(t), v);
}

double VectorField::maxSpeed() const
{
  double m = 0.0;
  const std::vector<float>& v = *this->First.velocity;
  for (std::size_t i = 0; i + 2 < v.size(); i += 3)
  {
    m = std::max(m, double(v[i] * v[i] + v[i + 1] * v[i + 1] + v[i + 2] * v[i + 2]));
  }
  return std::sqrt(m);
}

double VectorField::typicalSpeed() const
{
  const std::vector<float>& v = *this->First.velocity;
  std::vector<double> speeds;
  speeds.reserve(v.size() / 3);
  for (std::size_t i = 0; i + 2 < v.size(); i += 3)
  {
    const double s2 =
      double(v[i]) * v[i] + double(v[i + 1]) * v[i + 1] + double(v[i + 2]) * v[i + 2];
    if (s2 > 0.0 && std::isfinite(s2))
    {
      speeds.push_back(s2);
    }
  }
  if (speeds.empty())
  {
    return 0.0;
  }
  const auto at = speeds.begin() + std::ptrdiff_t(0.9 * double(speeds.size() - 1));
  std::nth_element(speeds.begin(), at, speeds.end());
  return std::sqrt(*at);
}

float dropFlatComponents(
  std::vector<float>& velocity, const std::array<bool, 3>& flat, float& inPlane)
{
  float dropped = 0.0f;
  inPlane = 0.0f;
  for (std::size_t i = 0; i + 2 < velocity.size(); i += 3)
  {
    float kept = 0.0f;
    for (int a = 0; a < 3; ++a)
    {
      float& v = velocity[i + std::size_t(a)];
      if (flat[std::size_t(a)])
      {
        dropped = std::max(dropped, std::abs(v));
        v = 0.0f;
      }
      else
      {
        kept += v * v;
      }
    }
    inPlane = std::max(inPlane, std::sqrt(kept));
  }
  return dropped;
}

} // namespace bp

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VectorField.h
 * @brief A vector field on a uniform or rectilinear grid, sampled trilinearly
 * in space and linearly in time between two time steps (thesis §3.4).
 *
 * An axis may carry explicit, strictly increasing point coordinates (the
 * altitude layers of thesis §3.4): sampling then finds the cell by binary
 * search and interpolates by the position within it, exactly, instead of the
 * thesis' power-law approximation. Both engines weigh with the same float
 * tables (axisTable()); the CPU finds the cell by binary search, the GPU's
 * bpLocate (Shaders/bp_common.glsl) by a table of bins and at most three
 * compares, which lands on the same cell.
 *
 * Positions outside the grid sample the nearest boundary value, as the thesis'
 * clamped 3D textures do; the engine decides separately when an element has
 * left the field. An axis with a single grid point is a plane: sampling ignores
 * it and so does the bounds test, so 2D data sets need no special case.
 */
#ifndef BoundParticles_VectorField_h
#define BoundParticles_VectorField_h

#include "Periodic.h"
#include "Simd.h"
#include "TrilinearAlong.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

/// Point positions x_i = origin + i * spacing, x fastest (VTK's point order),
/// or, along an axis with coordinates, x_i = coordinates[a][i].
struct GridGeometry
{
  std::array<int, 3> dims = { 0, 0, 0 };
  std::array<double, 3> origin = { 0, 0, 0 };
  /// Along a rectilinear axis, the mean spacing (for step and size defaults).
  std::array<double, 3> spacing = { 1, 1, 1 };
  /// Empty for a uniform axis; otherwise one strictly increasing value per point.
  std::array<std::vector<double>, 3> coordinates;
  /// A piece of a distributed run: the index of its point 0 in the whole grid
  /// (0 for a whole grid). Uniform axes then locate from the whole grid's
  /// first point and shift by it, so every piece rounds as the whole does.
  std::array<int, 3> firstIndex = { 0, 0, 0 };
  /// Periodic axes (Periodic.h): the period is the axis's extent, its last
  /// plane standing for its first. Ignored along an axis of one point.
  std::array<bool, 3> periodic = { false, false, false };

  /// Makes axis a rectilinear with these point coordinates (dims, origin and
  /// the mean spacing follow from them).
  void setCoordinates(int a, std::vector<double> values);
  bool isRectilinear(int a) const { return !this->coordinates[a].empty(); }
  /// Position of point i along axis a.
  double coordinate(int a, int i) const;
  /// Moves the grid by -shift (origin and coordinates).
  void translate(const std::array<double, 3>& shift);
  /// Whether two grids place every point within `tolerance` of each other.
  bool sameAs(const GridGeometry& other, double tolerance) const;

  /// The largest coordinate magnitude and span the engine's float
  /// arithmetic supports, and the narrowest cells it resolves (absolute, and
  /// relative to the axis's span).
  static constexpr double MaxCoordinate = 1e30;
  /// Cells at least this share of their distance from the world origin:
  /// 2^-40, some 4,000 double steps apart there.
  static constexpr double MinCellWidthPerDistance = 9.094947017729282e-13;
  static constexpr double MinCellWidth = 1e-30;
  static constexpr double MinRelativeCellWidth = 1e-6;

  std::size_t pointCount() const { return std::size_t(dims[0]) * dims[1] * dims[2]; }
  /// Empty when the grid can carry a flow, otherwise why not (its scale included).
  std::string validate() const;
  /// Empty when coordinates, spans and cell widths are within what the
  /// engine's float arithmetic supports, otherwise what to rescale.
  std::string checkScale() const;
  /// The narrowest cell along axis a (0 for an axis of one point).
  double smallestCell(int a) const;
  std::array<double, 6> bounds() const;
  double diagonal() const;
  /// Mean spacing over the axes with more than one point.
  double cellLength() const;
};

/**
 * The box elements live in: the reposition test's bounds, in the engine's
 * coordinates. An axis of one grid point is a plane and is ignored. A
 * distributed trace samples a piece of the field but tests against the whole
 * field's domain.
 */
struct Domain
{
  std::array<float, 3> lower = { 0, 0, 0 };
  std::array<float, 3> upper = { 0, 0, 0 };
  std::array<bool, 3> degenerate = { true, true, true };
  /// Periodic axes (Periodic.h): no side there, neither to leave nor a wall.
  std::array<bool, 3> periodic = { false, false, false };

  /// Whether axis a has sides: not a plane, not periodic.
  bool bounded(int a) const { return !this->degenerate[a] && !this->periodic[a]; }

  bool contains(const float p[3]) const
  {
    for (int a = 0; a < 3; ++a)
    {
      if (this->bounded(a) && !(p[a] >= this->lower[a] && p[a] <= this->upper[a]))
      {
        return false;
      }
    }
    return true;
  }

  /// Half the period (upper - lower, in float) of each periodic axis; 0
  /// along any other. The draw shader's bpTrailHalfPeriods.
  std::array<float, 3> halfPeriods() const
  {
    std::array<float, 3> half = { 0, 0, 0 };
    for (int a = 0; a < 3; ++a)
    {
      if (this->periodic[a] && !this->degenerate[a])
      {
        half[a] = 0.5f * (this->upper[a] - this->lower[a]);
      }
    }
    return half;
  }

  /// A trail pose across a periodic seam (engine specification 2.6): whether
  /// `pose` and `now` (an element's first particle in a trail pose and in
  /// the state shown) lie farther apart than half a period along a periodic
  /// axis, |pose - now| > halfPeriods() in float (bp_draw_vs_dec.glsl:
  /// bpAcrossPeriodicSeam). Never without a periodic axis.
  bool acrossPeriodicSeam(const float pose[3], const float now[3]) const
  {
    const std::array<float, 3> half = this->halfPeriods();
    for (int a = 0; a < 3; ++a)
    {
      if (half[a] > 0.0f && std::fabs(pose[a] - now[a]) > half[a])
      {
        return true;
      }
    }
    return false;
  }
};

/// One time step: 3 floats per grid point.
struct FieldSlice
{
  double time = 0.0;
  std::shared_ptr<const std::vector<float>> velocity;
  /// Per grid point as a cell's lowest corner: 1 where that cell is outside
  /// the flow's domain (DomainMask.h); null when no cell is.
  std::shared_ptr<const std::vector<std::uint8_t>> outsideCells;
  /// Release Weights (ReleaseWeights.h): one per grid point, or null.
  std::shared_ptr<const std::vector<float>> releaseWeights;
};

/**
 * A flat field (one point along an axis) has no flow across its plane: the
 * velocity's components along `flat` axes are dropped (made 0), so elements
 * stay in the plane instead of leaving it unseen. Returns the largest
 * component dropped (0 where none was), and the largest speed kept in the
 * plane through `inPlane`. `velocity` holds 3 floats per point.
 */
float dropFlatComponents(
  std::vector<float>& velocity, const std::array<bool, 3>& flat, float& inPlane);

class VectorField
{
public:
  /// A steady field: one slice.
  VectorField(const GridGeometry& grid, FieldSlice slice);
  /// An unsteady field between two slices with first.time < second.time.
  VectorField(const GridGeometry& grid, FieldSlice first, FieldSlice second);

  const GridGeometry& grid() const { return this->Grid; }
  bool isSteady() const { return !this->Second.velocity; }

  /// Velocity at p and time t.
  void sample(const float p[3], double t, float v[3]) const
  {
    this->sampleWeighted(p, this->timeWeight(t), v);
  }

  /// Velocity at p where the second slice weighs `weight` (timeWeight()):
  /// the engine's hot loop computes the weights once per step. The cell is
  /// found once for both slices.
  inline void sampleWeighted(const float p[3], float weight, float v[3]) const;

  /// Asks the cache for the grid points sampleWeighted(p, ...) will read,
  /// so that a caller with work queued can hide the wait for memory.
  inline void prefetch(const float p[3]) const;

  /**
   * Velocity at p (as sampleWeighted) and |curl v| there: the curl of the
   * trilinear interpolant in the cell that holds p, so both come from the
   * same eight grid points. Flat axes add no derivative.
   */
  float sampleWithVorticity(const float p[3], float weight, float v[3]) const;
  /// Velocity at p and curl v there, as sampleWithVorticity().
  void sampleWithCurl(const float p[3], float weight, float v[3], float curl[3]) const;
  /**
   * A heavy particle's step (Inertia.h's SlipStepper, `stepper`): the
   * velocity v at p (as sampleWeighted, the same bits), then the stepper's
   * direction q from it, then its step from dv/dt (the slices' difference
   * over their times: the field is linear in time between them; 0 for a
   * steady field) and the velocity's derivative along q, (q . grad) v, of
   * the trilinear interpolant in p's cell, each slice's blended as the
   * values are. That comes from the cell's corners directly
   * (TrilinearAlong.h), never through the whole gradient; in SSE lanes
   * (stepper.direction(Lanes), stepper.step(Lanes, Lanes)) where x is not a
   * plane, component by component (the float overloads) elsewhere.
   */
  template <class Stepper>
  inline void sampleAlong(const float p[3], float weight, Stepper& stepper, float v[3]) const;
  /// |curl v| at p and time t (sampleWithVorticity).
  float vorticityMagnitude(const float p[3], double t) const;

  /// Whether p lies in the grid's bounds (axes of one point are ignored).
  bool contains(const float p[3]) const { return this->Bounds.contains(p); }
  /// Whether the cell that holds p is outside the flow's domain in the
  /// first slice, or in the second where it weighs anything (DomainMask.h).
  bool outsideCellAt(const float p[3], float weight) const
  {
    return (this->FirstOutside || this->SecondOutside) && this->outsideCellOf(p, weight);
  }
  /// The index of the cell that holds p (clamped to the grid), as its lowest
  /// corner's point index: how outsideCells and release masks are indexed.
  inline std::size_t cellIndexAt(const float p[3]) const;
  /// The grid's bounds as a Domain.
  const Domain& domain() const { return this->Bounds; }

  /// The walls of the cells outside the flow (MaskWalls.h): whether any
  /// slice has such cells; the cell that holds p, per axis (this grid's
  /// indices, as cellIndexAt); whether cell `c` is outside as outsideCellAt;
  /// point i's coordinate along a (uniform: origin + i / inverse spacing in
  /// float; rectilinear: its axisTable entry); the last cell along a.
  bool hasOutsideCells() const { return this->FirstOutside || this->SecondOutside; }
  inline void cellOf(const float p[3], int c[3]) const;
  bool outsideCellIndexed(const int c[3], float weight) const;
  float pointCoordinate(int a, int i) const;
  int lastCellOf(int a) const { return this->LastCell[a] - this->IndexShift[a]; }

  /// Largest speed over the grid points of the first slice.
  double maxSpeed() const;
  /// The speed 90% of the first time step's moving points (speed above 0)
  /// are slower than: a typical fast speed, untouched by a few spikes; 0 for
  /// a still field.
  double typicalSpeed() const;

  /// The largest velocity component the engine supports (its square, summed
  /// over three components, must stay finite in float), and the largest
  /// velocity over the narrowest cell (the Vorticity array's differences).
  static constexpr float MaxVelocity = 1e18f;
  static constexpr double MaxGradient = 1e30;

  /// Empty when every value of every slice is finite and within MaxVelocity,
  /// the gradients within MaxGradient, and the slices match the grid.
  std::string validate() const;

  const FieldSlice& firstSlice() const { return this->First; }
  const FieldSlice& secondSlice() const { return this->Second; }

  /// Weight of the second slice at time t (0 for a steady field).
  float timeWeight(double t) const;

  /// The float constants sampling and the bounds test use, so that another
  /// implementation (the GPU engine) computes with the very same numbers.
  struct SamplingConstants
  {
    float origin[3], inverseSpacing[3], maxIndex[3], lower[3], upper[3];
    bool degenerate[3];
    bool rectilinear[3];
    bool periodic[3]; ///< Periodic.h: wrapped by period upper - lower
  };
  SamplingConstants samplingConstants() const;

  /// Along a rectilinear axis, per point i: its float coordinate and the float
  /// inverse width of cell i (0 for the last point), interleaved. Empty along
  /// a uniform axis.
  const std::vector<float>& axisTable(int a) const { return this->AxisTable[a]; }

private:
  /// outsideCellAt() where a slice has outside cells.
  bool outsideCellOf(const float p[3], float weight) const;
  /// The MaxVelocity and MaxGradient checks, given the largest |component|.
  std::string checkVelocityScale(float largest) const;

  /// The cell index and the position within it along axis a.
  inline void locate(int a, float x, std::size_t& cell, float& fraction) const;
  void locateRectilinear(int a, float x, std::size_t& cell, float& fraction) const;
  /// The cell's eight grid points in `data`, x fastest: c000, c100, c010, c110,
  /// c001, c101, c011, c111 (coincident along a flat axis).
  inline std::array<const float*, 8> cornersOf(const float* data, std::size_t base) const;
  /// The velocity in the located cell at `base` with fractions f, both slices
  /// blended (sampleWeighted once the cell is found).
  inline void sampleCell(std::size_t base, const float f[3], float weight, float v[3]) const;
  /// Trilinear interpolation in the cell at `base` (a point index) with weights f.
  inline void interpolate(const float* data, std::size_t base, const float f[3], float v[3]) const;
  /// The cell that holds p: its base point, fractions and the fractions'
  /// derivatives along each axis.
  inline void locateWithSlopes(const float p[3], std::size_t& base, float f[3], float w[3]) const;
  /// The gradient at the located cell, both slices blended (sampleWithCurl).
  void blendedGradient(
    std::size_t base, const float f[3], const float w[3], float weight, float d[3][3]) const;
  /// The velocity's derivatives d[a][k] = d v_k / d x_a of that interpolant,
  /// with w[a] the derivative of the fraction along axis a.
  void gradient(
    const float* data, std::size_t base, const float f[3], const float w[3], float d[3][3]) const;
#if BOUNDPARTICLES_SSE2
  /// The same with the components in SSE lanes 0-2 (Stride[0] == 1).
  inline void gradientLanes(
    const float* data, std::size_t base, const float f[3], const float w[3], __m128 d[3]) const;
  /// d += weight (second - d), lane by lane: the slices' gradients blended.
  static inline void blendLanes(__m128 d[3], const __m128 second[3], float weight);
  /// Lanes 0-2 of each of d's three vectors into out's rows.
  static inline void storeLanes(const __m128 d[3], float out[3][3]);
#endif
#if BOUNDPARTICLES_SSE2
  /// The same in SSE lanes 0-2, where x is not a plane (Stride[0] == 1).
  inline __m128 interpolateLanes(const float* data, std::size_t base, const float f[3]) const;
  /// One slice's interpolation in the cell at `base`, kept for a derivative
  /// along a direction (sampleAlong): in SSE lanes where x is not a plane.
  inline void interpolateAlong(
    const float* data, std::size_t base, const float f[3], TrilinearAlong<Lanes>& cell) const;
#endif
  inline void interpolateAlong(
    const float* data, std::size_t base, const float f[3], TrilinearAlong<float> cell[3]) const;

  GridGeometry Grid;
  FieldSlice First;
  FieldSlice Second;
  // Precomputed for the hot loop.
  float Origin[3];   ///< the whole grid's first point (GridGeometry::firstIndex)
  int IndexShift[3]; ///< GridGeometry::firstIndex: this grid's first point in the whole's
  float LowIndex[3]; ///< this grid's first and last points, in the whole grid's indices
  float HighIndex[3];
  float InverseSpacing[3];
  float MaxIndex[3]; ///< this grid's last point index (samplingConstants)
  int LastCell[3];   ///< the last cell's index in the whole grid's (IndexShift on a plane)
  bool Rectilinear[3];
  float Lower[3];
  float Upper[3];
  bool Degenerate[3];
  bool Periodic[3]; ///< periodic axes of more than one point (Periodic.h)
  Domain Bounds;
  std::size_t Stride[3];
  std::array<std::vector<float>, 3> AxisTable;
  const float* FirstData = nullptr;            ///< First.velocity's values
  const float* SecondData = nullptr;           ///< Second.velocity's, or null when steady
  const std::uint8_t* FirstOutside = nullptr;  ///< First.outsideCells', or null
  const std::uint8_t* SecondOutside = nullptr; ///< Second.outsideCells', or null
};

inline void VectorField::locate(int a, float x, std::size_t& cell, float& fraction) const
{
  if (this->Periodic[a])
  {
    x = wrapPeriodic(x, this->Lower[a], this->Upper[a]); // across the seam
  }
  if (this->Rectilinear[a])
  {
    this->locateRectilinear(a, x, cell, fraction);
    return;
  }
  // In the whole grid's indices, from its first point, so that a piece of a
  // distributed run finds the whole grid's cell and fraction to the bit; the
  // piece's own index is then an integer shift away.
  float g = (x - this->Origin[a]) * this->InverseSpacing[a];
  // Clamped to this grid's points, so that NaN lands on the first rather
  // than indexing out of the grid.
  g = g > this->LowIndex[a] ? g : this->LowIndex[a];
  g = g < this->HighIndex[a] ? g : this->HighIndex[a];
  // g >= 0, so truncation is floor; the last cell takes points on the upper
  // boundary, so i + 1 stays valid.
  const int i = std::min(int(g), this->LastCell[a]);
  fraction = g - float(i);
  cell = std::size_t(i - this->IndexShift[a]);
}

inline std::array<const float*, 8> VectorField::cornersOf(const float* data, std::size_t base) const
{
  const std::size_t sx = this->Stride[0], sy = this->Stride[1], sz = this->Stride[2];
  return { data + 3 * base, data + 3 * (base + sx), data + 3 * (base + sy),
    data + 3 * (base + sx + sy), data + 3 * (base + sz), data + 3 * (base + sx + sz),
    data + 3 * (base + sy + sz), data + 3 * (base + sx + sy + sz) };
}

inline void VectorField::interpolate(
  const float* data, std::size_t base, const float f[3], float v[3]) const
{
  const auto [c000, c100, c010, c110, c001, c101, c011, c111] = this->cornersOf(data, base);
  for (int k = 0; k < 3; ++k)
  {
    const float x00 = c000[k] + f[0] * (c100[k] - c000[k]);
    const float x10 = c010[k] + f[0] * (c110[k] - c010[k]);
    const float x01 = c001[k] + f[0] * (c101[k] - c001[k]);
    const float x11 = c011[k] + f[0] * (c111[k] - c011[k]);
    const float y0 = x00 + f[1] * (x10 - x00);
    const float y1 = x01 + f[1] * (x11 - x01);
    v[k] = y0 + f[2] * (y1 - y0);
  }
}

#if BOUNDPARTICLES_SSE2
inline __m128 VectorField::interpolateLanes(
  const float* data, std::size_t base, const float f[3]) const
{
  // The two corners of a cell edge along x are 6 consecutive floats; two
  // overlapping 4-float loads hold them, and the three components are
  // interpolated in lanes 0-2 with the scalar path's very operations, so both
  // paths give the same bits. The loads stay in the array: the edge's second
  // corner is a grid point, and the last load ends on its z.
  const __m128 fx = _mm_set1_ps(f[0]);
  auto edge = [data, fx](std::size_t corner)
  {
    const float* c = data + 3 * corner;
    const __m128 first = _mm_loadu_ps(c);       // x0 y0 z0 x1
    const __m128 shifted = _mm_loadu_ps(c + 2); // z0 x1 y1 z1
    const __m128 second = _mm_shuffle_ps(shifted, shifted, _MM_SHUFFLE(0, 3, 2, 1));
    return _mm_add_ps(first, _mm_mul_ps(fx, _mm_sub_ps(second, first)));
  };
  const std::size_t sy = this->Stride[1], sz = this->Stride[2];
  const __m128 x00 = edge(base), x10 = edge(base + sy);
  const __m128 x01 = edge(base + sz), x11 = edge(base + sy + sz);
  const __m128 fy = _mm_set1_ps(f[1]);
  const __m128 y0 = _mm_add_ps(x00, _mm_mul_ps(fy, _mm_sub_ps(x10, x00)));
  const __m128 y1 = _mm_add_ps(x01, _mm_mul_ps(fy, _mm_sub_ps(x11, x01)));
  return _mm_add_ps(y0, _mm_mul_ps(_mm_set1_ps(f[2]), _mm_sub_ps(y1, y0)));
}
#endif

inline std::size_t VectorField::cellIndexAt(const float p[3]) const
{
  std::size_t base = 0;
  for (int a = 0; a < 3; ++a)
  {
    std::size_t i;
    float f;
    this->locate(a, p[a], i, f);
    base += i * this->Stride[a];
  }
  return base;
}

inline void VectorField::cellOf(const float p[3], int c[3]) const
{
  for (int a = 0; a < 3; ++a)
  {
    std::size_t i;
    float f;
    this->locate(a, p[a], i, f);
    c[a] = int(i);
  }
}

inline void VectorField::prefetch(const float p[3]) const
{
#if defined(__GNUC__)
  const std::size_t base = this->cellIndexAt(p);
  const std::size_t sy = this->Stride[1], sz = this->Stride[2];
  for (const float* data : { this->FirstData, this->SecondData })
  {
    if (!data)
    {
      continue;
    }
    // Each of the cell's four x edges is 6 floats, possibly across two lines.
    for (const std::size_t corner : { base, base + sy, base + sz, base + sy + sz })
    {
      __builtin_prefetch(data + 3 * corner);
      __builtin_prefetch(data + 3 * corner + 5);
    }
  }
#else
  (void)p;
#endif
}

inline void VectorField::sampleWeighted(const float p[3], float weight, float v[3]) const
{
  std::size_t base = 0;
  float f[3];
  for (int a = 0; a < 3; ++a)
  {
    std::size_t i;
    this->locate(a, p[a], i, f[a]);
    base += i * this->Stride[a];
  }
  this->sampleCell(base, f, weight, v);
}

inline void VectorField::sampleCell(
  std::size_t base, const float f[3], float weight, float v[3]) const
{
  const bool blend = this->SecondData && weight > 0.0f;
#if BOUNDPARTICLES_SSE2
  if (this->Stride[0] == 1)
  {
    __m128 r = this->interpolateLanes(this->FirstData, base, f);
    if (blend)
    {
      const __m128 r1 = this->interpolateLanes(this->SecondData, base, f);
      r = _mm_add_ps(r, _mm_mul_ps(_mm_set1_ps(weight), _mm_sub_ps(r1, r)));
    }
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, r);
    v[0] = lanes[0];
    v[1] = lanes[1];
    v[2] = lanes[2];
    return;
  }
#endif
  this->interpolate(this->FirstData, base, f, v);
  if (blend)
  {
    float v1[3];
    this->interpolate(this->SecondData, base, f, v1);
    for (int k = 0; k < 3; ++k)
    {
      v[k] += weight * (v1[k] - v[k]);
    }
  }
}

inline void VectorField::locateWithSlopes(
  const float p[3], std::size_t& base, float f[3], float w[3]) const
{
  base = 0;
  for (int a = 0; a < 3; ++a)
  {
    std::size_t i;
    this->locate(a, p[a], i, f[a]);
    base += i * this->Stride[a];
    // d(fraction)/dx: 0 along a flat axis, where nothing varies.
    w[a] = this->Rectilinear[a] ? this->AxisTable[a][2 * i + 1] : this->InverseSpacing[a];
  }
}

#if BOUNDPARTICLES_SSE2
inline void VectorField::gradientLanes(
  const float* data, std::size_t base, const float f[3], const float w[3], __m128 d[3]) const
{
  // The four x edges as in interpolateLanes: two overlapping loads per edge
  // give both corners in lanes 0-2 without reading past the array. The
  // arithmetic is gradient()'s, operation for operation, so the bits agree.
  auto corners = [data](std::size_t corner, __m128& c0, __m128& c1)
  {
    const float* c = data + 3 * corner;
    c0 = _mm_loadu_ps(c);
    const __m128 shifted = _mm_loadu_ps(c + 2);
    c1 = _mm_shuffle_ps(shifted, shifted, _MM_SHUFFLE(0, 3, 2, 1));
  };
  const std::size_t sy = this->Stride[1], sz = this->Stride[2];
  __m128 c000, c100, c010, c110, c001, c101, c011, c111;
  corners(base, c000, c100);
  corners(base + sy, c010, c110);
  corners(base + sz, c001, c101);
  corners(base + sy + sz, c011, c111);
  const __m128 fx = _mm_set1_ps(f[0]), fy = _mm_set1_ps(f[1]), fz = _mm_set1_ps(f[2]);
  auto lerp = [](__m128 a, __m128 b, __m128 t)
  { return _mm_add_ps(a, _mm_mul_ps(t, _mm_sub_ps(b, a))); };
  const __m128 x0 = lerp(_mm_sub_ps(c100, c000), _mm_sub_ps(c110, c010), fy);
  const __m128 x1 = lerp(_mm_sub_ps(c101, c001), _mm_sub_ps(c111, c011), fy);
  d[0] = _mm_mul_ps(lerp(x0, x1, fz), _mm_set1_ps(w[0]));
  const __m128 y0 = lerp(_mm_sub_ps(c010, c000), _mm_sub_ps(c110, c100), fx);
  const __m128 y1 = lerp(_mm_sub_ps(c011, c001), _mm_sub_ps(c111, c101), fx);
  d[1] = _mm_mul_ps(lerp(y0, y1, fz), _mm_set1_ps(w[1]));
  const __m128 z0 = lerp(_mm_sub_ps(c001, c000), _mm_sub_ps(c101, c100), fx);
  const __m128 z1 = lerp(_mm_sub_ps(c011, c010), _mm_sub_ps(c111, c110), fx);
  d[2] = _mm_mul_ps(lerp(z0, z1, fy), _mm_set1_ps(w[2]));
}

inline void VectorField::blendLanes(__m128 d[3], const __m128 second[3], float weight)
{
  const __m128 weights = _mm_set1_ps(weight);
  for (int a = 0; a < 3; ++a)
  {
    d[a] = _mm_add_ps(d[a], _mm_mul_ps(weights, _mm_sub_ps(second[a], d[a])));
  }
}

inline void VectorField::storeLanes(const __m128 d[3], float out[3][3])
{
  for (int a = 0; a < 3; ++a)
  {
    alignas(16) float lanes[4];
    _mm_store_ps(lanes, d[a]);
    std::copy_n(lanes, 3, out[a]);
  }
}
#endif

#if BOUNDPARTICLES_SSE2
inline void VectorField::interpolateAlong(
  const float* data, std::size_t base, const float f[3], TrilinearAlong<Lanes>& cell) const
{
  // Each x edge's two corners are 6 consecutive floats: two overlapping
  // loads, as interpolateLanes reads them, without reading past the array.
  const std::size_t sy = this->Stride[1], sz = this->Stride[2];
  const std::size_t edges[4] = { base, base + sy, base + sz, base + sy + sz };
  Lanes c[8];
  for (int e = 0; e < 4; ++e)
  {
    const float* corner = data + 3 * edges[e];
    const __m128 shifted = _mm_loadu_ps(corner + 2);
    c[2 * e] = Lanes(_mm_loadu_ps(corner));
    c[2 * e + 1] = Lanes(_mm_shuffle_ps(shifted, shifted, _MM_SHUFFLE(0, 3, 2, 1)));
  }
  cell.interpolate(c, f);
}
#endif

inline void VectorField::interpolateAlong(
  const float* data, std::size_t base, const float f[3], TrilinearAlong<float> cell[3]) const
{
  const std::array<const float*, 8> corners = this->cornersOf(data, base);
  for (int k = 0; k < 3; ++k)
  {
    float c[8];
    for (int i = 0; i < 8; ++i)
    {
      c[i] = corners[i][k];
    }
    cell[k].interpolate(c, f);
  }
}

template <class Stepper>
inline void VectorField::sampleAlong(
  const float p[3], float weight, Stepper& stepper, float v[3]) const
{
  std::size_t base = 0;
  float f[3], slope[3];
  this->locateWithSlopes(p, base, f, slope);
  const bool unsteady = this->SecondData != nullptr;
  // The value as the heavy step always read it (both slices, for du/dt);
  // the derivative blended as sampleCell blends values (not at weight 0).
  const bool blend = unsteady && weight > 0.0f;
  const float rate = unsteady ? float(1.0 / (this->Second.time - this->First.time)) : 0.0f;
#if BOUNDPARTICLES_SSE2
  if (this->Stride[0] == 1)
  {
    TrilinearAlong<Lanes> first, second;
    this->interpolateAlong(this->FirstData, base, f, first);
    Lanes value = first.value, rateOfChange(0.0f);
    if (unsteady)
    {
      this->interpolateAlong(this->SecondData, base, f, second);
      const Lanes change = second.value - first.value;
      value = first.value + Lanes(weight) * change;
      rateOfChange = change * Lanes(rate);
    }
    value.store(v);
    const Lanes g =
      Lanes(_mm_setr_ps(slope[0], slope[1], slope[2], 0.0f)) * stepper.direction(value);
    const Lanes gx = g.broadcast<0>(), gy = g.broadcast<1>(), gz = g.broadcast<2>();
    Lanes along = first.along(gx, gy, gz, f);
    if (blend)
    {
      along = along + Lanes(weight) * (second.along(gx, gy, gz, f) - along);
    }
    stepper.step(rateOfChange, along);
    return;
  }
#endif
  TrilinearAlong<float> first[3], second[3];
  this->interpolateAlong(this->FirstData, base, f, first);
  if (unsteady)
  {
    this->interpolateAlong(this->SecondData, base, f, second);
  }
  float dvdt[3], g[3], along[3];
  for (int k = 0; k < 3; ++k)
  {
    const float change = unsteady ? second[k].value - first[k].value : 0.0f;
    v[k] = unsteady ? first[k].value + weight * change : first[k].value;
    dvdt[k] = change * rate;
    g[k] = slope[k] * stepper.direction(k, v[k]);
  }
  for (int k = 0; k < 3; ++k)
  {
    const float d = first[k].along(g[0], g[1], g[2], f);
    along[k] = blend ? d + weight * (second[k].along(g[0], g[1], g[2], f) - d) : d;
  }
  stepper.step(dvdt, along);
}

} // namespace bp

#endif

// SPDX-License-Identifier: BSD-3-Clause
#include "Engine.h"

#include "CounterHash.h"
#include "Pose.h"
#include "ShapeMatching.h"

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <sstream>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace bp
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

std::array<float, 9> toRowMajor(const Eigen::Matrix3d& m)
{
  std::array<float, 9> r;
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      r[3 * i + j] = float(m(i, j));
    }
  }
  return r;
}

inline bool finite3(const float* p)
{
  return std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]);
}

/**
 * Sizes v to `count` copies of `value` in memory the system may back with
 * huge pages: a step visits elements in space order, not memory order, and
 * with 4 KiB pages nearly every element's state would miss the TLB.
 */
template <class T>
void assignLarge(std::vector<T>& v, std::size_t count, T value)
{
  std::vector<T>().swap(v);
  v.reserve(count);
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::uintptr_t Huge = std::uintptr_t(2) << 20;
  const std::uintptr_t begin = reinterpret_cast<std::uintptr_t>(v.data());
  const std::uintptr_t first = (begin + Huge - 1) & ~(Huge - 1);
  const std::uintptr_t last = (begin + count * sizeof(T)) & ~(Huge - 1);
  if (last > first)
  {
    // Advice only: where it is refused the pages are ordinary.
    madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#endif
  v.assign(count, value);
}
} // namespace

float stableRelaxation(const ElementTemplate& shape)
{
  const std::size_t n = shape.particleCount();
  std::vector<double> load(n, 0.0);
  const auto pinned = [&](std::uint32_t i) { return !shape.pinned.empty() && shape.pinned[i]; };
  for (const Spring& s : shape.springs)
  {
    // The share each end takes: half, all where the other end is pinned.
    const bool pa = pinned(s.a), pb = pinned(s.b);
    load[s.a] += (pa ? 0.0 : (pb ? 1.0 : 0.5)) * s.stiffness;
    load[s.b] += (pb ? 0.0 : (pa ? 1.0 : 0.5)) * s.stiffness;
  }
  const double worst = n ? *std::max_element(load.begin(), load.end()) : 0.0;
  return worst > 0.0 ? float(1.0 / worst) : std::numeric_limits<float>::infinity();
}

std::array<float, 9> rotationFromDegrees(double x, double y, double z)
{
  const double d = Pi / 180.0;
  const Eigen::Matrix3d r = (Eigen::AngleAxisd(z * d, Eigen::Vector3d::UnitZ()) *
    Eigen::AngleAxisd(y * d, Eigen::Vector3d::UnitY()) *
    Eigen::AngleAxisd(x * d, Eigen::Vector3d::UnitX()))
                              .toRotationMatrix();
  return toRowMajor(r);
}

std::array<float, 4> quaternionFromUniforms(float u1, float u2, float u3)
{
  // Shoemake, "Uniform random rotations", Graphics Gems III (1992).
  const float s1 = std::sqrt(1.0f - u1), s2 = std::sqrt(u1);
  const float a = float(2.0 * Pi) * u2, b = float(2.0 * Pi) * u3;
  return { s1 * std::sin(a), s1 * std::cos(a), s2 * std::sin(b), s2 * std::cos(b) };
}

std::array<float, 4> multiplyQuaternions(const float r[4], const std::array<float, 4>& q)
{
  return { r[3] * q[0] + r[0] * q[3] + r[1] * q[2] - r[2] * q[1],
    r[3] * q[1] - r[0] * q[2] + r[1] * q[3] + r[2] * q[0],
    r[3] * q[2] + r[0] * q[1] - r[1] * q[0] + r[2] * q[3],
    r[3] * q[3] - r[0] * q[0] - r[1] * q[1] - r[2] * q[2] };
}

std::array<float, 4> inPlaneQuaternion(int axis, float u, const std::array<float, 4>& first)
{
  // r = (sin(a/2) e_axis, cos(a/2)), then the product r * first.
  const float half = float(Pi) * u;
  float r[4] = { 0, 0, 0, std::cos(half) };
  r[axis] = std::sin(half);
  return multiplyQuaternions(r, first);
}

std::array<float, 4> alongFlowQuaternion(const float v[3], int planeAxis,
  const std::array<float, 9>& frame, const std::array<float, 4>& first)
{
  float d[3] = { v[0], v[1], v[2] };
  if (planeAxis >= 0)
  {
    d[planeAxis] = 0.0f;
  }
  // Scaled by the largest component first, so that any unit of speed, however
  // small or large, normalises without underflow or overflow.
  const float m = std::max(std::max(std::abs(d[0]), std::abs(d[1])), std::abs(d[2]));
  if (!(m > 0.0f) || !(m <= std::numeric_limits<float>::max()))
  {
    return first;
  }
  d[0] = d[0] / m;
  d[1] = d[1] / m;
  d[2] = d[2] / m;
  const float inverse = 1.0f / std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  d[0] = d[0] * inverse;
  d[1] = d[1] * inverse;
  d[2] = d[2] * inverse;
  // a = frame * e_x, the long axis as the frame leaves it.
  const float a[3] = { frame[0], frame[3], frame[6] };
  const float c = a[0] * d[0] + a[1] * d[1] + a[2] * d[2];
  float r[4];
  if (1.0f + c < 1e-6f)
  {
    // Against the flow, within 0.08 degrees (where a x d carries no
    // direction): a half turn about the frame's z axis (the plane's normal
    // on a flat field), which keeps a flat element in its plane.
    r[0] = frame[2];
    r[1] = frame[5];
    r[2] = frame[8];
    r[3] = 0.0f;
  }
  else
  {
    // (a x d, 1 + a.d), normalised: half the angle between a and d.
    r[0] = a[1] * d[2] - a[2] * d[1];
    r[1] = a[2] * d[0] - a[0] * d[2];
    r[2] = a[0] * d[1] - a[1] * d[0];
    r[3] = 1.0f + c;
    const float n = 1.0f / std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + r[3] * r[3]);
    r[0] = r[0] * n;
    r[1] = r[1] * n;
    r[2] = r[2] * n;
    r[3] = r[3] * n;
  }
  return multiplyQuaternions(r, first);
}

std::array<float, 9> rotationFromUniforms(float u1, float u2, float u3)
{
  const std::array<float, 4> q = quaternionFromUniforms(u1, u2, u3);
  std::array<float, 9> R;
  quaternionToMatrix(q.data(), R.data());
  return R;
}

std::array<float, 4> quaternionFromRotation(const std::array<float, 9>& R)
{
  Eigen::Matrix3d m;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m(i, j) = R[3 * i + j];
  const Eigen::Quaterniond q(m);
  return { float(q.x()), float(q.y()), float(q.z()), float(q.w()) };
}

std::array<float, 9> restMomentInverse(const ElementTemplate& shape, float size)
{
  Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
  for (const auto& r : shape.rest)
  {
    const Eigen::Vector3d q(double(size) * r[0], double(size) * r[1], double(size) * r[2]);
    moment += q * q.transpose();
  }
  // Pseudo-inverse: directions the template does not span (the normal of a
  // flat one) get no stretch rather than an infinite one.
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(moment);
  const double largest = eigen.eigenvalues().cwiseAbs().maxCoeff();
  Eigen::Vector3d inverse = Eigen::Vector3d::Zero();
  for (int k = 0; k < 3; ++k)
  {
    const double lambda = eigen.eigenvalues()[k];
    if (largest > 0.0 && lambda > 1e-6 * largest)
    {
      inverse[k] = 1.0 / lambda;
    }
  }
  return toRowMajor(eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose());
}

std::string Engine::validate(const ElementTemplate& shape, const Parameters& p)
{
  std::ostringstream err;
  const std::string shapeError = shape.validate();
  if (!shapeError.empty())
  {
    return shapeError;
  }
  if (p.numberOfElements < 1)
  {
    return "NumberOfElements must be at least 1";
  }
  const std::size_t n = shape.particleCount();
  if (p.numberOfElements > MaxParticles / n)
  {
    err << "NumberOfElements " << p.numberOfElements << " x " << n
        << " particles per element exceeds the limit of " << MaxParticles
        << " particles; use fewer elements or a simpler shape";
    return err.str();
  }
  if (!(std::isfinite(p.elementSize) && p.elementSize > 0.0f))
  {
    return "ElementSize must be positive";
  }
  if (p.trailLength < 0 || p.trailLength > MaxTrailLength ||
    (p.trailLength > 0 &&
      !(std::isfinite(p.trailInterval) && p.trailInterval > 0.0 && std::isfinite(p.trailStart))))
  {
    return "TrailLength must be in [0, " + std::to_string(MaxTrailLength) +
      "] poses, with a positive, finite interval between two";
  }
  if (std::isnan(p.releaseStart) || std::isnan(p.releaseStop))
  {
    return "ReleaseStart and ReleaseStop must be numbers (one is NaN)";
  }
  if (!(p.releaseStart <= p.releaseStop))
  {
    std::ostringstream err;
    err << "the release window must not end before it starts: ReleaseStart " << p.releaseStart
        << " is after ReleaseStop " << p.releaseStop;
    return err.str();
  }
  if (p.planeAxis < -1 || p.planeAxis > 2)
  {
    return "the plane axis must be -1 (none) or an axis 0 to 2";
  }
  if (p.seedPoints.size() % 3 != 0 || p.seedPoints.size() / 3 > MaxSeedPoints)
  {
    return "there must be at most " + std::to_string(MaxSeedPoints) + " seed points, 3 floats each";
  }
  if (!std::all_of(
        p.seedPoints.begin(), p.seedPoints.end(), [](float x) { return std::isfinite(x); }))
  {
    return "the Seed Source has a point that is not finite (NaN or Inf), or one too far from the "
           "field's first point for float coordinates";
  }
  for (int k = 0; k < 3; ++k)
  {
    if (!(std::isfinite(p.emitterMin[k]) && std::isfinite(p.emitterMax[k]) &&
          p.emitterMin[k] <= p.emitterMax[k]))
    {
      return "the emitter box is invalid: EmitterSize must not be negative and both "
             "EmitterCenter and EmitterSize must be finite";
    }
  }
  if (!(std::isfinite(p.lifetimeMin) && std::isfinite(p.lifetimeMax) && p.lifetimeMin > 0.0f &&
        p.lifetimeMin <= p.lifetimeMax))
  {
    return "LifetimeRange must satisfy 0 < min <= max";
  }
  if (p.iterations < 0 || p.iterations > 1000)
  {
    return "RestorationIterations must lie in [0, 1000]";
  }
  if (!(p.relaxation > 0.0f && p.relaxation <= 2.0f))
  {
    return "the Jacobi relaxation factor must lie in (0, 2]";
  }
  if (!(p.shapeStiffness >= 0.0f && p.shapeStiffness <= 1.0f))
  {
    return "the shape-matching stiffness must lie in [0, 1]";
  }
  if (!(p.linearBlend >= 0.0f && p.linearBlend <= 1.0f))
  {
    return "the linear shape-matching blend (beta) must lie in [0, 1]";
  }
  if (int(p.linking) < int(Linking::None) || int(p.linking) > int(Linking::Torus))
  {
    return "Linking must be None, Chain, Ring, Sheet, Tube or Torus";
  }
  if (p.latticeWidth < 0)
  {
    return "LatticeWidth must not be negative (0 chooses a near-square lattice)";
  }
  if (!(p.linkStiffness >= 0.0f && p.linkStiffness <= 1.0f))
  {
    return "LinkStiffness must lie in [0, 1]";
  }

  return std::string();
}

std::string Engine::configure(const ElementTemplate& shape, const Parameters& p)
{
  const std::string error = Engine::validate(shape, p);
  if (!error.empty())
  {
    return error;
  }
  const std::size_t n = shape.particleCount();
  this->Shape = shape;
  this->Params = p;
  this->Pinned.assign(n, 0);
  if (!shape.pinned.empty())
  {
    this->Pinned = shape.pinned;
  }
  this->Springs.clear();
  std::vector<int> degree(n, 0);
  for (const Spring& s : shape.springs)
  {
    SpringWork w;
    w.a = s.a;
    w.b = s.b;
    w.rest = s.restLength * p.elementSize;
    w.stiffness = s.stiffness;
    const bool pa = this->Pinned[s.a] != 0, pb = this->Pinned[s.b] != 0;
    // A pinned end does not move, so the free end takes the whole correction (thesis §5.1).
    w.shareA = pa ? 0.0f : (pb ? 1.0f : 0.5f);
    w.shareB = pb ? 0.0f : (pa ? 1.0f : 0.5f);
    this->Springs.push_back(w);
    ++degree[s.a];
    ++degree[s.b];
  }
  // Gauss-Seidel applies the springs colour by colour (the GPU engine runs a
  // colour per pass), in spring order within a colour.
  const std::vector<int> colour = colourSprings(n, shape.springs);
  this->GaussSeidelSprings.clear();
  for (int c = 0; c <= (colour.empty() ? -1 : *std::max_element(colour.begin(), colour.end())); ++c)
  {
    for (std::size_t k = 0; k < colour.size(); ++k)
    {
      if (colour[k] == c)
      {
        this->GaussSeidelSprings.push_back(this->Springs[k]);
      }
    }
  }
  // Per particle, the springs it ends, in spring order: end a takes +shareA
  // of a correction, end b -shareB.
  this->IncidenceStart.assign(n + 1, 0);
  for (const SpringWork& w : this->Springs)
  {
    ++this->IncidenceStart[w.a + 1];
    ++this->IncidenceStart[w.b + 1];
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    this->IncidenceStart[i + 1] += this->IncidenceStart[i];
  }
  this->Incidences.resize(2 * this->Springs.size());
  {
    std::vector<std::uint32_t> next(this->IncidenceStart.begin(), this->IncidenceStart.end() - 1);
    for (std::size_t k = 0; k < this->Springs.size(); ++k)
    {
      const SpringWork& w = this->Springs[k];
      this->Incidences[next[w.a]++] = { std::uint32_t(k), w.shareA };
      this->Incidences[next[w.b]++] = { std::uint32_t(k), -w.shareB };
    }
  }
  this->InverseDegree.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    this->InverseDegree[i] = degree[i] > 0 ? 1.0f / float(degree[i]) : 0.0f;
  }

  const std::size_t E = p.numberOfElements;
  this->VisitOrder.clear();
  this->Ids.resize(E);
  for (std::size_t e = 0; e < E; ++e)
  {
    this->Ids[e] = std::uint32_t(e);
  }
  this->HasDomain = false;
  assignLarge(this->Positions, 3 * E * n, 0.0f);
  assignLarge(this->Normals, 3 * E * n, 0.0f);
  assignLarge(this->Forces, E * n, 0.0f);
  assignLarge(this->Lifetimes, E, 0.0f);
  assignLarge(this->Generations, E, std::uint32_t(0));
  assignLarge(this->InitialCenters, 3 * E, 0.0f);
  assignLarge(this->ResetFlags, E, std::uint8_t(0));
  assignLarge(this->Orientations, 4 * E, 0.0f);
  assignLarge(this->Poses, 4 * E, 0.0f);
  assignLarge(this->Spins, 4 * E, 0.0f);
  const std::size_t slots = std::size_t(std::max(p.trailLength, 0));
  assignLarge(this->TrailPositions, slots * 3 * E * n, 0.0f);
  assignLarge(this->TrailGenerations, slots * E, NoTrailPose);
  this->TrailTimes.assign(slots, -std::numeric_limits<double>::infinity());
  this->TrailNewest = -1;
  this->FrameQuaternion = quaternionFromRotation(p.frame);
  this->RestMomentInverse = restMomentInverse(shape, p.elementSize);
  this->Links = makeLinkTable(p.linking, E, p.latticeWidth, p.emitterMin, p.emitterMax);
  const std::size_t linkedValues = this->Links.empty() ? 0 : 3 * E * n;
  this->LinkBefore.assign(linkedValues, 0.0f);
  this->LinkAdvected.assign(linkedValues, 0.0f);
  this->LinkSnapshot.assign(linkedValues, 0.0f);
  return std::string();
}

void Engine::place(std::size_t e, bool releasing, const ReleaseFlow& flow)
{
  const Parameters& P = this->Params;
  // A super set is released as one: every element draws as element 0 does,
  // and sits at its lattice site.
  const bool linked = !this->Links.empty();
  const std::uint32_t element = linked ? 0u : this->Ids[e];
  const std::uint32_t generation = this->Generations[e];
  // Draws 3-6 (the centre's are releaseCenter()'s).
  float u[7];
  for (std::uint32_t d = 3; d < 7; ++d)
  {
    u[d] = uniformDraw(P.seed, element, generation, d);
  }
  float c[3];
  if (linked)
  {
    std::copy_n(this->Links.sites.data() + 3 * e, 3, c);
  }
  else
  {
    this->releaseCenter(element, generation, c);
  }
  std::copy_n(c, 3, this->InitialCenters.data() + 3 * e);
  const std::array<float, 4> q = P.orientation != Orientation::Random ? this->FrameQuaternion
    : P.planeAxis >= 0 ? inPlaneQuaternion(P.planeAxis, u[3], this->FrameQuaternion)
                       : quaternionFromUniforms(u[3], u[4], u[5]);
  this->orient(e, q);
  std::fill_n(this->Spins.begin() + 4 * e, 4, 0.0f);
  const std::size_t n = this->Shape.particleCount();
  std::fill_n(this->Forces.data() + e * n, n, 0.0f);
  this->Lifetimes[e] = P.lifetimeMin + u[6] * (P.lifetimeMax - P.lifetimeMin);
  this->ResetFlags[e] = releasing ? 0 : ReleaseHidden;
  // A super set keeps its lattice's one orientation, as it keeps one draw.
  if (P.orientation == Orientation::AlongFlow && !linked)
  {
    if (flow.field)
    {
      this->alignToFlow(e, flow);
    }
    else
    {
      this->ResetFlags[e] |= AlignPending;
    }
  }
}

void Engine::orient(std::size_t e, const std::array<float, 4>& q)
{
  const Parameters& P = this->Params;
  std::copy(q.begin(), q.end(), this->Orientations.begin() + 4 * e);
  // One particle has no orientation to show: its pose stays the identity.
  const bool oriented = this->Shape.particleCount() > 1;
  const std::array<float, 4> pose = oriented ? q : std::array<float, 4>{ 0, 0, 0, 1 };
  std::copy(pose.begin(), pose.end(), this->Poses.begin() + 4 * e);
  // Fixed places by the frame itself, not its quaternion's matrix (the same
  // rotation to rounding).
  std::array<float, 9> R = P.frame;
  if (P.orientation != Orientation::Fixed)
  {
    quaternionToMatrix(q.data(), R.data());
  }
  const float* c = this->InitialCenters.data() + 3 * e;
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  for (std::size_t i = 0; i < n; ++i)
  {
    const auto& r = this->Shape.rest[i];
    for (int k = 0; k < 3; ++k)
    {
      p[3 * i + k] =
        c[k] + P.elementSize * (R[3 * k] * r[0] + R[3 * k + 1] * r[1] + R[3 * k + 2] * r[2]);
    }
  }
}

void Engine::alignToFlow(std::size_t e, const ReleaseFlow& flow)
{
  float v[3];
  flow.field->sampleWeighted(this->InitialCenters.data() + 3 * e, flow.weight, v);
  this->orient(
    e, alongFlowQuaternion(v, this->Params.planeAxis, this->Params.frame, this->FrameQuaternion));
  this->ResetFlags[e] &= std::uint8_t(~AlignPending);
}

void Engine::releaseCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const
{
  const Parameters& P = this->Params;
  // Where a release may land: in the field's bounds and, with a mask, in a fit cell.
  auto fits = [this](const float* x)
  {
    return this->ReleaseGrid->contains(x) &&
      !(this->ReleaseUnfit && (*this->ReleaseUnfit)[this->ReleaseGrid->cellIndexAt(x)]);
  };
  if (!P.seedPoints.empty())
  {
    // Seed point r, or the next ones in turn where it does not fit.
    const std::uint64_t count = P.seedPoints.size() / 3;
    const std::uint64_t first = (std::uint64_t(generation) * P.numberOfElements + element) % count;
    auto seed = [&](int k) { std::copy_n(P.seedPoints.data() + 3 * ((first + k) % count), 3, c); };
    seed(0);
    for (int k = 1; this->ReleaseGrid && k < ReleaseTries && !fits(c); ++k)
    {
      seed(k);
    }
    return;
  }
  auto candidate = [&](int k)
  {
    for (int a = 0; a < 3; ++a)
    {
      const float u = uniformDraw(P.seed, element, generation, candidateDraw(k) + std::uint32_t(a));
      c[a] = P.emitterMin[a] + u * (P.emitterMax[a] - P.emitterMin[a]);
    }
  };
  candidate(0);
  if (!this->ReleaseUnfit)
  {
    return;
  }
  for (int k = 1; k < ReleaseTries && !fits(c); ++k)
  {
    candidate(k);
  }
}

void Engine::setReleaseMask(
  const GridGeometry& grid, std::shared_ptr<const std::vector<std::uint8_t>> unfit)
{
  const bool fits = unfit && unfit->size() == grid.pointCount();
  this->ReleaseUnfit = fits ? std::move(unfit) : nullptr;
  // The grid alone bounds seed points (FieldSlice-less: it locates, never samples).
  this->ReleaseGrid =
    grid.pointCount() > 0 ? std::make_shared<const VectorField>(grid, FieldSlice()) : nullptr;
}

int Engine::trailSlot(int k) const
{
  const int slots = int(this->TrailTimes.size());
  return ((this->TrailNewest - k) % slots + slots) % slots;
}

void Engine::recordTrail(double t)
{
  const int slots = int(this->TrailTimes.size());
  if (slots == 0)
  {
    return;
  }
  if (this->TrailNewest < 0 || this->TrailTimes[std::size_t(this->TrailNewest)] != t)
  {
    this->TrailNewest = (this->TrailNewest + 1) % slots;
  }
  const std::size_t slot = std::size_t(this->TrailNewest), E = this->elementCount();
  this->TrailTimes[slot] = t;
  std::copy(this->Positions.begin(), this->Positions.end(),
    this->TrailPositions.begin() + std::ptrdiff_t(slot * this->Positions.size()));
  std::copy(this->Generations.begin(), this->Generations.end(),
    this->TrailGenerations.begin() + std::ptrdiff_t(slot * E));
}

void Engine::initialize(const RangeRunner& run, double startTime, const VectorField* field)
{
  std::fill(this->Generations.begin(), this->Generations.end(), 0u);
  std::fill(this->TrailGenerations.begin(), this->TrailGenerations.end(), NoTrailPose);
  std::fill(
    this->TrailTimes.begin(), this->TrailTimes.end(), -std::numeric_limits<double>::infinity());
  this->TrailNewest = -1;
  const bool releasing = this->releasesAt(startTime, 0.0);
  const ReleaseFlow flow{ field, field ? field->timeWeight(startTime) : 0.0f };
  run(this->elementCount(),
    [this, releasing, &flow](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        this->place(e, releasing, flow);
        this->normalsOf(e);
      }
    });
}

void Engine::advectParticle(
  const VectorField& field, const StepWeights& w, double h, float p[3]) const
{
  const float hf = float(h);
  float k1[3];
  field.sampleWeighted(p, w.start, k1);
  switch (this->Params.integrator)
  {
    case Integrator::Euler:
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf * k1[k];
      }
      return;
    case Integrator::RK2:
    {
      float q[3], k2[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k1[k];
      }
      field.sampleWeighted(q, w.middle, k2);
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf * k2[k];
      }
      return;
    }
    case Integrator::RK4:
    {
      float q[3], k2[3], k3[3], k4[3];
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k1[k];
      }
      field.sampleWeighted(q, w.middle, k2);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + 0.5f * hf * k2[k];
      }
      field.sampleWeighted(q, w.middle, k3);
      for (int k = 0; k < 3; ++k)
      {
        q[k] = p[k] + hf * k3[k];
      }
      field.sampleWeighted(q, w.end, k4);
      for (int k = 0; k < 3; ++k)
      {
        p[k] += hf / 6.0f * (k1[k] + 2.0f * k2[k] + 2.0f * k3[k] + k4[k]);
      }
      return;
    }
  }
}

inline bool Engine::springCorrection(const float* p, const SpringWork& s, float c[3])
{
  // Thesis eqs. 2.3-2.5: the whole correction moves end a away from end b by
  // stiffness * (rest - length) along their difference; the ends share it.
  const float* pa = p + 3 * s.a;
  const float* pb = p + 3 * s.b;
  const float d[3] = { pa[0] - pb[0], pa[1] - pb[1], pa[2] - pb[2] };
  const float len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  if (!(len > 0.0f))
  {
    return false; // coincident ends give no direction to restore along
  }
  const float f = s.stiffness * (s.rest - len) / len;
  c[0] = f * d[0];
  c[1] = f * d[1];
  c[2] = f * d[2];
  return true;
}

void Engine::matchShape(float* p, float* orientation) const
{
  // Goals: the rest shape turned by the best-fit rotation about the current
  // centre (Müller et al. 2005, equal masses); particles move towards them.
  const std::size_t n = this->Shape.particleCount();
  const float size = this->Params.elementSize;
  float c[3], A[9];
  momentOf(p, n, this->Shape.rest, size, c, A);
  extractRotation(A, orientation);
  float R[9];
  quaternionToMatrix(orientation, R);
  if (this->Params.linearShapeMatching)
  {
    // Goals from M = beta * A Aqq^-1 + (1 - beta) * R (Müller et al. 2005, §4.3).
    const float beta = this->Params.linearBlend;
    const float* Q = this->RestMomentInverse.data();
    for (int row = 0; row < 3; ++row)
    {
      for (int col = 0; col < 3; ++col)
      {
        const float linear =
          A[3 * row] * Q[col] + A[3 * row + 1] * Q[3 + col] + A[3 * row + 2] * Q[6 + col];
        R[3 * row + col] = beta * linear + (1.0f - beta) * R[3 * row + col];
      }
    }
  }
  const float k = this->Params.shapeStiffness;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->Pinned[i])
    {
      continue;
    }
    const auto& r = this->Shape.rest[i];
    const float q[3] = { size * r[0], size * r[1], size * r[2] };
    for (int row = 0; row < 3; ++row)
    {
      const float goal =
        c[row] + (R[3 * row] * q[0] + R[3 * row + 1] * q[1] + R[3 * row + 2] * q[2]);
      p[3 * i + row] += k * (goal - p[3 * i + row]);
    }
  }
}

void Engine::restore(float* p, float* scratch, float* orientation) const
{
  for (int it = 0; it < this->Params.iterations; ++it)
  {
    this->restoreOnce(p, scratch, orientation);
  }
}

std::size_t Engine::restorationScratchFloats() const
{
  // Jacobi's per-spring corrections.
  return 3 * this->Springs.size();
}

bool Engine::restoresElements() const
{
  return !this->Springs.empty() || this->Params.restoration == Restoration::ShapeMatching;
}

void Engine::restoreOnce(float* p, float* scratch, float* orientation) const
{
  const std::size_t n = this->Shape.particleCount();
  const Restoration method = this->Params.restoration;
  if (method == Restoration::ShapeMatching)
  {
    this->matchShape(p, orientation);
    return;
  }
  if (method == Restoration::GaussSeidel)
  {
    // Each spring moves its ends at once, so later springs see the update.
    for (const SpringWork& s : this->GaussSeidelSprings)
    {
      float c[3];
      if (springCorrection(p, s, c))
      {
        for (int k = 0; k < 3; ++k)
        {
          p[3 * s.a + k] += s.shareA * c[k];
          p[3 * s.b + k] -= s.shareB * c[k];
        }
      }
    }
    return;
  }
  // Jacobi: every spring sees the positions of the previous iteration. Each
  // particle's corrections are summed in spring order, as a per-particle
  // gather over a spring list sorted by index sums them. The corrections are
  // computed first, all independent, so their square roots and divisions
  // overlap; coincident ends give no direction to restore along, and none.
  const std::size_t springs = this->Springs.size();
  float* corrections = scratch;
  for (std::size_t k = 0; k < springs; ++k)
  {
    float* c = corrections + 3 * k;
    if (!springCorrection(p, this->Springs[k], c))
    {
      std::fill_n(c, 3, 0.0f);
    }
  }
  // Each particle gathers its springs' corrections in spring order, with the
  // signed share of its end, in registers.
  const bool averaged = method == Restoration::AveragedJacobi;
  const float w = this->Params.relaxation;
  for (std::size_t i = 0; i < n; ++i)
  {
    float sum[3] = { 0, 0, 0 };
    for (std::uint32_t j = this->IncidenceStart[i]; j < this->IncidenceStart[i + 1]; ++j)
    {
      const Incidence& in = this->Incidences[j];
      const float* c = corrections + 3 * in.spring;
      for (int k = 0; k < 3; ++k)
      {
        sum[k] += in.share * c[k];
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      p[3 * i + k] += averaged ? sum[k] * this->InverseDegree[i] : w * sum[k];
    }
  }
}

Engine::StepWeights Engine::beginStep(const VectorField& field, double t, double h)
{
  // After resetDue() (a distributed step) nothing is left to place; a hidden
  // element, due at every step, would otherwise be placed twice.
  const bool resets = !this->ResetsDone;
  this->ResetsDone = false;
  return { field.timeWeight(t), field.timeWeight(t + 0.5 * h), field.timeWeight(t + h),
    this->releasesAt(t, h), resets };
}

void Engine::resetAndAdvect(std::size_t e, const VectorField& field, const StepWeights& weights,
  double h, float* before, float* advected)
{
  const std::size_t n = this->Shape.particleCount();
  if (weights.resets && (this->isDue(e)))
  {
    ++this->Generations[e];
    this->place(e, weights.releasing, { &field, weights.start });
  }
  else if (this->ResetFlags[e] & AlignPending)
  {
    this->alignToFlow(e, { &field, weights.start });
  }
  float* p = this->Positions.data() + 3 * e * n;
  std::copy_n(p, 3 * n, before);
  for (std::size_t i = 0; i < n; ++i)
  {
    if (!this->Pinned[i])
    {
      this->advectParticle(field, weights, h, p + 3 * i);
    }
  }
  if (advected)
  {
    std::copy_n(p, 3 * n, advected);
  }
}

void Engine::stepElement(std::size_t e, const VectorField& field, const StepWeights& weights,
  double h, std::vector<float>& scratch)
{
  const std::size_t n = this->Shape.particleCount();
  float* before = scratch.data(); // positions before the step
  // Positions before restoration, for the forces; without restoration every
  // force stays 0 and nothing is kept.
  const bool restores = this->restoresElements();
  float* advected = restores ? scratch.data() + 3 * n : nullptr;
  this->resetAndAdvect(e, field, weights, h, before, advected);
  if (restores)
  {
    this->restore(this->Positions.data() + 3 * e * n, scratch.data() + 6 * n,
      this->Orientations.data() + 4 * e);
  }
  this->settle(e, field, weights, h, before, advected);
}

void Engine::settle(std::size_t e, const VectorField& field, const StepWeights& weights, double h,
  const float* before, const float* advected)
{
  const std::size_t n = this->Shape.particleCount();
  float* p = this->Positions.data() + 3 * e * n;
  bool finite = true;
  float* force = this->Forces.data() + e * n;
  // Summed in float, particle by particle, as the GPU engine sums it.
  float c[3] = { 0, 0, 0 };
  bool anyOutside = false;
  const bool byParticle = this->Params.resetWhen == ResetWhen::AnyParticleLeaves;
  for (std::size_t i = 0; i < n; ++i)
  {
    const float* q = p + 3 * i;
    if (advected)
    {
      const float* a = advected + 3 * i;
      const float d[3] = { q[0] - a[0], q[1] - a[1], q[2] - a[2] };
      force[i] = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    }
    finite = finite && finite3(q);
    for (int k = 0; k < 3; ++k)
    {
      c[k] += q[k];
    }
    anyOutside = anyOutside || (byParticle && !this->inDomain(field, q, weights.end));
  }
  bool leave;
  if (!finite)
  {
    // Keep the last good positions on view until the reset at the next step.
    std::copy_n(before, 3 * n, p);
    std::fill_n(force, n, 0.0f);
    leave = true;
  }
  else
  {
    const float count = float(n);
    const float center[3] = { c[0] / count, c[1] / count, c[2] / count };
    leave = byParticle ? anyOutside : !this->inDomain(field, center, weights.end);
    leave = leave || this->releasedStagnant(e, center, h);
  }
  if (this->Params.trackPoses)
  {
    this->updatePose(e, field, weights, h, finite);
  }
  // A super set's element stays (and keeps its last good positions when they
  // turn non-finite): resetting it alone would tear the structure.
  // A hidden element stays hidden, and due (even in a super set, which is
  // released whole when the window opens).
  const std::uint8_t hidden = this->ResetFlags[e] & ReleaseHidden;
  this->ResetFlags[e] = std::uint8_t((leave && this->Links.empty() ? ResetDue : 0) | hidden);
  this->Lifetimes[e] -= float(h);
}

void Engine::updatePose(
  std::size_t e, const VectorField& field, const StepWeights& weights, double h, bool finite)
{
  const std::size_t n = this->Shape.particleCount();
  float* spin = this->Spins.data() + 4 * e;
  if (!finite || n < 2)
  {
    // Back at the positions before the step (or no orientation): no turn.
    std::fill_n(spin, 4, 0.0f);
    return;
  }
  float* pose = this->Poses.data() + 4 * e;
  const float before[4] = { pose[0], pose[1], pose[2], pose[3] };
  float center[3];
  fitPose(this->Positions.data() + 3 * e * n, n, this->Shape.rest, this->Params.elementSize, pose,
    center);
  spinBetween(before, pose, float(h), spin);
  float velocity[3], curl[3];
  field.sampleWithCurl(center, weights.end, velocity, curl);
  spin[3] = spinVorticityRatio(spin, curl, float(h));
}

bool Engine::releasedStagnant(std::size_t e, const float c[3], double h) const
{
  const Parameters& P = this->Params;
  if (!(P.releaseMinSpeed > 0.0f) || !this->Links.empty())
  {
    return false;
  }
  // Slower than the minimum since its release (the cheap test first) ...
  const float* start = this->InitialCenters.data() + 3 * e;
  const float d[3] = { c[0] - start[0], c[1] - start[1], c[2] - start[2] };
  const float reach = P.releaseMinSpeed * float(h);
  if (!(d[0] * d[0] + d[1] * d[1] + d[2] * d[2] < reach * reach))
  {
    return false;
  }
  // ... and in its first step: its lifetime is still the one drawn at its
  // placement (compared with half a step's slack, so that both engines'
  // roundings agree).
  const float drawn = P.lifetimeMin +
    uniformDraw(P.seed, this->Ids[e], this->Generations[e], 6) * (P.lifetimeMax - P.lifetimeMin);
  return drawn - this->Lifetimes[e] < 0.5f * float(h);
}

void Engine::restoreLinks(std::size_t e)
{
  const std::size_t n = this->Shape.particleCount();
  const float* snapshot = this->LinkSnapshot.data();
  float* p = this->Positions.data() + 3 * e * n;
  const std::int32_t* neighbour = &this->Links.neighbours[LinkDirections * e];
  const float* rest = &this->Links.rest[LinkDirections * e];
  const float stiffness = this->Params.linkStiffness;
  for (std::size_t i = 0; i < n; ++i)
  {
    if (this->Pinned[i])
    {
      continue; // and so is particle i of every neighbour
    }
    const float* q = snapshot + 3 * (e * n + i);
    float acc[3] = { 0, 0, 0 };
    int count = 0;
    for (int d = 0; d < LinkDirections; ++d)
    {
      if (neighbour[d] < 0)
      {
        continue;
      }
      ++count;
      const float* o = snapshot + 3 * (std::size_t(neighbour[d]) * n + i);
      const float v[3] = { q[0] - o[0], q[1] - o[1], q[2] - o[2] };
      const float len = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      if (len > 0.0f)
      {
        // Each end takes half, as a spring within an element does.
        const float f = stiffness * (rest[d] - len) / len;
        for (int k = 0; k < 3; ++k)
        {
          acc[k] += 0.5f * (f * v[k]);
        }
      }
    }
    if (count > 0)
    {
      const float average = 1.0f / float(count);
      for (int k = 0; k < 3; ++k)
      {
        p[3 * i + k] = q[k] + acc[k] * average;
      }
    }
  }
}

void Engine::stepLinked(const VectorField& field, double t, double h, const RangeRunner& run)
{
  const std::size_t n = this->Shape.particleCount(), E = this->elementCount();
  const StepWeights weights = this->beginStep(field, t, h);
  run(E,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        this->resetAndAdvect(e, field, weights, h, this->LinkBefore.data() + 3 * e * n,
          this->LinkAdvected.data() + 3 * e * n);
      }
    });
  for (int it = 0; it < this->Params.iterations; ++it)
  {
    if (this->restoresElements())
    {
      run(E,
        [&](std::size_t begin, std::size_t end)
        {
          std::vector<float> scratch(this->restorationScratchFloats());
          for (std::size_t e = begin; e < end; ++e)
          {
            this->restoreOnce(this->Positions.data() + 3 * e * n, scratch.data(),
              this->Orientations.data() + 4 * e);
          }
        });
    }
    // Links read the positions all elements had after this iteration.
    run(E,
      [&](std::size_t begin, std::size_t end)
      {
        std::copy(this->Positions.begin() + 3 * begin * n, this->Positions.begin() + 3 * end * n,
          this->LinkSnapshot.begin() + 3 * begin * n);
      });
    run(E,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t e = begin; e < end; ++e)
        {
          this->restoreLinks(e);
        }
      });
  }
  run(E,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        this->settle(e, field, weights, h, this->LinkBefore.data() + 3 * e * n,
          this->LinkAdvected.data() + 3 * e * n);
      }
    });
}

void Engine::step(const VectorField& field, double t, double h, const RangeRunner& run)
{
  if (!this->ResetsDone && recordsTrailAt(this->Params, t))
  {
    this->recordTrail(t); // resetDue() recorded it in a distributed step
  }
  if (!this->Links.empty())
  {
    this->stepLinked(field, t, h, run);
    return;
  }
  const std::size_t n = this->Shape.particleCount();
  const StepWeights weights = this->beginStep(field, t, h);
  const std::vector<std::uint32_t>& order = this->visitOrder(field);
  run(this->elementCount(),
    [&](std::size_t begin, std::size_t end)
    {
      // before + advected + restoration's scratch, per worker.
      std::vector<float> scratch(6 * n + this->restorationScratchFloats());
      for (std::size_t k = begin; k < end; ++k)
      {
        if (!order.empty())
        {
          // In visiting order the elements' own state is scattered in memory:
          // fetch it ahead, while earlier elements sample the field.
          // Its positions, once there, say which grid cells it will sample:
          // fetch those a few elements later.
          constexpr std::size_t StateAhead = 16, FieldAhead = 6;
          if (k + StateAhead < end)
          {
            this->prefetchElement(order[k + StateAhead]);
          }
          if (k + FieldAhead < end)
          {
            const std::size_t next = order[k + FieldAhead];
            const float* q = this->Positions.data() + 3 * next * n;
            for (std::size_t i = 0; i < n; ++i)
            {
              field.prefetch(q + 3 * i);
            }
          }
          this->stepElement(order[k], field, weights, h, scratch);
        }
        else
        {
          this->stepElement(k, field, weights, h, scratch);
        }
      }
    });
}

void Engine::prefetchElement(std::size_t e) const
{
#if defined(__GNUC__)
  const std::size_t n = this->Shape.particleCount();
  constexpr std::size_t Line = 64;
  __builtin_prefetch(this->ResetFlags.data() + e);
  __builtin_prefetch(this->Lifetimes.data() + e, 1);
  const char* positions = reinterpret_cast<const char*>(this->Positions.data() + 3 * e * n);
  for (std::size_t b = 0; b < 12 * n; b += Line)
  {
    __builtin_prefetch(positions + b, 1);
  }
  if (this->restoresElements())
  {
    const char* forces = reinterpret_cast<const char*>(this->Forces.data() + e * n);
    for (std::size_t b = 0; b < 4 * n; b += Line)
    {
      __builtin_prefetch(forces + b, 1);
    }
  }
#else
  (void)e;
#endif
}

const std::vector<std::uint32_t>& Engine::visitOrder(const VectorField& field)
{
  // Below a few thousand elements the field's sampled cells stay in cache anyway.
  constexpr std::size_t SmallestOrdered = 2048;
  // A sort costs a few per cent of a step, and elements move less than a cell
  // per step, so an order stays good for several steps.
  constexpr int StepsPerOrder = 8;
  const std::size_t E = this->elementCount(), n = this->Shape.particleCount();
  if (E < SmallestOrdered)
  {
    this->VisitOrder.clear();
    return this->VisitOrder;
  }
  if (this->VisitOrder.size() == E && this->StepsSinceOrdered < StepsPerOrder)
  {
    ++this->StepsSinceOrdered;
    return this->VisitOrder;
  }
  this->StepsSinceOrdered = 1;
  // The bins: the grid's cells coarsened evenly to about one per element.
  const GridGeometry& grid = field.grid();
  const Domain& domain = field.domain();
  double cells = 1.0;
  for (int a = 0; a < 3; ++a)
  {
    cells *= std::max(grid.dims[a] - 1, 1);
  }
  const double coarsening = std::min(1.0, std::cbrt(double(E) / cells));
  int bins[3];
  float binsPerUnit[3];
  std::size_t binStride[3], binCount = 1;
  for (int a = 0; a < 3; ++a)
  {
    const int axisCells = std::max(grid.dims[a] - 1, 1);
    bins[a] = domain.degenerate[a] ? 1 : std::max(1, int(axisCells * coarsening));
    const float width = domain.upper[a] - domain.lower[a];
    binsPerUnit[a] = width > 0.0f ? float(bins[a]) / width : 0.0f;
    binStride[a] = binCount;
    binCount *= std::size_t(bins[a]);
  }
  // A counting sort by the bin of each element's first particle.
  std::vector<std::uint32_t> binOf(E), start(binCount + 1, 0);
  for (std::size_t e = 0; e < E; ++e)
  {
    const float* p = this->Positions.data() + 3 * e * n;
    std::size_t bin = 0;
    for (int a = 0; a < 3; ++a)
    {
      const float u = (p[a] - domain.lower[a]) * binsPerUnit[a];
      // Outside the field (or not a number): the nearest bin.
      const int i = u >= 1.0f ? int(std::min(u, float(bins[a] - 1))) : 0;
      bin += std::size_t(i) * binStride[a];
    }
    binOf[e] = std::uint32_t(bin);
    ++start[bin + 1];
  }
  for (std::size_t b = 0; b < binCount; ++b)
  {
    start[b + 1] += start[b];
  }
  this->VisitOrder.resize(E);
  for (std::size_t e = 0; e < E; ++e)
  {
    this->VisitOrder[start[binOf[e]]++] = std::uint32_t(e);
  }
  return this->VisitOrder;
}

void Engine::setDomain(const Domain& domain)
{
  this->HasDomain = true;
  this->DomainBox = domain;
}

void Engine::resetDue(const RangeRunner& run, double t, double h)
{
  const bool releasing = this->releasesAt(t, h);
  // The trail pose is recorded before any reset, as step() alone records it.
  if (recordsTrailAt(this->Params, t))
  {
    this->recordTrail(t);
  }
  this->ResetsDone = true;
  run(this->elementCount(),
    [this, releasing](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        if (this->isDue(e))
        {
          ++this->Generations[e];
          // The new centre may lie in another piece: Along Flow turns the
          // element where it is held next (AlignPending).
          this->place(e, releasing, { nullptr, 0.0f });
        }
      }
    });
}

std::array<float, 3> Engine::centerOf(std::size_t e) const
{
  // Summed in float, particle by particle, as the reposition test sums it.
  const std::size_t n = this->Shape.particleCount();
  const float* p = this->Positions.data() + 3 * e * n;
  float c[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[3 * i + k];
    }
  }
  const float count = float(n);
  return { c[0] / count, c[1] / count, c[2] / count };
}

namespace
{
// A migration record: id, generation, reset flag, lifetime, initial centre,
// orientation, then positions and forces.
constexpr std::size_t RecordHeaderWords = 4 + 3 + 4;

std::uint32_t floatBits(float f)
{
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}
float bitsFloat(std::uint32_t u)
{
  float f;
  std::memcpy(&f, &u, sizeof f);
  return f;
}
} // namespace

std::size_t Engine::recordWords() const
{
  const std::size_t n = this->Shape.particleCount(), slots = this->TrailTimes.size();
  return RecordHeaderWords + 8 + 4 * n + slots * (1 + 3 * n);
}

void Engine::packElement(std::size_t e, std::vector<std::uint32_t>& out) const
{
  const std::size_t n = this->Shape.particleCount();
  out.push_back(this->Ids[e]);
  out.push_back(this->Generations[e]);
  out.push_back(this->ResetFlags[e]);
  out.push_back(floatBits(this->Lifetimes[e]));
  auto floats = [&out](const float* values, std::size_t count)
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      out.push_back(floatBits(values[k]));
    }
  };
  floats(this->InitialCenters.data() + 3 * e, 3);
  floats(this->Orientations.data() + 4 * e, 4);
  floats(this->Poses.data() + 4 * e, 4);
  floats(this->Spins.data() + 4 * e, 4);
  floats(this->Positions.data() + 3 * e * n, 3 * n);
  floats(this->Forces.data() + e * n, n);
  // Its trail, slot by slot.
  const std::size_t E = this->elementCount();
  for (std::size_t slot = 0; slot < this->TrailTimes.size(); ++slot)
  {
    out.push_back(this->TrailGenerations[slot * E + e]);
    floats(this->TrailPositions.data() + 3 * (slot * E + e) * n, 3 * n);
  }
}

std::string Engine::exchange(
  const std::vector<std::uint8_t>& leaving, const std::vector<std::uint32_t>& records)
{
  const std::size_t held = this->elementCount(), words = this->recordWords();
  if (leaving.size() != held)
  {
    return "the leaving flags do not match the elements held";
  }
  if (records.size() % words != 0)
  {
    return "the element records do not match this element template";
  }
  if (!this->Links.empty())
  {
    return "a super set cannot be split among pieces";
  }
  if (records.empty() && std::find(leaving.begin(), leaving.end(), 1) == leaving.end())
  {
    return std::string(); // nothing moves: the elements stay as they are, in order
  }
  // (id, source): source < held is an element kept, otherwise record
  // source - held.
  std::vector<std::pair<std::uint32_t, std::size_t>> order;
  for (std::size_t e = 0; e < held; ++e)
  {
    if (!leaving[e])
    {
      order.emplace_back(this->Ids[e], e);
    }
  }
  const std::size_t incoming = records.size() / words;
  for (std::size_t r = 0; r < incoming; ++r)
  {
    const std::uint32_t id = records[r * words];
    if (id >= this->Params.numberOfElements)
    {
      return "an element record carries id " + std::to_string(id) + " of " +
        std::to_string(this->Params.numberOfElements) + " elements";
    }
    order.emplace_back(id, held + r);
  }
  std::sort(order.begin(), order.end());
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    if (order[k].first == order[k - 1].first)
    {
      return "element " + std::to_string(order[k].first) + " arrived twice";
    }
  }

  const std::size_t n = this->Shape.particleCount(), E = order.size();
  std::vector<std::uint32_t> ids(E), generations(E);
  std::vector<std::uint8_t> flags(E);
  std::vector<float> lifetimes(E), centers(3 * E), orientations(4 * E), poses(4 * E), spins(4 * E),
    positions(3 * E * n), forces(E * n);
  const std::size_t slots = this->TrailTimes.size();
  std::vector<float> trailPositions(slots * 3 * E * n);
  std::vector<std::uint32_t> trailGenerations(slots * E);
  for (std::size_t k = 0; k < E; ++k)
  {
    const std::size_t source = order[k].second;
    if (source < held)
    {
      ids[k] = this->Ids[source];
      generations[k] = this->Generations[source];
      flags[k] = this->ResetFlags[source];
      lifetimes[k] = this->Lifetimes[source];
      std::copy_n(this->InitialCenters.data() + 3 * source, 3, centers.data() + 3 * k);
      std::copy_n(this->Orientations.data() + 4 * source, 4, orientations.data() + 4 * k);
      std::copy_n(this->Poses.data() + 4 * source, 4, poses.data() + 4 * k);
      std::copy_n(this->Spins.data() + 4 * source, 4, spins.data() + 4 * k);
      std::copy_n(this->Positions.data() + 3 * source * n, 3 * n, positions.data() + 3 * k * n);
      std::copy_n(this->Forces.data() + source * n, n, forces.data() + k * n);
      for (std::size_t slot = 0; slot < slots; ++slot)
      {
        trailGenerations[slot * E + k] = this->TrailGenerations[slot * held + source];
        std::copy_n(this->TrailPositions.data() + 3 * (slot * held + source) * n, 3 * n,
          trailPositions.data() + 3 * (slot * E + k) * n);
      }
      continue;
    }
    const std::uint32_t* r = records.data() + (source - held) * words;
    ids[k] = r[0];
    generations[k] = r[1];
    flags[k] = std::uint8_t(r[2] & (ResetDue | ReleaseHidden | AlignPending));
    lifetimes[k] = bitsFloat(r[3]);
    const std::uint32_t* values = r + 4;
    auto floats = [&values](float* out, std::size_t count)
    {
      for (std::size_t j = 0; j < count; ++j)
      {
        out[j] = bitsFloat(*values++);
      }
    };
    floats(centers.data() + 3 * k, 3);
    floats(orientations.data() + 4 * k, 4);
    floats(poses.data() + 4 * k, 4);
    floats(spins.data() + 4 * k, 4);
    floats(positions.data() + 3 * k * n, 3 * n);
    floats(forces.data() + k * n, n);
    for (std::size_t slot = 0; slot < slots; ++slot)
    {
      trailGenerations[slot * E + k] = *values++;
      floats(trailPositions.data() + 3 * (slot * E + k) * n, 3 * n);
    }
  }
  this->Ids = std::move(ids);
  this->VisitOrder.clear();
  this->Generations = std::move(generations);
  this->ResetFlags = std::move(flags);
  this->Lifetimes = std::move(lifetimes);
  this->InitialCenters = std::move(centers);
  this->Orientations = std::move(orientations);
  this->Poses = std::move(poses);
  this->Spins = std::move(spins);
  this->Positions = std::move(positions);
  this->Forces = std::move(forces);
  this->TrailPositions = std::move(trailPositions);
  this->TrailGenerations = std::move(trailGenerations);
  // Recomputed from the positions before they are shown.
  this->Normals.assign(3 * E * n, 0.0f);
  return std::string();
}

void Engine::normalsOf(std::size_t e)
{
  const std::size_t n = this->Shape.particleCount();
  elementNormals(this->Shape, this->Positions.data() + 3 * e * n, this->Normals.data() + 3 * e * n);
}

void Engine::updateNormals(const RangeRunner& run)
{
  const std::size_t n = this->particlesPerElement();
  run(this->elementCount(),
    [this, n](std::size_t begin, std::size_t end)
    {
      elementsNormals(this->Shape, this->Positions.data() + 3 * begin * n,
        this->Normals.data() + 3 * begin * n, end - begin);
    });
}

StepSchedule::StepSchedule(double start, double dt, std::vector<double> breaks)
  : Start(start)
  , Dt(dt)
  , Epsilon(dt * 1e-6)
  , Breaks(std::move(breaks))
{
  std::sort(this->Breaks.begin(), this->Breaks.end());
}

double StepSchedule::next(double t) const
{
  const double limit = t + this->Epsilon;
  // Grid points are computed from their index, never accumulated, so every run
  // meets the same ones.
  double k = std::floor((t - this->Start) / this->Dt);
  double grid = this->Start + k * this->Dt;
  while (grid <= limit)
  {
    k += 1.0;
    grid = this->Start + k * this->Dt;
  }
  // A break before the grid point, or within epsilon after it, wins: steps
  // land exactly on breaks and no sliver step is left on either side.
  const auto it = std::upper_bound(this->Breaks.begin(), this->Breaks.end(), limit);
  if (it != this->Breaks.end() && *it <= grid + this->Epsilon)
  {
    return *it;
  }
  return grid;
}

double advance(const StepSchedule& schedule, double t, double target,
  const std::function<void(double t, double h)>& step,
  const std::function<bool(double time)>& keepGoing)
{
  for (double next = schedule.next(t); next <= target + schedule.epsilon(); next = schedule.next(t))
  {
    if (keepGoing && !keepGoing(t))
    {
      break;
    }
    step(t, next - t);
    t = next;
  }
  return t;
}

double advance(Engine& engine, const VectorField& field, const StepSchedule& schedule, double t,
  double target, const RangeRunner& run, const std::function<bool(double time)>& keepGoing)
{
  return advance(
    schedule, t, target, [&](double from, double h) { engine.step(field, from, h, run); },
    keepGoing);
}

std::string gpuTextureError(const ElementTemplate& shape, std::size_t elements, long long maxSize)
{
  std::ostringstream err;
  const std::size_t n = shape.particleCount();
  const ParticleLayout layout = ParticleLayout::of(elements, n);
  if (layout.width > maxSize || layout.height > maxSize)
  {
    err << elements << " elements of " << n << " particles need a " << layout.width << " x "
        << layout.height << " state texture, beyond this GPU's GL_MAX_TEXTURE_SIZE of " << maxSize;
    return err.str();
  }
  const long long tableWidth = 2 * (long long)n;
  const long long listRows = (4 * (long long)shape.springs.size() + 4095) / 4096;
  const long long triangleRows = (3 * (long long)shape.triangles.size() + 4095) / 4096;
  if (tableWidth > maxSize || listRows > maxSize || triangleRows > maxSize)
  {
    err << "the element template's " << n << " particles, " << shape.springs.size()
        << " springs and " << shape.triangles.size() << " triangles need template tables of up to "
        << std::max({ tableWidth, listRows, triangleRows })
        << " texels along one side, beyond this GPU's GL_MAX_TEXTURE_SIZE of " << maxSize
        << "; the GPU engine takes templates of at most " << maxSize / 2 << " particles";
    return err.str();
  }
  return std::string();
}

ParticleLayout ParticleLayout::of(std::size_t elements, std::size_t particlesPerElement)
{
  ParticleLayout l;
  l.elementGrid[0] = std::max<long long>(1, (long long)std::ceil(std::sqrt(double(elements))));
  l.elementGrid[1] = (long long)((elements + l.elementGrid[0] - 1) / l.elementGrid[0]);
  const double n = double(particlesPerElement);
  l.blocksPerRow = (long long)std::ceil(std::sqrt(n * l.elementGrid[1] / l.elementGrid[0]));
  l.blocksPerRow = std::max<long long>(1, std::min<long long>(l.blocksPerRow, (long long)n));
  l.width = l.blocksPerRow * l.elementGrid[0];
  l.height = (((long long)n + l.blocksPerRow - 1) / l.blocksPerRow) * l.elementGrid[1];
  return l;
}

void sampleAtPositions(const VectorField& field, double t, const float* positions,
  std::size_t count, float* velocity, float* vorticity, const RangeRunner& run)
{
  const float weight = field.timeWeight(t);
  run(count,
    [&](std::size_t begin, std::size_t end)
    {
      // Elements lie in memory in no spatial order, so each new one's cells
      // are likely out of cache: ask for them a few particles ahead.
      constexpr std::size_t Ahead = 24;
      for (std::size_t i = begin; i < end; ++i)
      {
        if (i + Ahead < end)
        {
          field.prefetch(positions + 3 * (i + Ahead));
        }
        if (vorticity)
        {
          vorticity[i] = field.sampleWithVorticity(positions + 3 * i, weight, velocity + 3 * i);
        }
        else
        {
          field.sampleWeighted(positions + 3 * i, weight, velocity + 3 * i);
        }
      }
    });
}

} // namespace bp

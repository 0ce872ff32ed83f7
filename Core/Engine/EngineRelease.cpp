// SPDX-License-Identifier: BSD-3-Clause
// Releasing elements (Engine.h, step 1): where a release lands (the emitter
// box, the seed points, the release mask), how the element is turned (fixed,
// random, in the plane, along the flow) and the draws it takes; placing the
// whole system and, in a distributed step, the elements that are due.
#include "CounterHash.h"
#include "Engine.h"
#include "Quaternion.h"

#include <algorithm>
#include <limits>

namespace bp
{

float lifetimeDraw(const Parameters& p, std::uint32_t drawElement, std::uint32_t generation)
{
  // A lattice's generation is released together: its lifetime is element 0's.
  const std::uint32_t element = p.releasePattern == ReleasePattern::Lattice ? 0u : drawElement;
  return p.lifetimeMin +
    uniformDraw(p.seed, element, generation, LifetimeDraw) * (p.lifetimeMax - p.lifetimeMin);
}

void Engine::place(std::size_t e, bool releasing, const ReleaseFlow& flow)
{
  const Parameters& P = this->Params;
  // A super set is released as one: every element draws as element 0 does,
  // and sits at its lattice site.
  const bool linked = !this->Links.empty();
  const std::uint32_t element = this->drawElement(e);
  const std::uint32_t generation = this->Generations[e];
  // The orientation draws (the centre's are releaseCenter()'s, the lifetime's lifetimeDraw()'s:
  // a lattice's generation is released together, with element 0's lifetime).
  float u[3];
  for (std::uint32_t k = 0; k < 3; ++k)
  {
    u[k] = uniformDraw(P.seed, element, generation, OrientationDraw + k);
  }
  float c[3];
  bool fits = true;
  if (linked)
  {
    std::copy_n(this->Links.sites.data() + 3 * e, 3, c);
  }
  else
  {
    fits = this->releaseCenter(element, generation, c);
  }
  std::copy_n(c, 3, this->InitialCenters.data() + 3 * e);
  const std::array<float, 4> q = P.orientation != Orientation::Random ? this->FrameQuaternion
    : P.planeAxis >= 0 ? inPlaneQuaternion(P.planeAxis, u[0], this->FrameQuaternion)
                       : quaternionFromUniforms(u[0], u[1], u[2]);
  this->orient(e, q);
  std::fill_n(this->Spins.begin() + 4 * e, 4, 0.0f);
  const std::size_t n = this->Shape.particleCount();
  std::fill_n(this->Forces.data() + e * n, n, 0.0f);
  if (!this->Slips.empty())
  {
    std::fill_n(this->Slips.data() + 3 * e * n, 3 * n, 0.0f); // released with the flow's velocity
  }
  this->Lifetimes[e] = lifetimeDraw(P, element, generation);
  // A lattice point that does not fit is never shown (due again each step).
  this->ResetFlags[e] = releasing && fits ? 0 : ReleaseHidden;
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
  this->orient(e,
    alongFlowQuaternion(
      v, this->Params.planeAxis, this->Params.frame, this->LongAxis, this->FrameQuaternion));
  this->ResetFlags[e] &= std::uint8_t(~AlignPending);
}

bool Engine::releaseCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const
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
    return true;
  }
  if (P.releasePattern == ReleasePattern::Lattice)
  {
    const std::array<float, 3> x = P.lattice.point(element);
    std::copy(x.begin(), x.end(), c);
    return !this->ReleaseGrid || fits(c);
  }
  if (this->Weights)
  {
    return this->weightedCenter(element, generation, c);
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
    return true;
  }
  for (int k = 1; k < ReleaseTries && !fits(c); ++k)
  {
    candidate(k);
  }
  return true;
}

bool Engine::weightedCenter(std::uint32_t element, std::uint32_t generation, float c[3]) const
{
  const Parameters& P = this->Params;
  const ReleaseWeights& W = *this->Weights;
  // Candidate k, drawn where weights may be above 0, is taken where it fits
  // with probability w(c) / maximum; else the fitting candidate of the
  // largest weight seen; else (none fits) the last, which the release then
  // keeps hidden, due again at the next step, as a lattice point that does
  // not fit: a weighted release never lands where the mask forbids.
  float lo[3], hi[3];
  weightedBox(P.emitterMin, P.emitterMax, W, lo, hi);
  float best[3];
  float bestWeight = -1.0f;
  for (int k = 0; k < ReleaseTries; ++k)
  {
    for (int a = 0; a < 3; ++a)
    {
      const float u = uniformDraw(P.seed, element, generation, candidateDraw(k) + std::uint32_t(a));
      c[a] = lo[a] + u * (hi[a] - lo[a]);
    }
    const bool fit = this->ReleaseGrid->contains(c) &&
      !(this->ReleaseUnfit && (*this->ReleaseUnfit)[this->ReleaseGrid->cellIndexAt(c)]);
    if (!fit)
    {
      continue;
    }
    const float w = W.at(c);
    if (uniformDraw(P.seed, element, generation, weightDraw(k)) * W.maximum() < w)
    {
      return true;
    }
    if (w > bestWeight)
    {
      bestWeight = w;
      std::copy_n(c, 3, best);
    }
  }
  if (bestWeight >= 0.0f)
  {
    std::copy_n(best, 3, c);
  }
  return bestWeight >= 0.0f;
}

void Engine::setReleaseMask(const GridGeometry& grid,
  std::shared_ptr<const std::vector<std::uint8_t>> unfit,
  std::shared_ptr<const ReleaseWeights> weights)
{
  const bool fits = unfit && unfit->size() == grid.pointCount();
  this->ReleaseUnfit = fits ? std::move(unfit) : nullptr;
  this->Weights = grid.pointCount() > 0 ? std::move(weights) : nullptr;
  // The grid alone bounds seed points (FieldSlice-less: it locates, never samples).
  this->ReleaseGrid =
    grid.pointCount() > 0 ? std::make_shared<const VectorField>(grid, FieldSlice()) : nullptr;
}

void Engine::initialize(const RangeRunner& run, double startTime, const VectorField* field)
{
  std::fill(this->Generations.begin(), this->Generations.end(), 0u);
  std::fill(this->TrailGenerations.begin(), this->TrailGenerations.end(), NoTrailPose);
  std::fill(
    this->TrailTimes.begin(), this->TrailTimes.end(), -std::numeric_limits<double>::infinity());
  this->TrailNewest = -1;
  this->Log.clear(); // a trace's events start with it
  const bool releasing = this->releasesAt(startTime, 0.0);
  const ReleaseFlow flow{ field, field ? field->timeWeight(startTime) : 0.0f };
  run(this->elementCount(),
    [this, releasing, &flow](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        this->place(e, releasing, flow);
      }
    });
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

} // namespace bp

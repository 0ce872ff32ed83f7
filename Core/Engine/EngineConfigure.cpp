// SPDX-License-Identifier: BSD-3-Clause
// Engine::configure: the spring tables each restoration method walks, built
// once from the template, and the per-element state sized for the system;
// with the template-derived constants stableRelaxation and restMomentInverse.
#include "EigenRows.h"
#include "Engine.h"
#include "LargeVector.h"
#include "Quaternion.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <limits>

namespace bp
{

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
  const Eigen::Matrix3d m =
    eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
  return toRowMajor(m);
}

std::string Engine::configure(const ElementTemplate& shape, const Parameters& p)
{
  const std::string error = Engine::validate(shape, p);
  if (!error.empty())
  {
    return error;
  }
  this->Shape = shape;
  this->Params = p;
  this->Log.clear();
  this->buildSprings();
  this->buildGaussSeidelOrder();
  this->buildIncidences();
  this->sizeElements(p.numberOfElements);
  this->FrameQuaternion = quaternionFromRotation(p.frame);
  this->LongAxis = longAxis(shape);
  this->RestMomentInverse = restMomentInverse(shape, p.elementSize);
  this->Links =
    makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax);
  return std::string();
}

void Engine::buildSprings()
{
  const ElementTemplate& shape = this->Shape;
  const std::size_t n = shape.particleCount();
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
    w.rest = s.restLength * this->Params.elementSize;
    w.stiffness = s.stiffness;
    const bool pa = this->Pinned[s.a] != 0, pb = this->Pinned[s.b] != 0;
    // A pinned end does not move, so the free end takes the whole correction (thesis §5.1).
    w.shareA = pa ? 0.0f : (pb ? 1.0f : 0.5f);
    w.shareB = pb ? 0.0f : (pa ? 1.0f : 0.5f);
    this->Springs.push_back(w);
    ++degree[s.a];
    ++degree[s.b];
  }
  this->InverseDegree.resize(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    this->InverseDegree[i] = degree[i] > 0 ? 1.0f / float(degree[i]) : 0.0f;
  }
}

void Engine::buildGaussSeidelOrder()
{
  // Gauss-Seidel applies the springs colour by colour (the GPU engine runs a
  // colour per pass), in spring order within a colour.
  const std::vector<int> colour = colourSprings(this->Shape.particleCount(), this->Shape.springs);
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
}

void Engine::buildIncidences()
{
  // Per particle, the springs it ends, in spring order: end a takes +shareA
  // of a correction, end b -shareB.
  const std::size_t n = this->Shape.particleCount();
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
  std::vector<std::uint32_t> next(this->IncidenceStart.begin(), this->IncidenceStart.end() - 1);
  for (std::size_t k = 0; k < this->Springs.size(); ++k)
  {
    const SpringWork& w = this->Springs[k];
    this->Incidences[next[w.a]++] = { std::uint32_t(k), w.shareA };
    this->Incidences[next[w.b]++] = { std::uint32_t(k), -w.shareB };
  }
}

void Engine::sizeElements(std::size_t E)
{
  forEachElementArray(*this,
    [E](const char* /*name*/, auto& array, std::size_t width, std::size_t blocks, auto fill)
    { assignLarge(array, blocks * E * width, fill); });
  for (std::size_t e = 0; e < E; ++e)
  {
    this->Ids[e] = std::uint32_t(e);
  }
  this->HasDomain = false;
  this->TrailTimes.assign(
    std::size_t(std::max(this->Params.trailLength, 0)), -std::numeric_limits<double>::infinity());
  this->TrailNewest = -1;
  // Sized again where it is used.
  this->Scratch = StepScratch();
}

} // namespace bp

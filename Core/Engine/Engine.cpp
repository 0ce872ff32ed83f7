// SPDX-License-Identifier: BSD-3-Clause
// What is left of the engine after its roles' own files (EngineConfigure,
// EngineValidate, EngineRelease, EngineStep, EngineLinked, EngineVisitOrder,
// EngineMigration): motion trails, normals for output, and the walk along a
// step schedule.
#include "Engine.h"
#include "ElementNormals.h"
#include "LargeVector.h"

#include <algorithm>
#include <limits>

namespace bp
{

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

bool Engine::trailAcrossSeam(std::size_t slot, std::size_t e, const VectorField& field) const
{
  const std::size_t first = e * this->particlesPerElement();
  return this->domainOf(field).acrossPeriodicSeam(
    this->TrailPositions.data() + 3 * (slot * this->particleCount() + first),
    this->Positions.data() + 3 * first);
}

void Engine::updateNormals(const RangeRunner& run)
{
  const std::size_t n = this->particlesPerElement();
  std::vector<float>& normals = this->Scratch.normals;
  if (normals.size() != 3 * this->particleCount())
  {
    assignLarge(normals, 3 * this->particleCount(), 0.0f);
  }
  run(this->elementCount(),
    [this, n, &normals](std::size_t begin, std::size_t end)
    {
      elementsNormals(this->Shape, this->Positions.data() + 3 * begin * n,
        normals.data() + 3 * begin * n, end - begin);
    });
}

double advance(Engine& engine, const VectorField& field, const StepSchedule& schedule, double t,
  double target, const RangeRunner& run, const std::function<bool(double time)>& keepGoing)
{
  return advance(
    schedule, t, target, [&](double from, double h) { engine.step(field, from, h, run); },
    keepGoing);
}

} // namespace bp

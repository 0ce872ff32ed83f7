// SPDX-License-Identifier: BSD-3-Clause
// The step of a super set (Core/Elements/SuperSet.h): the elements' own step in
// phases over the whole system, with an averaged Jacobi pass over the links
// after every restoration iteration, so linked elements wait for each other.
#include "Engine.h"
#include "SpringForce.h"

#include <algorithm>

namespace bp
{

void Engine::restoreLinks(std::size_t e)
{
  const std::size_t n = this->Shape.particleCount();
  const float* snapshot = this->Scratch.linkSnapshot.data();
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
      float force[3];
      if (springForce(q, o, rest[d], stiffness, force))
      {
        // Each end takes half, as a spring within an element does.
        for (int k = 0; k < 3; ++k)
        {
          acc[k] += 0.5f * force[k];
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
  // The whole system's positions before the step, after advection, and after
  // each iteration (for the links); sized here, as a copy of the engine has none.
  for (std::vector<float>* buffer :
    { &this->Scratch.linkBefore, &this->Scratch.linkAdvected, &this->Scratch.linkSnapshot })
  {
    if (buffer->size() != 3 * E * n)
    {
      buffer->assign(3 * E * n, 0.0f);
    }
  }
  run(E,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t e = begin; e < end; ++e)
      {
        this->resetAndAdvect(e, field, weights, h, this->Scratch.linkBefore.data() + 3 * e * n,
          this->Scratch.linkAdvected.data() + 3 * e * n);
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
          this->Scratch.linkSnapshot.begin() + 3 * begin * n);
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
        this->settle(e, field, weights, h, this->Scratch.linkBefore.data() + 3 * e * n,
          this->Scratch.linkAdvected.data() + 3 * e * n);
      }
    });
}

} // namespace bp

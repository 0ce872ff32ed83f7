// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SampleAtPositions.h
 * @brief The field sampled at given positions, in parallel: the CPU path of
 * the output's Velocity, Speed and Vorticity arrays.
 */
#ifndef BoundParticles_SampleAtPositions_h
#define BoundParticles_SampleAtPositions_h

#include "Parallel.h"
#include "VectorField.h"

#include <cstddef>

namespace bp
{

/// Velocity and |curl v| sampled at `count` positions (3 floats each);
/// `vorticity` may be null.
void sampleAtPositions(const VectorField& field, double t, const float* positions,
  std::size_t count, float* velocity, float* vorticity, const RangeRunner& run);

} // namespace bp

#endif

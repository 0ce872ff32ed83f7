// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CounterHash.h
 * @brief Counter-based random numbers shared by the CPU and GPU engines.
 *
 * A reset draws its random numbers from a hash of (seed, element, generation,
 * draw index) instead of a stateful generator, so any element can be placed by
 * any thread (or GPU fragment) in any order with identical results. The hash is
 * pcg4d (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 2020);
 * it uses only 32-bit unsigned multiply, add, xor and shift, which GLSL
 * reproduces bit for bit (Shaders/ carries the same function).
 */
#ifndef BoundParticles_CounterHash_h
#define BoundParticles_CounterHash_h

#include <cstdint>

namespace bp
{

/// pcg4d's linear congruential step, x * HashMultiplier + HashIncrement
/// (bpHash in bp_shared.glsl gets both as generated #defines).
constexpr std::uint32_t HashMultiplier = 1664525u;
constexpr std::uint32_t HashIncrement = 1013904223u;
/// The step of uniformFromHash: 2^-24, so the top 24 bits of a hash give a
/// float in [0, 1) exactly (bpDraw in bp_shared.glsl gets it as BP_HASH_UNIT).
constexpr float HashUnit = 1.0f / 16777216.0f;

/// pcg4d over the four counters; returns the first lane.
inline std::uint32_t counterHash(
  std::uint32_t seed, std::uint32_t element, std::uint32_t generation, std::uint32_t draw)
{
  std::uint32_t x = seed * HashMultiplier + HashIncrement;
  std::uint32_t y = element * HashMultiplier + HashIncrement;
  std::uint32_t z = generation * HashMultiplier + HashIncrement;
  std::uint32_t w = draw * HashMultiplier + HashIncrement;
  x += y * w;
  y += z * x;
  z += x * y;
  w += y * z;
  x ^= x >> 16u;
  y ^= y >> 16u;
  z ^= z >> 16u;
  w ^= w >> 16u;
  x += y * w;
  y += z * x;
  z += x * y;
  w += y * z;
  return x;
}

/// Uniform float in [0, 1): the top 24 bits, exactly representable in a float.
inline float uniformFromHash(std::uint32_t h)
{
  return static_cast<float>(h >> 8u) * HashUnit;
}

/// Draw number `draw` of the reset of `element` in its `generation`.
inline float uniformDraw(
  std::uint32_t seed, std::uint32_t element, std::uint32_t generation, std::uint32_t draw)
{
  return uniformFromHash(counterHash(seed, element, generation, draw));
}

} // namespace bp

#endif

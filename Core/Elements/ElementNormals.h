// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ElementNormals.h
 * @brief Per-particle normals of elements: the mean of the unit normals of
 * the template's triangles at each particle.
 *
 * The output writes a normal for every particle on every update, so this is
 * on the path of every frame of Play (issue 16). The GPU's bp_normals shader
 * follows the same definition.
 */
#ifndef BoundParticles_ElementNormals_h
#define BoundParticles_ElementNormals_h

#include "ElementTemplate.h"

#include <cstddef>

namespace bp
{

/**
 * The normals of one element of `shape` at positions `p` (3n floats) into
 * `normals` (3n floats). A particle on no triangle of non-zero area (or
 * with non-finite corners) gets (0, 0, 1).
 */
void elementNormals(const ElementTemplate& shape, const float* p, float* normals);

/**
 * The normals of `count` consecutive elements (3n floats each at
 * `positions` and at `normals`), bit for bit as elementNormals() gives
 * them, four elements at a time in SSE2 lanes where there are some (Simd.h).
 */
void elementsNormals(
  const ElementTemplate& shape, const float* positions, float* normals, std::size_t count);

} // namespace bp

#endif

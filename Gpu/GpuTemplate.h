// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuTemplate.h
 * @brief The element template as the GPU engine's passes read it.
 *
 * Made once per configure() from the template and the element size:
 *  - the rest positions, one texel per template particle;
 *  - per particle, where its springs and triangles start in their lists and
 *    how many it has, its share of a spring's correction and whether it is
 *    pinned; the lists hold each particle's springs and triangles in index
 *    order, so the GPU sums corrections and normals in the CPU engine's order;
 *  - the springs by colour (colourSprings) for Gauss-Seidel, one pass per
 *    colour, applied in the order the CPU engine applies them;
 *  - optionally the springs written as GLSL code (thesis §3.5), for the Jacobi
 *    pass to compile in instead of reading its buffer: same corrections in the
 *    same order, so the same bits.
 *
 * Needs the GL context current; the textures are deleted as GlObjects.h says.
 */
#ifndef BoundParticles_GpuTemplate_h
#define BoundParticles_GpuTemplate_h

#include "ElementTemplate.h"
#include "GlObjects.h"

#include <array>
#include <string>

namespace bp
{

class GpuTemplate
{
public:
  /// Uploads the template's tables, its spring rest lengths scaled by
  /// `elementSize`; with `writeSpringCode`, also writes springSumCode.
  void upload(const ElementTemplate& shape, float elementSize, bool writeSpringCode);

  /// n x 1: rest positions.
  GlTexture rest;
  /// n x 2, per particle: its springs (first, count, 1 / degree, pinned),
  /// then its triangles (first, count).
  GlTexture particleInfo;
  /// Two texels a spring: (a, b, share, 0), (rest length, stiffness, 0, 0).
  GlTexture springs;
  /// Texels a row of `springs`; even, so a spring never spans two rows.
  int springsWidth = 2;
  /// A texel a triangle: its three particle indices.
  GlTexture triangles;
  int trianglesWidth = 1;
  /// 2n x colours: per colour, each particle's spring of that colour.
  GlTexture colouredSprings;
  int colourCount = 0;
  /// Linear shape matching's inverse rest moment (bp::restMomentInverse).
  std::array<float, 9> restMomentInverse = {};
  /// bpSpringSum() with the springs as code; empty unless asked for.
  std::string springSumCode;
};

} // namespace bp

#endif

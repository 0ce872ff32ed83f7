// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ElementTemplate.h
 * @brief The shape every element of a system is an instance of (thesis §3.3).
 *
 * A template is n particles with rest positions, springs that hold the shape,
 * and triangles that draw it. The springs decide how an element may fold and
 * need not follow the drawn edges. Rest positions are normalised so that the
 * template is centred on its centroid and its bounding sphere has diameter 1;
 * the engine then scales it by the element size in world units.
 */
#ifndef BoundParticles_ElementTemplate_h
#define BoundParticles_ElementTemplate_h

#include "BoundParticlesChoices.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace bp
{

struct Spring
{
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  float restLength = 0.0f;
  float stiffness = 1.0f; ///< in [0, 1]; 1 restores the full violation per iteration
};

/// The most springs a template may have (about 100 MB of spring tables);
/// All Pairs on a mesh of more than about 2,900 points passes it.
constexpr std::size_t MaxTemplateSprings = std::size_t(1) << 22;

struct ElementTemplate
{
  std::string name;
  std::vector<std::array<float, 3>> rest;
  std::vector<Spring> springs;
  std::vector<std::array<std::uint32_t, 3>> triangles; ///< counter-clockwise seen from outside
  std::vector<std::uint8_t> pinned;                    ///< empty, or one flag per particle

  std::size_t particleCount() const { return this->rest.size(); }

  /// Empty when the template is usable, otherwise what is wrong with it.
  std::string validate() const;

  /// Centres the rest shape on its centroid, scales its bounding sphere to
  /// diameter 1 and recomputes every spring's rest length.
  void normalize();
};

/**
 * The template's long axis, a unit vector in its own coordinates: what
 * Release Orientation = Along Flow turns onto the flow. The x axis (exactly)
 * where the template is at least as long along x as along any direction,
 * as every built-in shape is; otherwise the principal axis of its rest
 * positions (the direction of their largest spread), so a custom template
 * laid along y or z still swims along the flow, not across it.
 */
std::array<float, 3> longAxis(const ElementTemplate& shape);

/// A normalised template of the shape (BuiltinShape, in BoundParticlesChoices.h).
ElementTemplate builtinTemplate(BuiltinShape shape);

/**
 * A colouring of the springs in which no two springs of one colour share a
 * particle (greedy, in spring order): the colour of each spring. Gauss-Seidel
 * applies the springs colour by colour, so that each colour can run as one
 * parallel pass on the GPU and give the same result as on the CPU.
 */
std::vector<int> colourSprings(std::size_t particles, const std::vector<Spring>& springs);

/// Springs for a mesh of `particles` points and these triangles (MeshSprings, in
/// BoundParticlesChoices.h: which springs).
std::vector<std::array<std::uint32_t, 2>> meshSprings(std::size_t particles,
  const std::vector<std::array<std::uint32_t, 3>>& triangles, MeshSprings mode);

/**
 * Builds a template from points, triangles and spring pairs; rest lengths come
 * from the points. When `springPairs` is empty, the triangles' edges become the
 * springs. The result is normalised.
 */
ElementTemplate makeTemplate(const std::string& name,
  const std::vector<std::array<float, 3>>& points,
  const std::vector<std::array<std::uint32_t, 3>>& triangles,
  const std::vector<std::array<std::uint32_t, 2>>& springPairs);

/**
 * The template's triangles as one triangle strip, the way VTK reads a strip
 * (triangle k is s[k], s[k+1], s[k+2], the first two swapped when k is odd):
 * every triangle once, with its winding, in any order. Empty when they form
 * no strip (or are more than `MaxStripTriangles`). The output then has one
 * cell per element instead of one per triangle, which ParaView's geometry
 * filter and mappers walk cell by cell every frame.
 */
std::vector<std::uint32_t> triangleStrip(const ElementTemplate& shape);
constexpr std::size_t MaxStripTriangles = 1024;

} // namespace bp

#endif

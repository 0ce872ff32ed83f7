// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuState.h
 * @brief The GPU engine's state textures: particles, elements, and a step's scratch.
 *
 * A pass never reads the texture it writes, so what a step carries over
 * lives in pairs: a pass reads one and writes the other, which then becomes
 * current. Each pair flips on its own (the centres only when elements are
 * placed, the orientations only with shape matching). The scratch textures
 * hold a step's intermediate positions and shape-matching fits.
 *
 * Needs the GL context current; the textures are deleted as GlObjects.h says.
 */
#ifndef BoundParticles_GpuState_h
#define BoundParticles_GpuState_h

#include "GlObjects.h"
#include "GpuPasses.h"
#include "SuperSet.h"

#include <array>

namespace bp
{

/// Two textures of one size: a pass reads current() and writes next(), then flip().
class TexturePair
{
public:
  void make(int width, int height);
  GLuint current() const { return this->Textures[this->Current].get(); }
  GLuint next() const { return this->Textures[1 - this->Current].get(); }
  void flip() { this->Current = 1 - this->Current; }

private:
  std::array<GlTexture, 2> Textures;
  int Current = 0;
};

class GpuState
{
public:
  /// Makes every texture for `layout` (and the super set's, from `links`);
  /// the saved copy waits for the first save().
  void make(const GpuLayout& layout, const LinkTable& links);

  /// Keeps a copy of what a step carries over; restore() goes back to it.
  void save(const GpuPasses& passes, const GpuLayout& layout);
  /// Goes back to the copy of save(); nothing before the first save.
  void restore(const GpuPasses& passes, const GpuLayout& layout);

  // Per particle, a texel each (GpuLayout::particleTexel).
  TexturePair particles;             ///< grid-local position, force
  GlTexture advected;                ///< a step's positions after advection
  GlTexture before;                  ///< positions before the step (placed anew where reset)
  std::array<GlTexture, 2> restored; ///< restoration passes write these in turn
  GlTexture normals;                 ///< unit normal (updateNormals)
  GlTexture samples;                 ///< velocity, |curl v| (updateFieldSamples)

  // Per element, a texel each (element e at (e % W, e / W)).
  TexturePair elements;                 ///< lifetime, generation, reset flag, non-finite
  TexturePair centers;                  ///< the generation's initial centre
  TexturePair orientations;             ///< rotation as placed, then as fitted: a quaternion
  GlTexture matchCenters;               ///< shape matching: the fit's centre
  std::array<GlTexture, 2> matchLinear; ///< linear shape matching: the goal matrix, packed

  // A super set: per element its lattice site, its neighbours and link rest lengths.
  bool linked = false;
  GlTexture latticeSites; ///< made (zero) for every system: every pass binds it
  GlTexture linkNeighbours;
  GlTexture linkRest;

private:
  /// Copies the pairs' current textures into the saved copy, or back.
  void copySaved(const GpuPasses& passes, const GpuLayout& layout, bool intoCopy) const;

  /// The copy save() keeps of the current textures of the pairs.
  struct Saved
  {
    GlTexture particles, elements, centers, orientations;
  };
  Saved Copy;
};

} // namespace bp

#endif

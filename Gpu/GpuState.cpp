// SPDX-License-Identifier: BSD-3-Clause
#include "GpuState.h"

#include <algorithm>
#include <vector>

namespace bp
{

void TexturePair::make(int width, int height)
{
  for (GlTexture& texture : this->Textures)
  {
    texture = makeTexture2D(width, height);
  }
  this->Current = 0;
}

void GpuState::make(const GpuLayout& layout, const LinkTable& links)
{
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  this->particles.make(pw, ph);
  this->advected = makeTexture2D(pw, ph);
  this->before = makeTexture2D(pw, ph);
  for (GlTexture& texture : this->restored)
  {
    texture = makeTexture2D(pw, ph);
  }
  this->normals = makeTexture2D(pw, ph);
  this->samples = makeTexture2D(pw, ph);

  this->elements.make(w, h);
  this->centers.make(w, h);
  this->orientations.make(w, h);
  this->matchCenters = makeTexture2D(w, h);
  for (GlTexture& texture : this->matchLinear)
  {
    texture = makeTexture2D(w, h);
  }

  // The super set's lattice, the same table the CPU engine builds.
  this->linked = !links.empty();
  std::vector<float> sites(this->linked ? 4 * std::size_t(layout.elementCount) : 0, 0.0f);
  for (std::size_t e = 0; e < sites.size() / 4; ++e)
  {
    std::copy_n(&links.sites[3 * e], 3, &sites[4 * e]);
  }
  this->latticeSites = makeElementTexture(w, h, sites);
  if (this->linked)
  {
    this->linkRest = makeElementTexture(w, h, links.rest);
    this->linkNeighbours = makeElementIndexTexture(w, h, links.neighbours);
  }
}

void GpuState::save(const GpuPasses& passes, const GpuLayout& layout)
{
  if (!this->Copy.particles)
  {
    this->Copy.particles = makeTexture2D(layout.particleTextureWidth, layout.particleTextureHeight);
    this->Copy.elements = makeTexture2D(layout.elementGrid[0], layout.elementGrid[1]);
    this->Copy.centers = makeTexture2D(layout.elementGrid[0], layout.elementGrid[1]);
    this->Copy.orientations = makeTexture2D(layout.elementGrid[0], layout.elementGrid[1]);
  }
  this->copySaved(passes, layout, true);
}

void GpuState::restore(const GpuPasses& passes, const GpuLayout& layout)
{
  if (this->Copy.particles)
  {
    this->copySaved(passes, layout, false);
  }
}

void GpuState::copySaved(const GpuPasses& passes, const GpuLayout& layout, bool intoCopy) const
{
  struct Kept
  {
    GLuint live, copy;
    int width, height;
  };
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  // The current textures of the pairs, which stay current either way.
  const Kept kept[] = { { this->particles.current(), this->Copy.particles.get(), pw, ph },
    { this->elements.current(), this->Copy.elements.get(), w, h },
    { this->centers.current(), this->Copy.centers.get(), w, h },
    { this->orientations.current(), this->Copy.orientations.get(), w, h } };
  for (const Kept& k : kept)
  {
    if (intoCopy)
      passes.copyTexture(k.live, k.copy, k.width, k.height);
    else
      passes.copyTexture(k.copy, k.live, k.width, k.height);
  }
}

} // namespace bp

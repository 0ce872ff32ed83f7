// SPDX-License-Identifier: BSD-3-Clause
#include "GpuState.h"

#include <algorithm>
#include <limits>
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

int TrailRing::slot(int k) const
{
  const int slots = this->length();
  return ((this->newest - k) % slots + slots) % slots;
}

void GpuState::make(const GpuLayout& layout, const LinkTable& links, int trailLength, bool inertial)
{
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  this->particles.make(pw, ph);
  this->SlipWidth = inertial ? pw : 1;
  this->SlipHeight = inertial ? ph : 1;
  for (GlTexture* slip : { &this->slips, &this->slipsNext, &this->slipMoves })
  {
    *slip = makeTexture2D(this->SlipWidth, this->SlipHeight);
  }
  this->advected = makeTexture2D(pw, ph);
  this->before = makeTexture2D(pw, ph);
  for (GlTexture& texture : this->restored)
  {
    texture = makeTexture2D(pw, ph);
  }
  this->normals = makeTexture2D(pw, ph);
  this->samples = makeTexture2D(pw, ph);

  for (TexturePair& pair : this->perElement)
  {
    pair.make(w, h);
  }
  this->matchCenters = makeTexture2D(w, h);
  this->anchorShifts = makeTexture2D(w, h);
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

  const int slots = std::max(trailLength, 0);
  this->trail.particles.clear();
  this->trail.elements.clear();
  for (int k = 0; k < slots; ++k)
  {
    this->trail.particles.add(makeTexture2D(pw, ph));
    this->trail.elements.add(makeTexture2D(w, h));
  }
  this->trail.times.assign(std::size_t(slots), -std::numeric_limits<double>::infinity());
  this->trail.newest = -1;
}

void GpuState::clearTrail(const GpuPasses& passes)
{
  const float zero[4] = { 0, 0, 0, 0 }, noGeneration[4] = { 0, -1, 0, 0 };
  for (int k = 0; k < this->trail.length(); ++k)
  {
    passes.clearTexture(this->trail.particles[std::size_t(k)], zero);
    passes.clearTexture(this->trail.elements[std::size_t(k)], noGeneration);
  }
  std::fill(
    this->trail.times.begin(), this->trail.times.end(), -std::numeric_limits<double>::infinity());
  this->trail.newest = -1;
}

void GpuState::recordTrail(const GpuPasses& passes, const GpuLayout& layout, double t)
{
  TrailRing& r = this->trail;
  const int slots = r.length();
  if (slots == 0)
  {
    return;
  }
  const bool replaces = r.newest >= 0 && r.times[std::size_t(r.newest)] == t;
  const int slot = replaces ? r.newest : (r.newest + 1) % slots;
  if (this->Copy.watchesTrail && this->Copy.trailSlot < 0)
  {
    // A step after save(): keep what this slot held, for restore().
    this->copyTrailSlot(passes, layout, slot, true);
    this->Copy.trailSlot = slot;
  }
  r.newest = slot;
  r.times[std::size_t(slot)] = t;
  passes.copyTexture(this->particles.current(), r.particles[std::size_t(slot)],
    layout.particleTextureWidth, layout.particleTextureHeight);
  passes.copyTexture(this->current(ElementTexture::State), r.elements[std::size_t(slot)],
    layout.elementGrid[0], layout.elementGrid[1]);
}

void GpuState::copyTrailSlot(
  const GpuPasses& passes, const GpuLayout& layout, int slot, bool intoCopy)
{
  const GLuint live[2] = { this->trail.particles[std::size_t(slot)],
    this->trail.elements[std::size_t(slot)] };
  const GLuint copy[2] = { this->Copy.trailParticles.get(), this->Copy.trailElements.get() };
  const int width[2] = { layout.particleTextureWidth, layout.elementGrid[0] };
  const int height[2] = { layout.particleTextureHeight, layout.elementGrid[1] };
  for (int k = 0; k < 2; ++k)
  {
    if (intoCopy)
      passes.copyTexture(live[k], copy[k], width[k], height[k]);
    else
      passes.copyTexture(copy[k], live[k], width[k], height[k]);
  }
}

void GpuState::save(const GpuPasses& passes, const GpuLayout& layout)
{
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  if (!this->Copy.particles)
  {
    this->Copy.particles = makeTexture2D(pw, ph);
    this->Copy.slips = makeTexture2D(this->SlipWidth, this->SlipHeight);
    for (GlTexture& copy : this->Copy.perElement)
    {
      copy = makeTexture2D(w, h);
    }
    if (this->trail.length() > 0)
    {
      this->Copy.trailParticles = makeTexture2D(pw, ph);
      this->Copy.trailElements = makeTexture2D(w, h);
    }
  }
  this->copySaved(passes, layout, true);
  // A step records into at most one slot of the trail: recordTrail() keeps
  // that one before it overwrites it, so a save costs no copy of the ring.
  this->Copy.trailTimes = this->trail.times;
  this->Copy.trailNewest = this->trail.newest;
  this->Copy.trailSlot = -1;
  this->Copy.watchesTrail = this->trail.length() > 0;
}

void GpuState::restore(const GpuPasses& passes, const GpuLayout& layout)
{
  if (!this->Copy.particles)
  {
    return;
  }
  this->copySaved(passes, layout, false);
  // Without this a short step taken back would leave its record: the oldest
  // pose lost and a pose at the shown state's own time in the trail.
  if (this->Copy.trailSlot >= 0)
  {
    this->copyTrailSlot(passes, layout, this->Copy.trailSlot, false);
  }
  this->trail.times = this->Copy.trailTimes;
  this->trail.newest = this->Copy.trailNewest;
  this->Copy.watchesTrail = false; // the steps from here on are kept
}

void GpuState::copySaved(const GpuPasses& passes, const GpuLayout& layout, bool intoCopy) const
{
  this->copyState(passes, layout, this->Copy.particles.get(), this->Copy.slips.get(),
    this->Copy.perElement, intoCopy);
}

void GpuState::copyState(const GpuPasses& passes, const GpuLayout& layout, GLuint particles,
  GLuint slips, const std::array<GlTexture, ElementTextureCount>& perElement, bool intoCopy) const
{
  // The current textures of the pairs, which stay current either way.
  const auto copy = [&](GLuint live, GLuint kept, int width, int height)
  {
    if (intoCopy)
      passes.copyTexture(live, kept, width, height);
    else
      passes.copyTexture(kept, live, width, height);
  };
  copy(this->particles.current(), particles, layout.particleTextureWidth,
    layout.particleTextureHeight);
  copy(this->slips.get(), slips, this->SlipWidth, this->SlipHeight);
  for (int row = 0; row < ElementTextureCount; ++row)
  {
    copy(this->perElement[std::size_t(row)].current(), perElement[std::size_t(row)].get(),
      layout.elementGrid[0], layout.elementGrid[1]);
  }
}

void GpuState::keepCheckpoint(const GpuPasses& passes, const GpuLayout& layout, long long steps)
{
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  Checkpoint& c = this->Checkpoints[steps];
  if (!c.particles)
  {
    c.particles = makeTexture2D(pw, ph);
    c.slips = makeTexture2D(this->SlipWidth, this->SlipHeight);
    for (GlTexture& copy : c.perElement)
    {
      copy = makeTexture2D(w, h);
    }
    for (int k = 0; k < this->trail.length(); ++k)
    {
      c.trailParticles.add(makeTexture2D(pw, ph));
      c.trailElements.add(makeTexture2D(w, h));
    }
  }
  this->copyState(passes, layout, c.particles.get(), c.slips.get(), c.perElement, true);
  for (int k = 0; k < this->trail.length(); ++k)
  {
    const std::size_t slot = std::size_t(k);
    passes.copyTexture(this->trail.particles[slot], c.trailParticles[slot], pw, ph);
    passes.copyTexture(this->trail.elements[slot], c.trailElements[slot], w, h);
  }
  c.trailTimes = this->trail.times;
  c.trailNewest = this->trail.newest;
}

void GpuState::Checkpoint::reset()
{
  this->particles.reset();
  this->slips.reset();
  for (GlTexture& texture : this->perElement)
  {
    texture.reset();
  }
  this->trailParticles.clear();
  this->trailElements.clear();
}

bool GpuState::resumeCheckpoint(const GpuPasses& passes, const GpuLayout& layout, long long steps)
{
  const Checkpoint* found = this->Checkpoints.find(steps);
  if (!found)
  {
    return false;
  }
  const Checkpoint& c = *found;
  const int pw = layout.particleTextureWidth, ph = layout.particleTextureHeight;
  const int w = layout.elementGrid[0], h = layout.elementGrid[1];
  this->copyState(passes, layout, c.particles.get(), c.slips.get(), c.perElement, false);
  for (int k = 0; k < this->trail.length(); ++k)
  {
    const std::size_t slot = std::size_t(k);
    passes.copyTexture(c.trailParticles[slot], this->trail.particles[slot], pw, ph);
    passes.copyTexture(c.trailElements[slot], this->trail.elements[slot], w, h);
  }
  this->trail.times = c.trailTimes;
  this->trail.newest = c.trailNewest;
  // As after restore(): no short step is shown, the steps from here on are kept.
  this->Copy.watchesTrail = false;
  return true;
}

GpuState::Boundary GpuState::boundary(bool saved) const
{
  Boundary b;
  const bool copy = saved && this->Copy.particles;
  b.particles = copy ? this->Copy.particles.get() : this->particles.current();
  b.slips = copy ? this->Copy.slips.get() : this->slips.get();
  for (int row = 0; row < ElementTextureCount; ++row)
  {
    const std::size_t r = std::size_t(row);
    b.perElement[r] = copy ? this->Copy.perElement[r].get() : this->perElement[r].current();
  }
  for (int k = 0; k < this->trail.length(); ++k)
  {
    // The one slot a step since save() overwrote is in the copy.
    const bool kept = copy && this->Copy.trailSlot == k;
    b.trailParticles.push_back(
      kept ? this->Copy.trailParticles.get() : this->trail.particles[std::size_t(k)]);
    b.trailElements.push_back(
      kept ? this->Copy.trailElements.get() : this->trail.elements[std::size_t(k)]);
  }
  b.trailTimes = copy ? this->Copy.trailTimes : this->trail.times;
  b.trailNewest = copy ? this->Copy.trailNewest : this->trail.newest;
  return b;
}

void GpuState::setTrail(const std::vector<double>& times, int newest)
{
  this->trail.times = times;
  this->trail.newest = newest;
  // What save() kept is of another state now.
  this->Copy.watchesTrail = false;
  this->Copy.trailSlot = -1;
}

double GpuState::checkpointBytes(const GpuLayout& layout) const
{
  const double particleTexels =
    double(layout.particleTextureWidth) * double(layout.particleTextureHeight);
  const double elementTexels = double(layout.elementGrid[0]) * double(layout.elementGrid[1]);
  const double texels = particleTexels + double(this->SlipWidth) * double(this->SlipHeight) +
    ElementTextureCount * elementTexels + this->trail.length() * (particleTexels + elementTexels);
  return 16.0 * texels;
}

} // namespace bp

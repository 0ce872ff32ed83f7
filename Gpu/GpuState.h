// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuState.h
 * @brief The GPU engine's state textures: particles, elements, and a step's scratch.
 *
 * A pass never reads the texture it writes, so what a step carries over
 * lives in pairs: a pass reads one and writes the other, which then becomes
 * current. Each pair flips when a pass writes it (the centres only when
 * elements are placed, the orientations in the reset pass and with shape
 * matching, the poses in the reset and pose passes, the spins in the pose
 * pass). The per-element state is one list, ElementTexture: the textures,
 * the saved copy and the passes' GLSL declarations all follow it. The
 * scratch textures hold a step's intermediate positions and shape-matching
 * fits. Motion trails are a ring of copies of the particle and element
 * textures (TrailRing).
 *
 * Needs the GL context current; the textures are deleted as GlObjects.h says.
 */
#ifndef BoundParticles_GpuState_h
#define BoundParticles_GpuState_h

#include "GlObjects.h"
#include "GpuPasses.h"
#include "GpuStateLayout.h"
#include "SuperSet.h"

#include <array>
#include <map>
#include <string>
#include <vector>

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

/**
 * Motion trails (Parameters::trailLength): slot s holds the particle texture
 * and the element texture (generation in .y) as they were at the start of a
 * step at times[s] (Engine::recordTrail). The slot times and the newest slot
 * live on the host; the textures are copied by blits, never read back.
 */
struct TrailRing
{
  GlTextureList particles;   ///< per slot: position, force
  GlTextureList elements;    ///< per slot: lifetime, generation (-1: none), flags
  std::vector<double> times; ///< per slot; -infinity: nothing recorded
  int newest = -1;           ///< the slot written last, -1 before any

  int length() const { return int(this->times.size()); }
  /// The slot of the k-th newest pose (Engine::trailSlot).
  int slot(int k) const;
};

class GpuState
{
public:
  /// Makes every texture for `layout` (and the super set's, from `links`,
  /// and a trail ring of `trailLength` slots); the saved copy waits for the
  /// first save().
  void make(const GpuLayout& layout, const LinkTable& links, int trailLength, bool inertial);

  /// Keeps a copy of what a step carries over; restore() goes back to it.
  /// The trail ring is kept by its slot times and, copied when a step is
  /// about to overwrite it, the one slot a step records into (recordTrail).
  void save(const GpuPasses& passes, const GpuLayout& layout);
  /// Goes back to the copy of save(); nothing before the first save. The
  /// trail comes back whole when the steps since save() recorded at most one
  /// new slot, as the one short step the tracer takes back does.
  void restore(const GpuPasses& passes, const GpuLayout& layout);

  /// @name Checkpoints (Stepper::keepCheckpoint): copies, on the GPU, of
  /// what save() copies and of the whole trail ring (its textures, times
  /// and newest slot: many steps lie between a checkpoint and a resume),
  /// keyed by step count. Dropped with the state.
  ///@{
  void keepCheckpoint(const GpuPasses& passes, const GpuLayout& layout, long long steps);
  /// Goes back to the copy kept after `steps` steps, as restore() goes back
  /// to save()'s; false (nothing changed) if none was kept there.
  bool resumeCheckpoint(const GpuPasses& passes, const GpuLayout& layout, long long steps);
  void dropCheckpoints() { this->Checkpoints.clear(); }
  std::size_t checkpointCount() const { return this->Checkpoints.size(); }
  /// The bytes of one checkpoint's textures (bp::gpuCheckpointBytes).
  double checkpointBytes(const GpuLayout& layout) const;
  ///@}

  /// @name A state to save and resume (GpuEngineState.h)
  ///@{
  /// The textures that hold the state at a step boundary, and the trail's
  /// times and newest slot: the current ones, or with `saved` those of
  /// save()'s copy (a short step shown past the boundary; the current ones
  /// before any save()).
  struct Boundary
  {
    GLuint particles = 0, slips = 0;
    std::array<GLuint, ElementTextureCount> perElement{};
    std::vector<GLuint> trailParticles, trailElements; ///< by slot
    std::vector<double> trailTimes;
    int trailNewest = -1;
  };
  Boundary boundary(bool saved) const;
  /// The trail ring's times and newest slot, after its textures were written
  /// (a loaded state): a later restore() keeps them.
  void setTrail(const std::vector<double>& times, int newest);
  ///@}

  /// Empties the trail ring (Engine::initialize): no time recorded, every
  /// slot's generations -1 and positions 0.
  void clearTrail(const GpuPasses& passes);
  /// Records the current particle and element textures at time t into the
  /// next slot, or into the newest one when it holds t already (a step taken
  /// back and taken again records once), as Engine::recordTrail.
  void recordTrail(const GpuPasses& passes, const GpuLayout& layout, double t);

  // Per particle, a texel each (GpuLayout::particleTexel).
  TexturePair particles;             ///< grid-local position, force
  GlTexture advected;                ///< a step's positions after advection
  GlTexture before;                  ///< positions before the step (placed anew where reset)
  std::array<GlTexture, 2> restored; ///< restoration passes write these in turn
  GlTexture normals;                 ///< unit normal (updateNormals)
  GlTexture samples;                 ///< velocity, |curl v| (updateFieldSamples)
  /// Heavy particles (bp_slip.glsl; 1 x 1 each without inertia): the slip
  /// (carried over, saved), the slip pass's new slip and its displacement.
  GlTexture slips, slipsNext, slipMoves;

  // Per element, a texel each (element e at (e % W, e / W)).
  std::array<TexturePair, ElementTextureCount> perElement; ///< by ElementTexture
  TexturePair& element(ElementTexture row) { return this->perElement[std::size_t(row)]; }
  const TexturePair& element(ElementTexture row) const
  {
    return this->perElement[std::size_t(row)];
  }
  /// The current texture of a row.
  GLuint current(ElementTexture row) const { return this->element(row).current(); }
  GlTexture matchCenters;               ///< shape matching: the fit's centre
  GlTexture anchorShifts;               ///< Anchor = Centre: a step's move back to the anchor
  std::array<GlTexture, 2> matchLinear; ///< linear shape matching: the goal matrix, packed

  // A super set: per element its lattice site, its neighbours and link rest lengths.
  bool linked = false;
  GlTexture latticeSites; ///< made (zero) for every system: every pass binds it
  GlTexture linkNeighbours;
  GlTexture linkRest;

  TrailRing trail;

private:
  /// Copies the pairs' current textures into the saved copy, or back.
  void copySaved(const GpuPasses& passes, const GpuLayout& layout, bool intoCopy) const;
  /// Copies trail slot `slot` into the saved copy, or back.
  void copyTrailSlot(const GpuPasses& passes, const GpuLayout& layout, int slot, bool intoCopy);

  /// The copy save() keeps of the current textures of the pairs, and of the
  /// trail ring the times and the one slot a step since save() overwrote.
  struct Saved
  {
    GlTexture particles;
    GlTexture slips;
    std::array<GlTexture, ElementTextureCount> perElement;
    GlTexture trailParticles, trailElements;
    std::vector<double> trailTimes;
    int trailNewest = -1;
    int trailSlot = -1;        ///< the slot held in trailParticles / trailElements, -1: none
    bool watchesTrail = false; ///< from save() to restore(): keep the first slot overwritten
  };
  Saved Copy;
  /// A checkpoint: the textures save() copies, and the whole trail ring.
  struct Checkpoint
  {
    GlTexture particles;
    GlTexture slips;
    std::array<GlTexture, ElementTextureCount> perElement;
    GlTextureList trailParticles, trailElements;
    std::vector<double> trailTimes;
    int trailNewest = -1;

    /// Deletes its textures (the context must be current).
    void reset();
  };
  /**
   * The checkpoints by step count. Like GlObjectList, it deletes their
   * textures when cleared or when another set is assigned over it (the
   * engine's release assigns a new state): a std::map alone would only
   * forget them, as ~GlObject calls no GL, and their memory would stay held
   * after the tracer went (gui.memory found it).
   */
  class CheckpointSet
  {
  public:
    CheckpointSet() = default;
    CheckpointSet(CheckpointSet&&) noexcept = default;
    CheckpointSet& operator=(CheckpointSet&& other) noexcept
    {
      if (this != &other)
      {
        this->clear();
        this->Items = std::move(other.Items);
      }
      return *this;
    }
    /// Deletes every checkpoint's textures (the context must be current).
    void clear()
    {
      for (auto& item : this->Items)
      {
        item.second.reset();
      }
      this->Items.clear();
    }
    Checkpoint& operator[](long long steps) { return this->Items[steps]; }
    const Checkpoint* find(long long steps) const
    {
      const auto found = this->Items.find(steps);
      return found == this->Items.end() ? nullptr : &found->second;
    }
    std::size_t size() const { return this->Items.size(); }

  private:
    std::map<long long, Checkpoint> Items;
  };
  CheckpointSet Checkpoints;
  /// Copies the pairs' current textures and the slips into `particles`,
  /// `slips` and `perElement`, or back (save()'s copy and a checkpoint's alike).
  void copyState(const GpuPasses& passes, const GpuLayout& layout, GLuint particles, GLuint slips,
    const std::array<GlTexture, ElementTextureCount>& perElement, bool intoCopy) const;
  int SlipWidth = 1, SlipHeight = 1; ///< the slips' textures' size
};

} // namespace bp

#endif

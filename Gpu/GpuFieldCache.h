// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuFieldCache.h
 * @brief The field's time steps resident on the GPU, and the rectilinear axes' lookups.
 *
 * A field time step is an RGB32F 3D texture sampled exactly with texelFetch,
 * with, where the data marks points outside the flow's domain, an R8UI 3D
 * texture of the cells outside it (DomainMask.h) for the reposition test.
 * At most three are resident: the two the current field interpolates
 * between, and one arriving a slab of z layers at a time (stageSlice), so
 * that moving on to the next time step does not upload a whole volume at
 * once. A time step is known by its data (the shared velocity array), never
 * by an address that could be freed and reused.
 *
 * A rectilinear axis is sampled through its coordinate table and a lookup of
 * equal bins, each naming the cell its start falls in (bpLocate in
 * bp_common.glsl): the GPU finds a cell with one bin fetch and at most three
 * compares where the CPU engine searches.
 *
 * Every call needs the GL context current; the textures are deleted as
 * GlObjects.h says.
 */
#ifndef BoundParticles_GpuFieldCache_h
#define BoundParticles_GpuFieldCache_h

#include "DomainMask.h"
#include "GlObjects.h"
#include "VectorField.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

class GpuPass;

class GpuFieldCache
{
public:
  /// Makes the field's time steps resident: one already uploaded (or staged)
  /// is not uploaded again, the rest of a partly staged one is uploaded now,
  /// and the least recently used one outside the field makes room. Keeps a
  /// copy of the field (a grid and shared time steps: no velocities copied).
  /// Empty on success, otherwise why the GPU cannot sample this field.
  std::string setField(const VectorField& field);

  /// Uploads whole z layers (at least one, about maxBytes) of a time step on
  /// the current field's grid into the slot the field does not use. Returns
  /// the layers still to upload (0 when it is resident).
  int stageSlice(const FieldSlice& slice, std::size_t maxBytes);

  /// Whether the field last set has a periodic axis (Periodic.h).
  bool periodic() const
  {
    if (!this->Field)
    {
      return false;
    }
    const auto c = this->Field->samplingConstants();
    return c.periodic[0] || c.periodic[1] || c.periodic[2];
  }

  /// How many time steps are resident (at most three).
  int residentTimeSteps() const;

  /// The field last set; null before the first.
  const VectorField* field() const { return this->Field.get(); }

  /// Sets the sampling uniforms of bp_common.glsl and binds the current time
  /// steps and the axes' lookups. Only with a field set.
  void applyTo(GpuPass& pass) const;

  /// Binds where releases may not land (releaseUnfitCells of the current
  /// field at `minSpeed`, made once per field and speed) for the reset pass.
  void applyReleaseMaskTo(GpuPass& pass, float minSpeed);
  /// Binds the current field's Release Weights (its first time step's), or
  /// none (applyReleaseMaskTo calls it).
  void applyReleaseWeightsTo(GpuPass& pass);

private:
  /// A time step resident, or arriving a slab of z layers at a time. Held by
  /// its data, so a freed and reused address can never pass for it.
  struct Slot
  {
    GlTexture texture;
    std::shared_ptr<const std::vector<float>> data;
    /// The time step's cells outside the domain (R8UI, as DomainMask.h), or none.
    GlTexture outsideTexture;
    std::shared_ptr<const std::vector<std::uint8_t>> outside;
    int layers = 0; ///< z layers uploaded so far
    std::uint64_t lastUse = 0;
  };

  std::string checkSize(const GridGeometry& grid) const;
  Slot& slotFor(const std::shared_ptr<const std::vector<float>>& data, int keepA, int keepB);
  void uploadLayers(Slot& slot, const GridGeometry& grid, int count);
  /// Gives the slot the time step's mask of cells outside the domain.
  void uploadOutside(Slot& slot, const GridGeometry& grid, const FieldSlice& slice);
  /// The mask a slot without one binds: an active sampler needs a texture.
  GLuint outsideTextureOf(const Slot& slot) const;
  void fitSlots(const GridGeometry& grid);
  std::string uploadAxes(const VectorField& field);

  // Two time steps in use and one arriving: at most three volumes resident.
  std::array<Slot, 3> Slots;
  std::array<int, 3> SlotDims = { 0, 0, 0 }; ///< the grid every slot is sized for
  std::uint64_t UseClock = 0;
  int CurrentSlots[2] = { -1, -1 }; ///< the current field's first and second time step

  GlTexture NoOutsideTexture; ///< one cell, inside
  GlTexture ReleaseTexture;   ///< the release mask, or none
  /// The mask's cells (releaseUnfitCells), for the weights' reach.
  std::shared_ptr<const std::vector<std::uint8_t>> ReleaseUnfit;
  ReleaseMaskSource ReleaseFrom;
  GlTexture WeightsTexture;                              ///< (|w|, 0, 0) per grid point, or none
  GlTexture NoWeightsTexture;                            ///< one point of weight 0
  std::shared_ptr<const std::vector<float>> WeightsFrom; ///< what WeightsTexture was made from
  float WeightMax = 0.0f;
  std::array<float, 3> WeightSupportMin = { 0, 0, 0 }; ///< ReleaseWeights::supportMin
  std::array<float, 3> WeightSupportMax = { 0, 0, 0 };
  GlTexture AxesTexture; ///< per axis: coordinate table, then bin lookup (bp_common.glsl)
  std::array<std::vector<float>, 3> AxesTables; ///< what AxesTexture was made from
  int Bins[3] = { 1, 1, 1 };
  float BinScale[3] = { 0, 0, 0 }; ///< bins per unit of length

  std::unique_ptr<VectorField> Field;
};

} // namespace bp

#endif

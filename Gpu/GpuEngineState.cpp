// SPDX-License-Identifier: BSD-3-Clause
// The GPU engine's state as a bp::EngineState, read back and uploaded (GpuEngineState.h).
#include "GpuEngineState.h"

#include "GpuSystem.h"
#include "ParticleLayout.h"

#include <array>
#include <cstdint>
#include <cstring>
#include <vector>

namespace bp
{
namespace
{
std::uint32_t bitsOf(float value)
{
  std::uint32_t word;
  std::memcpy(&word, &value, sizeof word);
  return word;
}

float floatOf(std::uint32_t word)
{
  float value;
  std::memcpy(&value, &word, sizeof value);
  return value;
}

/// The state's values in the textures' terms, element-major: per element 4
/// floats a row (the texture's texel order), per particle 3 (or 1) floats.
struct Columns
{
  std::array<std::vector<float>, ElementTextureCount> rows;
  std::vector<float> positions, forces, slips;
  std::vector<std::vector<float>> trailPositions, trailElements; ///< by slot

  std::vector<float>& row(ElementTexture r) { return this->rows[std::size_t(r)]; }
};

/**
 * Moves one record's words from or into the columns, element e of E with n
 * particles: `read` true fills `record` from the columns. False if the
 * layout holds an array the GPU engine does not know.
 */
bool transfer(Columns& c, const std::vector<StateArray>& layout, std::size_t e, std::size_t n,
  std::uint32_t* record, bool read)
{
  // A float column's values at `at`, `count` of them.
  const auto floats = [&](float* at, std::size_t count)
  {
    for (std::size_t k = 0; k < count; ++k, ++record)
    {
      if (read)
        *record = bitsOf(at[k]);
      else
        at[k] = floatOf(*record);
    }
  };
  float* state = &c.row(ElementTexture::State)[4 * e];
  float* centers = &c.row(ElementTexture::Centers)[4 * e];
  for (const StateArray& array : layout)
  {
    const std::string& name = array.name;
    if (name == "Ids")
    {
      *record = read ? std::uint32_t(e) : *record;
      ++record;
    }
    else if (name == "Generations")
    {
      if (read)
        *record = std::uint32_t(state[1]);
      else
        state[1] = float(*record);
      ++record;
    }
    else if (name == "ResetFlags")
    {
      // The test's flag (1 due, 2 terminated this step) and the centre's .w
      // (1 hidden, 2 terminated before): bp_reset.glsl's encoding.
      if (read)
        *record = (state[2] > 0.5f && state[2] < 1.5f ? ResetDue : 0u) |
          (centers[3] > 0.5f && centers[3] < 1.5f ? ReleaseHidden : 0u) |
          (state[2] > 1.5f || centers[3] > 1.5f ? Terminated : 0u);
      else
      {
        state[2] = (*record & ResetDue) ? 1.0f : 0.0f;
        state[3] = 0.0f;
        centers[3] = (*record & Terminated) ? 2.0f : (*record & ReleaseHidden) ? 1.0f : 0.0f;
      }
      ++record;
    }
    else if (name == "Lifetimes")
      floats(state, 1);
    else if (name == "InitialCenters")
      floats(centers, 3);
    else if (name == "Orientations")
      floats(&c.row(ElementTexture::Orientations)[4 * e], 4);
    else if (name == "Poses")
      floats(&c.row(ElementTexture::Poses)[4 * e], 4);
    else if (name == "Spins")
      floats(&c.row(ElementTexture::Spins)[4 * e], 4);
    else if (name == "Positions")
      floats(&c.positions[3 * n * e], 3 * n);
    else if (name == "Forces")
      floats(&c.forces[n * e], n);
    else if (name == "Slips")
      floats(&c.slips[3 * n * e], 3 * n);
    else if (name == "TrailGenerations")
    {
      for (std::vector<float>& slot : c.trailElements)
      {
        float* g = &slot[4 * e + 1];
        if (read)
          *record = *g < 0.0f ? NoTrailPose : std::uint32_t(*g);
        else
          *g = *record == NoTrailPose ? -1.0f : float(*record);
        ++record;
      }
    }
    else if (name == "TrailPositions")
    {
      for (std::vector<float>& slot : c.trailPositions)
        floats(&slot[3 * n * e], 3 * n);
    }
    else
      return false;
  }
  return true;
}

std::size_t wordsOf(const std::vector<StateArray>& layout)
{
  std::size_t words = 0;
  for (const StateArray& array : layout)
    words += array.components;
  return words;
}

/// Every column read from the textures of `b`.
Columns readColumns(const GpuSystem& S, const GpuState::Boundary& b)
{
  Columns c;
  const int w = S.layout.elementGrid[0], h = S.layout.elementGrid[1];
  for (int r = 0; r < ElementTextureCount; ++r)
    S.passes.readTexture(b.perElement[std::size_t(r)], w, h, c.rows[std::size_t(r)]);
  S.passes.readParticles(b.particles, S.layout, &c.positions, &c.forces);
  if (carriesInertia(S.parameters))
    S.passes.readParticles(b.slips, S.layout, &c.slips, nullptr);
  for (std::size_t k = 0; k < b.trailParticles.size(); ++k)
  {
    c.trailPositions.emplace_back();
    S.passes.readParticles(b.trailParticles[k], S.layout, &c.trailPositions.back(), nullptr);
    c.trailElements.emplace_back();
    S.passes.readTexture(b.trailElements[k], w, h, c.trailElements.back());
  }
  return c;
}
} // namespace

std::string readEngineState(const GpuSystem& S, bool saved, EngineState& out)
{
  const GpuState::Boundary b = S.state.boundary(saved);
  Columns c = readColumns(S, b);
  EngineState state;
  state.layout = Engine::stateLayout(S.shape, S.parameters);
  state.recordWords = wordsOf(state.layout);
  const std::size_t E = std::size_t(S.layout.elementCount);
  const std::size_t n = std::size_t(S.layout.particlesPerElement);
  state.records.assign(E * state.recordWords, 0u);
  for (std::size_t e = 0; e < E; ++e)
  {
    if (!transfer(c, state.layout, e, n, &state.records[e * state.recordWords], true))
    {
      return "the GPU engine holds no array of this record's layout";
    }
  }
  state.trailTimes = b.trailTimes;
  state.trailNewest = b.trailNewest;
  state.emitterMin = S.parameters.emitterMin;
  state.emitterMax = S.parameters.emitterMax;
  out = std::move(state);
  return std::string();
}

std::string loadEngineState(GpuSystem& S, const EngineState& state)
{
  const std::size_t E = std::size_t(S.layout.elementCount);
  std::string error =
    checkEngineState(state, Engine::stateLayout(S.shape, S.parameters), S.parameters);
  error = error.empty() ? gpuStateRefusal(state, E) : error;
  if (!error.empty())
  {
    return error;
  }
  // The current textures, so that their padding keeps its texels.
  Columns c = readColumns(S, S.state.boundary(false));
  const std::size_t n = std::size_t(S.layout.particlesPerElement);
  for (std::size_t e = 0; e < E; ++e)
  {
    // A trail slot holds no lifetime nor flag in the record (its colour only).
    for (std::vector<float>& slot : c.trailElements)
      slot[4 * e] = slot[4 * e + 2] = slot[4 * e + 3] = 0.0f;
    std::vector<std::uint32_t> record(state.records.begin() + std::ptrdiff_t(e * state.recordWords),
      state.records.begin() + std::ptrdiff_t((e + 1) * state.recordWords));
    if (!transfer(c, state.layout, e, n, record.data(), false))
    {
      return "the GPU engine holds no array of this record's layout";
    }
  }
  const GpuState::Boundary b = S.state.boundary(false);
  const int w = S.layout.elementGrid[0], h = S.layout.elementGrid[1];
  for (int r = 0; r < ElementTextureCount; ++r)
    S.passes.writeTexture(b.perElement[std::size_t(r)], w, h, c.rows[std::size_t(r)]);
  S.passes.writeParticles(b.particles, S.layout, c.positions, &c.forces);
  if (carriesInertia(S.parameters))
    S.passes.writeParticles(b.slips, S.layout, c.slips, nullptr);
  for (std::size_t k = 0; k < b.trailParticles.size(); ++k)
  {
    S.passes.writeParticles(b.trailParticles[k], S.layout, c.trailPositions[k], nullptr);
    S.passes.writeTexture(b.trailElements[k], w, h, c.trailElements[k]);
  }
  S.state.setTrail(state.trailTimes, state.trailNewest);
  S.parameters.emitterMin = state.emitterMin;
  S.parameters.emitterMax = state.emitterMax;
  S.updateNormals();
  return std::string();
}

} // namespace bp

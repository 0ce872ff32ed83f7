// SPDX-License-Identifier: BSD-3-Clause
// A state to save and resume (Engine.h, EngineState.h): every element's
// record, as migration packs it (EngineMigration.cpp), laid out by the one
// list of per-element arrays (Engine::forEachElementArray), and the
// engine's scalars around the elements.
#include "Engine.h"

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace bp
{
namespace
{
template <class T>
StateArray::Type stateType()
{
  static_assert(
    std::is_same_v<T, std::uint32_t> || std::is_same_v<T, std::uint8_t> || std::is_same_v<T, float>,
    "a per-element array of another type needs a StateArray::Type");
  if constexpr (std::is_same_v<T, std::uint32_t>)
  {
    return StateArray::Type::UInt32;
  }
  else if constexpr (std::is_same_v<T, std::uint8_t>)
  {
    return StateArray::Type::UInt8;
  }
  else
  {
    return StateArray::Type::Float32;
  }
}
} // namespace

std::vector<StateArray> Engine::stateLayout() const
{
  std::vector<StateArray> layout;
  forEachElementArray(*this,
    [&layout](
      const char* name, const auto& /*array*/, std::size_t width, std::size_t blocks, auto fill)
    {
      if (width * blocks > 0)
      {
        layout.push_back({ name, stateType<decltype(fill)>(), width * blocks });
      }
    });
  return layout;
}

std::vector<StateArray> Engine::stateLayout(
  const ElementTemplate& shape, const Parameters& parameters)
{
  // An engine of no element with the shape's particle count and the
  // parameters: the list reads nothing else (its arrays stay empty).
  Engine sizes;
  sizes.Shape.rest = shape.rest;
  sizes.Params = parameters;
  return sizes.stateLayout();
}

EngineState Engine::saveState() const
{
  EngineState state;
  state.layout = this->stateLayout();
  state.recordWords = this->recordWords();
  const std::size_t E = this->elementCount();
  state.records.reserve(E * state.recordWords);
  for (std::size_t e = 0; e < E; ++e)
  {
    this->packElement(e, state.records); // Ids increasing, as the engine keeps them
  }
  state.trailTimes = this->TrailTimes;
  state.trailNewest = this->TrailNewest;
  state.emitterMin = this->Params.emitterMin;
  state.emitterMax = this->Params.emitterMax;
  return state;
}

std::string Engine::loadState(const EngineState& state)
{
  std::string error = checkEngineState(state, this->stateLayout(), this->Params);
  if (!error.empty())
  {
    return error;
  }
  // A resumed trace's events start at the state's time (a state holds none).
  this->Log.clear();
  // Every element held leaves; the state's, all of them (checkEngineState),
  // come in by exchange()'s merge (which takes a super set too: nothing is
  // split here).
  error = this->merge(std::vector<std::uint8_t>(this->elementCount(), 1), state.records);
  if (!error.empty())
  {
    return error;
  }
  this->TrailTimes = state.trailTimes;
  this->TrailNewest = state.trailNewest;
  this->setEmitter(state.emitterMin, state.emitterMax);
  // The state is on a step boundary: the next step resets what is due.
  this->ResetsDone = false;
  return std::string();
}

} // namespace bp

// SPDX-License-Identifier: BSD-3-Clause
// Migration between the pieces of a distributed run (Engine.h, "Distributed
// runs"): an element's state as 32-bit words and the exchange that drops the
// elements leaving and takes in those arriving. Both walk the one list of
// per-element arrays (Engine::forEachElementArray), so a record holds every
// array in that list, bit for bit. A saved state's records are the same
// (EngineSaveState.cpp): Engine::loadState takes them in by the same merge.
#include "Engine.h"

#include <algorithm>
#include <cstring>
#include <type_traits>
#include <utility>

namespace bp
{
namespace
{
std::uint32_t toWord(std::uint32_t u)
{
  return u;
}
std::uint32_t toWord(std::uint8_t u)
{
  return u;
}
std::uint32_t toWord(float f)
{
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

template <class T>
T fromWord(std::uint32_t u)
{
  if constexpr (std::is_same_v<T, float>)
  {
    float f;
    std::memcpy(&f, &u, sizeof f);
    return f;
  }
  else
  {
    return T(u);
  }
}
/// Where exchange() takes each element from, in the new order.
struct Sources
{
  /// (id, source) per element: source < held is an element kept, otherwise
  /// the record source - held.
  const std::vector<std::pair<std::uint32_t, std::size_t>>& order;
  std::size_t held;
  const std::vector<std::uint32_t>& records;
  std::size_t words; ///< per record
};

/// One per-element array (Engine::forEachElementArray's `width` and
/// `blocks`) after an exchange: each element's values from the array or
/// from its record, where the array's words start `offset` words in.
template <class T>
std::vector<T> merged(const std::vector<T>& array, std::size_t width, std::size_t blocks,
  const Sources& from, std::size_t offset)
{
  const std::size_t E = from.order.size(), held = from.held;
  std::vector<T> out(blocks * E * width);
  for (std::size_t k = 0; k < E; ++k)
  {
    const std::size_t source = from.order[k].second;
    for (std::size_t b = 0; b < blocks; ++b)
    {
      T* to = out.data() + (b * E + k) * width;
      if (source < held)
      {
        std::copy_n(array.data() + (b * held + source) * width, width, to);
        continue;
      }
      const std::uint32_t* words =
        from.records.data() + (source - held) * from.words + offset + b * width;
      for (std::size_t j = 0; j < width; ++j)
      {
        to[j] = fromWord<T>(words[j]);
      }
    }
  }
  return out;
}
} // namespace

void Engine::setDomain(const Domain& domain)
{
  this->HasDomain = true;
  this->DomainBox = domain;
}

std::array<float, 3> Engine::centerOf(std::size_t e) const
{
  // Summed in float, particle by particle, as the reposition test sums it.
  const std::size_t n = this->Shape.particleCount();
  const float* p = this->Positions.data() + 3 * e * n;
  float c[3] = { 0, 0, 0 };
  for (std::size_t i = 0; i < n; ++i)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[k] += p[3 * i + k];
    }
  }
  const float count = float(n);
  return { c[0] / count, c[1] / count, c[2] / count };
}

std::size_t Engine::recordWords() const
{
  std::size_t words = 0;
  forEachElementArray(*this,
    [&words](const char* /*name*/, const auto& /*array*/, std::size_t width, std::size_t blocks,
      auto /*fill*/) { words += width * blocks; });
  return words;
}

std::size_t Engine::recordWords(const ElementTemplate& shape, const Parameters& parameters)
{
  // forEachElementArray's widths and blocks, from the shape and parameters alone.
  const std::size_t n = shape.particleCount();
  const std::size_t slots = std::size_t(std::max(parameters.trailLength, 0));
  const std::size_t perElement = 1 + 1 + 1 + 1 + 3 + 4 + 4 + 4; // ids ... spins
  const std::size_t perParticle = 3 + 1 + (carriesInertia(parameters) ? 3 : 0);
  return perElement + perParticle * n + slots * (1 + 3 * n);
}

void Engine::packElement(std::size_t e, std::vector<std::uint32_t>& out) const
{
  const std::size_t E = this->elementCount();
  forEachElementArray(*this,
    [&](
      const char* /*name*/, const auto& array, std::size_t width, std::size_t blocks, auto /*fill*/)
    {
      for (std::size_t b = 0; b < blocks; ++b)
      {
        const auto* values = array.data() + (b * E + e) * width;
        for (std::size_t k = 0; k < width; ++k)
        {
          out.push_back(toWord(values[k]));
        }
      }
    });
}

std::string Engine::mergeOrder(const std::vector<std::uint8_t>& leaving,
  const std::vector<std::uint32_t>& records,
  std::vector<std::pair<std::uint32_t, std::size_t>>& order) const
{
  const std::size_t held = this->elementCount(), words = this->recordWords();
  for (std::size_t e = 0; e < held; ++e)
  {
    if (!leaving[e])
    {
      order.emplace_back(this->Ids[e], e);
    }
  }
  const std::size_t incoming = records.size() / words;
  for (std::size_t r = 0; r < incoming; ++r)
  {
    const std::uint32_t id = records[r * words]; // the record's first word (Ids)
    if (id >= this->Params.numberOfElements)
    {
      return "an element record carries id " + std::to_string(id) + " of " +
        std::to_string(this->Params.numberOfElements) + " elements";
    }
    order.emplace_back(id, held + r);
  }
  std::sort(order.begin(), order.end());
  for (std::size_t k = 1; k < order.size(); ++k)
  {
    if (order[k].first == order[k - 1].first)
    {
      return "element " + std::to_string(order[k].first) + " arrived twice";
    }
  }
  return std::string();
}

std::string Engine::exchange(
  const std::vector<std::uint8_t>& leaving, const std::vector<std::uint32_t>& records)
{
  const std::size_t held = this->elementCount(), words = this->recordWords();
  if (leaving.size() != held)
  {
    return "the leaving flags do not match the elements held";
  }
  if (records.size() % words != 0)
  {
    return "the element records do not match this element template";
  }
  if (!this->Links.empty())
  {
    return "a super set cannot be split among pieces";
  }
  if (records.empty() && std::find(leaving.begin(), leaving.end(), 1) == leaving.end())
  {
    return std::string(); // nothing moves: the elements stay as they are, in order
  }
  return this->merge(leaving, records);
}

std::string Engine::merge(
  const std::vector<std::uint8_t>& leaving, const std::vector<std::uint32_t>& records)
{
  const std::size_t held = this->elementCount(), words = this->recordWords();
  std::vector<std::pair<std::uint32_t, std::size_t>> order;
  const std::string error = this->mergeOrder(leaving, records, order);
  if (!error.empty())
  {
    return error;
  }
  const Sources sources{ order, held, records, words };
  std::size_t offset = 0; // of the array's words in a record
  forEachElementArray(*this,
    [&](const char* /*name*/, auto& array, std::size_t width, std::size_t blocks, auto /*fill*/)
    {
      array = merged(array, width, blocks, sources, offset);
      offset += blocks * width;
    });
  // A record's flags keep only the bits a flag may hold.
  for (std::uint8_t& flags : this->ResetFlags)
  {
    flags = std::uint8_t(flags & (ResetDue | ReleaseHidden | AlignPending | Terminated));
  }
  this->Scratch.visitOrder.clear();
  this->Scratch.normals.clear(); // recomputed from the positions before they are shown
  return std::string();
}

} // namespace bp

// SPDX-License-Identifier: BSD-3-Clause
#include "VelocityNames.h"

#include <algorithm>
#include <cctype>
#include <string>

namespace bp
{
namespace
{
/// `name` split into lower-case words: at separators, where a lower-case
/// letter or digit is followed by an upper-case one (WindVelocity), and
/// where digits follow a letter (Velocity3D).
std::vector<std::string> words(const std::string& name)
{
  std::vector<std::string> result(1);
  for (std::size_t i = 0; i < name.size(); ++i)
  {
    const unsigned char c = static_cast<unsigned char>(name[i]);
    if (!std::isalnum(c))
    {
      if (!result.back().empty())
      {
        result.emplace_back();
      }
      continue;
    }
    const unsigned char before = i > 0 ? static_cast<unsigned char>(name[i - 1]) : 0;
    const bool camel = std::isupper(c) && (std::islower(before) || std::isdigit(before));
    const bool digits = std::isdigit(c) && std::isalpha(before);
    if ((camel || digits) && !result.back().empty())
    {
      result.emplace_back();
    }
    result.back() += char(std::tolower(c));
  }
  if (result.back().empty())
  {
    result.pop_back();
  }
  return result;
}

bool among(const std::string& word, std::initializer_list<const char*> list)
{
  return std::any_of(list.begin(), list.end(), [&](const char* w) { return word == w; });
}

/// A velocity's own names, as words.
bool velocityWord(const std::string& w)
{
  return among(w,
    { "velocity", "velocities", "vel", "velo", "vels", "u", "uvw", "v", "wind", "flow", "current",
      "currents" });
}

/// Words of other vector quantities: a name holding one is not a velocity
/// (acceleration, displacement, vorticity, gradients, normals...).
bool otherQuantity(const std::string& w)
{
  return among(w,
    { "acceleration", "accel", "accl", "acc", "displacement", "displ", "disp", "vorticity", "vort",
      "curl", "grad", "gradient", "normals", "normal", "coordinates", "coords", "force", "forces",
      "position", "positions", "tangent", "tangents", "stress", "strain", "b", "e", "magnetic",
      "electric" });
}
} // namespace

int velocityNameRank(const std::string& name)
{
  const std::vector<std::string> w = words(name);
  if (w.empty() || std::any_of(w.begin(), w.end(), otherQuantity))
  {
    return -1;
  }
  if (w.size() == 1 && velocityWord(w[0]))
  {
    return 0;
  }
  return std::any_of(w.begin(), w.end(), velocityWord) ? 1 : -1;
}

bool namesOtherQuantity(const std::string& name)
{
  const std::vector<std::string> w = words(name);
  return std::any_of(w.begin(), w.end(), otherQuantity);
}

int pickDefaultVectors(const std::vector<std::string>& names, int active)
{
  if (names.empty())
  {
    return -1;
  }
  if (active >= 0 && std::size_t(active) < names.size())
  {
    return active;
  }
  return std::max(pickVelocityName(names), 0);
}

int preferFittingUnits(const std::vector<VectorsCandidate>& candidates, int chosen)
{
  if (chosen < 0 || std::size_t(chosen) >= candidates.size() ||
    candidates[std::size_t(chosen)].unitsFit)
  {
    return chosen;
  }
  int best = chosen, bestRank = 3;
  for (std::size_t i = 0; i < candidates.size(); ++i)
  {
    const VectorsCandidate& c = candidates[i];
    if (!c.unitsFit || namesOtherQuantity(c.name))
    {
      continue;
    }
    const int named = velocityNameRank(c.name);
    const int rank = named >= 0 ? named : 2; // a name that says nothing after a velocity's
    if (rank < bestRank)
    {
      best = int(i);
      bestRank = rank;
    }
  }
  return best;
}

std::string fittingUnitsReason(
  const std::string& mismatched, bool mismatchedActive, const std::string& warning)
{
  // The time line's units warnings state their findings, then turn to what
  // the velocity's units may be ("...: the velocity's units may not match",
  // "...; check the velocity's units").
  std::string findings = warning;
  for (const char* turn :
    { ", so the trace crumples", ": the velocity's units", "; check the velocity's units" })
  {
    const std::size_t at = findings.find(turn);
    if (at != std::string::npos)
    {
      findings.resize(at);
    }
  }
  if (!findings.empty())
  {
    findings[0] = char(std::tolower(static_cast<unsigned char>(findings[0])));
  }
  return "its units fit the grid and the time steps, while those of '" + mismatched + "'" +
    (mismatchedActive ? ", the input's active vectors," : "") + " do not" +
    (findings.empty() ? std::string() : ": " + findings);
}

int pickVelocityName(const std::vector<std::string>& names)
{
  int best = -1, bestRank = -1;
  for (std::size_t i = 0; i < names.size(); ++i)
  {
    const int rank = velocityNameRank(names[i]);
    if (rank >= 0 && (best < 0 || rank < bestRank))
    {
      best = int(i);
      bestRank = rank;
    }
  }
  return best;
}

} // namespace bp

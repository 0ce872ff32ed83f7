// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerSaidOnce.h
 * @brief The tracer's warnings said once per configuration.
 *
 * An unsteady input, a replay (going back in time, another display's update)
 * or an in situ step would say the same warning at every update. Each kind
 * of warning is a Topic; `first(topic)` is true the first time it is asked
 * since the last `forget()` (the tracer's invalidate(): a change of the
 * filter or its input), and for a topic given a text, again whenever that
 * text differs from the last one given.
 */
#ifndef BoundParticles_TracerSaidOnce_h
#define BoundParticles_TracerSaidOnce_h

#include <map>
#include <string>

namespace bpvtk
{

/// What a warning said once per configuration is about.
enum class Topic
{
  NonFinite,    ///< the input's NaN share
  Mask,         ///< an unusable vtkValidPointMask
  Resample,     ///< the resampler's warning (blocks without the Vectors, the grid)
  Weights,      ///< Release Weights unusable
  Seeds,        ///< the seed points' warnings
  OutOfPlane,   ///< a flat field's crossing vectors
  GridChange,   ///< in situ, a change of grid
  CellVectors,  ///< point Vectors made of a cell array
  Emitter,      ///< the emitter box moved into a changed grid (releaseIntoGrid)
  Interactions, ///< the engine's event log full (bp::InteractionLog::full)
  Surfaces      ///< what of the Surfaces input is left out
};

class SaidOnce
{
public:
  /// True when `topic` was not said since the last forget(), or was said
  /// with another text: say it now. Records it as said with `text`.
  bool first(Topic topic, const std::string& text = std::string())
  {
    const auto found = this->Said.find(topic);
    if (found != this->Said.end() && found->second == text)
    {
      return false;
    }
    this->Said[topic] = text;
    return true;
  }
  /// Whether `topic` was said since the last forget(), whatever its text.
  bool said(Topic topic) const { return this->Said.count(topic) > 0; }
  /// A new configuration: every topic may be said again.
  void forget() { this->Said.clear(); }

private:
  std::map<Topic, std::string> Said; ///< each topic said, with its last text
};

} // namespace bpvtk

#endif

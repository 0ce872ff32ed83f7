// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file StreamTimeLine.h
 * @brief The time line of an input that offers only its present time step.
 *
 * In situ (Catalyst's producer, a source flagged with no prior temporal
 * access, a trivial producer fed one step at a time) the input holds one time
 * step; the next arrives later and the past cannot be asked for again. The
 * trace advances with each step that arrives, from the last one to the
 * present, and needs both: the tracer keeps the last in its FieldCache. This
 * line is the times the trace has been given since it started, in the order
 * they came; each new time is judged against it: the first starts the trace,
 * a later one advances it, a repeated or earlier one is refused (the trace
 * keeps its state).
 *
 * No VTK here.
 */
#ifndef BoundParticles_StreamTimeLine_h
#define BoundParticles_StreamTimeLine_h

#include <string>
#include <vector>

namespace bp
{

class StreamTimeLine
{
public:
  /// What a time that arrives does to the trace.
  enum class Arrival
  {
    Start,   ///< the first time: the trace starts there
    Advance, ///< later than the last: the trace advances to it
    Repeat,  ///< the last time again: refused, the trace stays
    Back,    ///< earlier than the last, or not finite: refused, the trace stays
  };

  /// Judges `time` and, for Start and Advance, adds it to the line.
  Arrival offer(double time);

  /// What to tell the user of a refused arrival of `time` (empty otherwise).
  std::string refusal(Arrival arrival, double time) const;

  /// The trace starts again at the present time (a setting changed, or the
  /// trace was lost): only the last time is kept.
  void restartAtPresent();

  /// The present time's step could not be taken (its data was unusable):
  /// it leaves the line, and the next time that arrives advances the trace
  /// from the one before it.
  void dropPresent();

  void clear() { this->Times.clear(); }
  bool empty() const { return this->Times.empty(); }
  /// The times given since the trace started, increasing.
  const std::vector<double>& times() const { return this->Times; }
  double present() const { return this->Times.empty() ? 0.0 : this->Times.back(); }

private:
  std::vector<double> Times;
};

} // namespace bp

#endif

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerTimeLine.h
 * @brief The tracer's time line, post hoc: resolved from the input's time
 * steps and the filter's time properties, its warnings said once, and the
 * Vectors default's units check.
 *
 * The filter owns one and calls it from RequestInformation (docs/design.md,
 * "One update"). Before Vectors is chosen (a tracer just made, whose default
 * comes next: vtkSMBoundParticleVectorsDomain) the check tries each
 * 3-component point array's units against the time line it would give, and
 * keeps the array whose units failed, the one preferred and why
 * (UnitsMismatchedVectors, UnitsFittingVectors) while the input (its
 * producer, port and pipeline MTime) is the same; the time line's warnings
 * then wait for an update that still has no Vectors (sayPending()).
 *
 * It reads the filter only through vtkAlgorithm (its input) and the
 * settings it is given: it does not include the filter's header.
 */
#ifndef BoundParticles_TracerTimeLine_h
#define BoundParticles_TracerTimeLine_h

#include "TraceSettings.h" // for bp::TimeLine, bp::TimeScale

#include "vtkType.h" // for vtkMTimeType

#include <string>
#include <tuple>
#include <vector>

class vtkAlgorithm;
class vtkDataObject;
class vtkInformation;
class vtkInformationVector;

namespace bpvtk
{
struct FieldProbe;
struct TracerConfig;

/// The filter's properties that make its time line.
struct TimeLineSettings
{
  double duration = 0.0;          ///< Duration (0: automatic)
  int framesPerInputStep = 0;     ///< Frames Per Input Step (0: automatic)
  int numberOfTimeSteps = 0;      ///< Number Of Time Steps
  double stepSize = 0.0;          ///< Step Size
  bool stepInCellLengths = false; ///< Step Size Unit is Cell Length

  /// Whether the time line is resolved from the field's speed (a probe).
  bool automatic(const std::vector<double>& inputTimes) const;
  /// Frames Per Input Step out of its range (automatic frames are used).
  bool framesOutOfRange() const;
  /// bp::resolveTimeLine of these settings.
  bp::TimeLine resolve(const std::vector<double>& inputTimes, const bp::TimeScale& scale) const;
};

class TracerTimeLine
{
public:
  /// `owner` (the filter) is the input read and the object messages name.
  explicit TracerTimeLine(vtkAlgorithm* owner);

  /// The input's TIME_STEPS (none for a steady input).
  static std::vector<double> inputTimeSteps(vtkInformation* inInfo);
  /// Not an MPI run of several processes (their pieces may offer different arrays).
  static bool isSerialRun();
  /// Both outputs' time steps and range, `times` (none where null), and
  /// the FTLE map's extent from `probe` (bpvtk::announceFtleMap).
  static void announce(vtkInformationVector* outputVector, const std::vector<double>* times,
    const TracerConfig& config, const FieldProbe& probe);

  /// RequestInformation's units check: true when it runs again (the input
  /// changed, or Vectors is still unchosen), its findings then forgotten.
  bool beginUnitsCheck(bool unchosen);
  /// Of the data the probe delivered: prefers an array whose units fit
  /// when the default's do not (bp::preferFittingUnits).
  void preferFittingVectors(const TimeLineSettings& settings, vtkDataObject* data,
    vtkInformation* inInfo, const std::vector<double>& inputTimes);
  /// Asked before RequestInformation saw the input (pvpython sets the
  /// Vectors default as soon as Input is set): the check on the data the
  /// input holds, as it holds it, updating nothing. Once per input.
  void checkHeldInput(const TimeLineSettings& settings);

  /// The time line of `settings`; its warnings said once, or held for an
  /// update while Vectors is `unchosen`. An out-of-range Frames Per Input
  /// Step is an error (automatic frames are used).
  bp::TimeLine resolve(const TimeLineSettings& settings, const std::vector<double>& inputTimes,
    const bp::TimeScale& scale, bool unchosen);
  /// Says the warnings held while Vectors was unchosen (an update that
  /// still has none).
  void sayPending();

  /// The array whose units failed the check, and the one preferred.
  const std::string& mismatchedVectors() const { return this->Mismatched; }
  const std::string& fittingVectors() const { return this->Fitting; }
  /// Why `vectors` (a point array) was preferred for its units; empty when
  /// it was not (bp::fittingUnitsReason).
  std::string reasonFor(const std::string& vectors, int association) const;

private:
  using InputKey = std::tuple<const void*, int, vtkMTimeType>;
  InputKey inputKey() const;
  /// Forgets the findings: they are of the input `key` from now on.
  void restartUnitsCheck(const InputKey& key);
  /// Each warning not said by the last resolve().
  void sayOnce(const std::vector<std::string>& warnings);

  vtkAlgorithm* const Owner;
  /// The warnings resolved while Vectors was not chosen.
  std::vector<std::string> Pending;
  /// The last warnings said (the pipeline asks for information again after
  /// every change, and the same warning twice in a row says nothing new).
  std::vector<std::string> Said;
  std::string Mismatched;             ///< the array whose units failed the check
  std::string Fitting;                ///< the one preferred
  std::string Reason;                 ///< why
  InputKey Checked{ nullptr, -1, 0 }; ///< the input they were found of
};

} // namespace bpvtk

#endif

// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, replaying: the settings resolved against the
// start's field, the checks of a new trace, and the stepper configured and
// placed at the start. See vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "ElementStretch.h"
#include "ElementTemplate.h"
#include "Memory.h"
#include "Partition.h"
#include "Periodic.h"
#include "TracerInput.h"
#include "VectorField.h"
#include "vtkBoundParticleSeedType.h"

#include "vtkDataObject.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"

#include <algorithm>

bpvtk::TracerPass vtkBoundParticleTracerInternals::replay(
  const Config& config, vtkInformationVector** inputVector)
{
  const std::vector<int> ids = this->Plan.needed(this->Plan.startTime(), this->target());
  const int missing = this->Held.cache.firstMissing(ids);
  if (missing >= 0)
  {
    return Pass::need(missing);
  }
  if (this->Layout.distributed() && config.linking())
  {
    return Pass::fail("Super sets (Linking) run in one process; in parallel (" +
      std::to_string(this->Layout.Pieces) + " processes) set Linking to None.");
  }
  const bp::VectorField field = this->Held.cache.field(this->Held.grid, ids);
  bpvtk::TracerSeeds seeds;
  // With Linking no seeds are used: a Surface is not even drawn (it may
  // have nothing to release over), only said to be unused, as the others.
  const bool unusedSurface =
    config.linking() && config.seedType && config.seedType->UsesSeedSource();
  const std::string seedError =
    unusedSurface ? std::string() : this->gatherSeeds(config, inputVector, field, seeds);
  if (!seedError.empty())
  {
    return Pass::fail(seedError);
  }
  bp::FieldFacts facts = this->fieldFacts(field);
  this->restartInSitu(config, facts);
  bp::TraceSettings settings = config.trace;
  settings.seeded = !seeds.xyz.empty() && !config.linking();
  if ((!seeds.xyz.empty() || unusedSurface) && config.linking())
  {
    vtkWarningWithObjectMacro(this->Owner,
      "Linking places each super set as one structure in the emitter box: the "
        << (unusedSurface ? config.seedType->GetSeedTypeName() : seeds.name)
        << " is not used. Set Linking to None to release from the seeds.");
    seeds.xyz.clear();
  }
  const bp::Resolution resolved = bp::resolveSettings(settings, facts);
  this->Resolved.settings = settings;
  for (const std::string& warning : resolved.warnings)
  {
    vtkWarningWithObjectMacro(this->Owner, << warning);
  }
  if (!resolved.error.empty())
  {
    return Pass::fail(resolved.error);
  }
  this->Resolved.dt = resolved.dt;
  this->Resolved.elementSize = resolved.elementSize;
  this->Resolved.startMaxSpeed = facts.maxSpeed;
  if (this->needMoreGhostLayers(resolved, facts))
  {
    this->Held.cache.clear();
    return Pass::need(ids.front());
  }
  const Pass configured = this->configureStepper(config, inputVector, field, resolved, seeds);
  if (configured.kind == Pass::Done)
  {
    this->startTrace(config);
  }
  return configured;
}

std::string vtkBoundParticleTracerInternals::gatherSeeds(const Config& config,
  vtkInformationVector** inputVector, const bp::VectorField& field, bpvtk::TracerSeeds& seeds)
{
  if (config.seedType && config.seedType->UsesSeedSource())
  {
    return this->surfaceSeedPoints(config, inputVector, field, seeds);
  }
  const std::string seedError = this->readSeeds(config, inputVector, seeds.xyz);
  if (!seedError.empty())
  {
    return seedError;
  }
  seeds.total = seeds.xyz.size() / 3;
  if (config.seedSource && seeds.xyz.empty())
  {
    vtkWarningWithObjectMacro(
      this->Owner, "The Seed Source has no points; elements are released in the emitter box.");
  }
  if (config.seedSource && config.seedType)
  {
    // A connected input is the more deliberate choice, and kept its meaning
    // in scripts and state files made before there were Seed Types.
    vtkWarningWithObjectMacro(this->Owner,
      "A Seed Source is connected: its points are the release positions, and Seed Type "
        << config.seedType->GetSeedTypeName()
        << " is not used. Disconnect it (SeedSource = None) to release from the "
        << config.seedType->GetSeedTypeName() << ".");
  }
  if (!config.seedSource)
  {
    this->seedTypePoints(config, field, seeds);
    this->warnOfUnusableSeeds(config.seedType);
  }
  return std::string();
}

bool vtkBoundParticleTracerInternals::needMoreGhostLayers(
  const bp::Resolution& resolved, const bp::FieldFacts& facts)
{
  if (!this->Layout.distributed())
  {
    return false;
  }
  // Enough ghost layers for an element and a step at twice the start's
  // largest speed (an unsteady flow may speed up; heavy particles settle at
  // up to gravity's speed); if the pieces in hand have fewer, ask for them
  // again with more. Every process computes the same number from the same
  // global values.
  const int needed = bp::ghostCellsNeeded(resolved.elementSize,
    2.0 * std::max(facts.maxSpeed, resolved.speed), resolved.dt, this->Layout.DomainSmallestCell);
  if (needed <= this->Layout.GhostCells)
  {
    return false;
  }
  this->Layout.GhostCells = needed;
  return true;
}

bp::FieldFacts vtkBoundParticleTracerInternals::fieldFacts(const bp::VectorField& field)
{
  bp::FieldFacts facts;
  // The whole field's, also in parallel where this process holds a piece.
  facts.bounds = this->Layout.domainBounds(this->Held.grid);
  facts.offset = this->Held.offset;
  facts.dims = this->Layout.wholeDims(this->Held.grid); // its flat axes, as keepInPlane's
  facts.cellLength = this->Layout.cellLength(this->Held.grid);
  facts.maxSpeed = field.maxSpeed();
  if (this->Layout.distributed())
  {
    facts.maxSpeed = this->Layout.globalMax(facts.maxSpeed);
  }
  const std::vector<double>& times = this->Plan.outputTimes();
  facts.timeSpan = times.back() - times.front();
  return facts;
}

std::string vtkBoundParticleTracerInternals::elementTemplate(
  const Config& config, vtkInformationVector** inputVector, bp::ElementTemplate& shape)
{
  shape = bp::builtinTemplate(config.shape);
  if (!config.templateInput)
  {
    return std::string();
  }
  std::string error;
  vtkPolyData* mesh = bpvtk::templateMesh(vtkDataObject::GetData(inputVector[1], 0), error);
  return error.empty() ? bpvtk::templateFromPolyData(mesh, config.templateSprings, shape) : error;
}

void vtkBoundParticleTracerInternals::warnOfReleaseWindow(const bp::Parameters& p)
{
  // Tested in the trace's own time, said in the data's (TimeDirection.h).
  const std::vector<double>& times = this->Plan.outputTimes();
  const std::vector<double>& offered = this->Plan.offeredTimes();
  const bool backward = this->Plan.direction() == bp::TimeDirection::Backward;
  const std::array<double, 2> window =
    bp::traceWindow(this->Plan.direction(), p.releaseStart, p.releaseStop);
  if (!times.empty() && (p.releaseStop < times.front() || p.releaseStart > times.back()))
  {
    vtkWarningWithObjectMacro(this->Owner,
      "No element is released: the Release Window ["
        << window[0] << ", " << window[1] << "] lies outside the offered times [" << offered.front()
        << ", " << offered.back() << "]"
        << (backward ? " (a backward trace releases from the window's latest time on)." : "."));
  }
  else if (times.size() > 1 && p.releaseStart == times.back())
  {
    // A step releases what is due in [t, t + h): the last offered time ends
    // the last step, so a window that starts there releases in none.
    vtkWarningWithObjectMacro(this->Owner,
      "No element is shown released: the Release Window "
        << (backward ? "ends at the first offered time (" : "starts at the last offered time (")
        << bp::traceTime(this->Plan.direction(), times.back())
        << (backward ? "), where the backward trace ends. End it later."
                     : "), after the last step. Start it earlier."));
  }
}

void vtkBoundParticleTracerInternals::warnOfDeformation(
  const Config& config, const bp::ElementTemplate& shape, const bp::Parameters& p)
{
  const bool map = p.releasePattern == bp::ReleasePattern::Lattice;
  const bool arrays =
    config.wants(bp::OutputArrayId::ElementFTLE) || config.wants(bp::OutputArrayId::ElementStretch);
  if ((map || arrays) && bp::StretchFit(shape.rest, 1.0).span() == 0)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "The element template has a single particle (Element Shape Point), which cannot stretch: "
        << (arrays ? "ElementFTLE is 0 and ElementStretch 1 everywhere" : "")
        << (arrays && map ? ", and " : "") << (map ? "the FTLE map marks every point invalid" : "")
        << ". Choose a shape of several particles (Cross, Strip...) to measure stretch.");
  }
}

std::string vtkBoundParticleTracerInternals::checkPeriodic(
  const Config& config, const bp::VectorField& field) const
{
  static const char* const axes[3] = { "x", "y", "z" };
  std::string named;
  for (int a = 0; a < 3; ++a)
  {
    if (config.periodic[a])
    {
      named += named.empty() ? axes[a] : std::string(", ") + axes[a];
    }
  }
  if (named.empty())
  {
    return std::string();
  }
  for (int a = 0; a < 3; ++a)
  {
    if (config.periodic[a] && field.grid().dims[a] < 2)
    {
      return std::string("Periodic along ") + axes[a] + " needs the grid to have more than one " +
        "point along " + axes[a] + ", but it has " + std::to_string(field.grid().dims[a]) +
        ": turn Periodic off along " + axes[a] + ".";
    }
  }
  if (config.linking())
  {
    return "Periodic (" + named +
      ") cannot be used with Linking: a super set's elements would move across a periodic side "
      "one by one, and their links would then span the whole domain; set Linking to None.";
  }
  return std::string();
}

void vtkBoundParticleTracerInternals::warnOfPeriodicSeams(
  const Config& config, const bp::VectorField& field) const
{
  static const char* const axes[3] = { "x", "y", "z" };
  const auto& velocity = field.firstSlice().velocity;
  if (!(config.periodic[0] || config.periodic[1] || config.periodic[2]))
  {
    return;
  }
  const bool distributed = this->Layout.distributed();
  double fastest = 0.0;
  if (distributed)
  {
    // Collective, on every process alike (checkPeriodic passed on each): the
    // whole field's largest speed.
    fastest = this->Layout.globalMax(velocity ? bp::largestFiniteSpeed(*velocity) : 0.0);
  }
  for (int a = 0; a < 3; ++a)
  {
    // The period is the extent: a last plane that is not a copy of the first
    // (data one spacing short of its period) is traced, but with a jump at
    // the seam and the wrong period. A thousandth of the top speed is rounding.
    double mismatch = 0.0;
    if (config.periodic[a] && distributed)
    {
      // Each piece holds the whole periodic axis, over its block of the others.
      const double difference = this->Layout.globalMax(
        velocity ? bp::periodicSeamDifference(field.grid(), *velocity, a) : 0.0);
      mismatch = fastest > 0.0 ? difference / fastest : 0.0;
    }
    else if (config.periodic[a] && velocity)
    {
      mismatch = bp::periodicSeamMismatch(field.grid(), *velocity, a);
    }
    if (mismatch > 1e-3)
    {
      vtkWarningWithObjectMacro(this->Owner,
        "Periodic along " << axes[a] << ": the grid's last plane along " << axes[a]
                          << " is not a copy of its first (they differ by up to "
                          << 100.0 * mismatch
                          << "% of the largest speed). The period is the grid's extent, its last "
                             "plane standing for its first; data whose last plane is one spacing "
                             "short of the period is traced with a jump at the seam: append a "
                             "copy of the first plane (the user guide's Periodic domains).");
    }
  }
}

std::string vtkBoundParticleTracerInternals::checkConfiguration(const Config& config,
  vtkInformationVector** inputVector, const bp::VectorField& field, const bpvtk::TracerSeeds& seeds,
  bp::ElementTemplate& shape, bp::Parameters& p)
{
  if (this->Plan.streaming() && config.trace.timeDirection == bp::TimeDirection::Backward)
  {
    return "Time Direction = Backward needs the whole time series, but in situ only the present "
           "time step arrives: set Time Direction to Forward.";
  }
  const std::string periodicError = this->checkPeriodic(config, field);
  if (!periodicError.empty())
  {
    return periodicError;
  }
  this->warnOfPeriodicSeams(config, field);
  const std::string templateError = this->elementTemplate(config, inputVector, shape);
  if (!templateError.empty())
  {
    return templateError;
  }
  this->warnOfDeformation(config, shape, p);
  p.trailStart = this->Resolved.scheduleStart; // trail poses on the schedule's own steps
  if (!seeds.xyz.empty())
  {
    const std::string seedError = this->seedPoints(seeds, field, p);
    if (!seedError.empty())
    {
      return seedError;
    }
  }
  this->gatherSurfaces(config, inputVector, field, p);
  if (!this->InSitu.restart)
  {
    // A restart's only time is its first step: its elements came before.
    this->warnOfReleaseWindow(p);
  }
  // The engine's own checks first: they name the setting to change.
  const std::string invalid = bp::Engine::validate(shape, p);
  if (!invalid.empty())
  {
    return invalid + ".";
  }
  const std::string memoryError = bp::checkAllocatable(bp::traceBytes(shape, p),
    std::to_string(p.numberOfElements) + " elements of " + std::to_string(shape.particleCount()) +
      " particles");
  if (!memoryError.empty())
  {
    return memoryError + "; use fewer elements or a smaller template.";
  }
  const float stable = bp::stableRelaxation(shape);
  if (p.restoration == bp::Restoration::Jacobi && p.relaxation > stable)
  {
    vtkWarningWithObjectMacro(this->Owner,
      "Relaxation Factor " << p.relaxation
                           << " would make Jacobi diverge on this element (a particle's springs "
                           << "add up to " << 1.0f / stable << " shares); using " << stable
                           << ", the largest stable factor. Averaged Jacobi needs no factor.");
    p.relaxation = stable;
  }
  const std::string fallback = this->Steppers.fallBackIfTooLarge(shape, p);
  if (!fallback.empty())
  {
    vtkWarningWithObjectMacro(this->Owner, << fallback);
  }
  const std::string error = this->stepper().configure(shape, p);
  return error.empty() ? error : error + ".";
}

bpvtk::TracerPass vtkBoundParticleTracerInternals::configureStepper(const Config& config,
  vtkInformationVector** inputVector, const bp::VectorField& field, const bp::Resolution& resolved,
  const bpvtk::TracerSeeds& seeds)
{
  bp::ElementTemplate shape;
  bp::Parameters p = resolved.parameters;
  std::string error = this->checkConfiguration(config, inputVector, field, seeds, shape, p);
  if (this->Layout.distributed())
  {
    // The checks above are each process's own (its template, its memory);
    // what follows is collective.
    error = this->Layout.agree(error);
  }
  if (!error.empty())
  {
    return Pass::fail(error);
  }
  // A mask that leaves no cell inside the flow's domain (masked or NaN
  // corners everywhere in the start's interval): no release could land.
  const bp::ReleaseMask inside = this->Layout.distributed()
    ? this->Layout.releaseMask()(field, 0.0f)
    : bp::ReleaseMask{ field.grid(), bp::releaseUnfitCells(field, 0.0f) };
  if (bp::leavesNoCell(inside))
  {
    return Pass::fail("No cell of the field lies inside the flow's domain at the start (every "
                      "cell has a corner where vtkValidPointMask is 0 or the vector is NaN or "
                      "Inf, in one of its time steps): there is nowhere to release elements.");
  }
  this->warnOfUnreachableWeights(config, field, p);
  bp::Stepper& stepper = this->stepper();
  error = stepper.setField(field);
  if (!error.empty())
  {
    return Pass::fail(error + ".");
  }
  if (this->Layout.distributed())
  {
    this->Steppers.distributed().setPieces(
      *this->Layout.Partition, this->Layout.Domain, this->Layout.Piece);
  }
  stepper.initialize(this->Plan.startTime());
  this->Resolved.parameters = p;
  this->Resolved.particlesPerElement = shape.particleCount();
  this->Resolved.traceBytes = bp::traceBytes(shape, p);
  // Then, with an Initial State File, its elements instead of those placed.
  error = this->resumeFromState(config, shape, p);
  if (!error.empty())
  {
    return Pass::fail(error);
  }
  if (this->Steppers.queue())
  {
    // The display's output has no particles: it carries the ranges they span.
    this->Resolved.rangeFacts = bp::rangeFactsOf(field, p, resolved.dt, config.coloringAxis,
      this->Held.offset, this->Held.grid.bounds(), shape.particleCount());
  }
  return Pass();
}

void vtkBoundParticleTracerInternals::warnOfUnreachableWeights(
  const Config& config, const bp::VectorField& field, const bp::Parameters& p)
{
  const bool weighted = !config.releaseWeights.empty() && p.seedPoints.empty() &&
    p.releasePattern == bp::ReleasePattern::Random && p.linking == bp::Linking::None;
  if (!weighted || this->Said.said(bpvtk::Topic::Weights))
  {
    return; // not used, or already said to be unusable
  }
  // Collective in a distributed run, as every process takes this path alike.
  const auto& values = field.firstSlice().releaseWeights;
  const bool local = values && bp::releaseWeightsOf(field.grid(), values) != nullptr;
  const bool any =
    this->Layout.distributed() ? this->Layout.globalMax(local ? 1.0 : 0.0) > 0.0 : local;
  const bp::ReleaseMask mask = this->Layout.distributed()
    ? this->Layout.releaseMask()(field, p.releaseMinSpeed)
    : bp::releaseMaskOf(field, p.releaseMinSpeed);
  if (any && !mask.weights && this->Said.first(bpvtk::Topic::Weights))
  {
    vtkWarningWithObjectMacro(this->Owner,
      "Release Weights: the array '"
        << config.releaseWeights
        << "' is above 0 only where releases may not land (vtkValidPointMask 0, NaN or Inf "
           "vectors, or flow slower than MinimumReleaseSpeed); releases are uniform.");
  }
}

void vtkBoundParticleTracerInternals::startTrace(const Config& config)
{
  this->Storage.reset(); // the element count or shape may have changed
  this->Schedule.reset(new bp::StepSchedule(this->Resolved.scheduleStart, this->Resolved.dt,
    this->Plan.unsteady() ? this->Plan.inputTimes() : std::vector<double>()));
  bp::Stepper& stepper = this->stepper();
  stepper.dropCheckpoints();
  this->Spacing = this->checkpointSpacing(config);
  bp::TraceCursor& cursor = stepper.cursor;
  cursor.committed = this->Plan.startTime();
  cursor.steps = 0;
  cursor.valid = true;
  cursor.configuration = this->Configuration;
  cursor.producer = this->ProducerId;
  cursor.showsPartialStep = false;
  if (this->ResumedSteps >= 0)
  {
    // The state resumed stands where its trace stood; kept as a checkpoint
    // (when checkpoints are kept), so going back to it is a copy.
    cursor.committed = this->ResumedTime;
    cursor.steps = this->ResumedSteps;
    if (this->Spacing.every > 0)
    {
      stepper.keepCheckpoint(cursor.steps, cursor.committed);
    }
  }
  this->ReplayPending = false;
}

bp::CheckpointSpacing vtkBoundParticleTracerInternals::checkpointSpacing(const Config& config)
{
  bp::Stepper& stepper = this->stepper();
  if (!stepper.keepsCheckpoints() || this->Plan.streaming())
  {
    return bp::CheckpointSpacing();
  }
  // The whole system's state as the stepper keeps it (Engine::recordWords,
  // the same on every process, so that every process keeps its checkpoints
  // at the same steps; the GPU engine's textures, padding included, where
  // they are larger: bp::gpuCheckpointBytes).
  const double stateBytes = stepper.checkpointBytes();
  // Automatic: half the whole trace's size (engine and output), the same
  // estimate that refuses a trace too large for the process.
  const double asked = config.checkpointMemory < 0.0 ? 0.5 * this->Resolved.traceBytes
                                                     : config.checkpointMemory * 1048576.0;
  const double budget = std::min(asked, 0.5 * bp::allocatableBytes());
  return bp::checkpointSpacing(budget, stateBytes, this->Plan.stepsToEnd(this->Resolved.dt));
}

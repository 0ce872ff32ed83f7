// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleTracerInternals.h"

#include "ElementTemplate.h"
#include "Memory.h"
#include "Partition.h"
#include "TraceSettings.h"
#include "TracerInput.h"
#include "VectorField.h"
#include "vtkBoundParticleSeedType.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>

namespace
{
std::uint64_t nextProducerId()
{
  static std::mutex m;
  static std::uint64_t next = 0;
  std::lock_guard<std::mutex> lock(m);
  return ++next;
}

/// The array name the Vectors property asks for; empty when none is set.
std::string vectorsName(vtkBoundParticleTracer* self)
{
  vtkInformation* info = self->GetInputArrayInformation(0);
  const char* name = info && info->Has(vtkDataObject::FIELD_NAME())
    ? info->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  return name ? name : "";
}
} // namespace

vtkBoundParticleTracer::vtkInternals::vtkInternals()
  : ProducerId(nextProducerId())
{
}

void vtkBoundParticleTracer::vtkInternals::invalidate()
{
  ++this->Configuration;
  this->WarnedNonFinite = false;
  this->WarnedMask = false;
  this->WarnedResample = false;
  this->Steppers.invalidate();
}

void vtkBoundParticleTracer::vtkInternals::clear()
{
  this->Steppers.active().cursor.valid = false;
  this->Cache.clear();
  this->Continuing = false;
}

void vtkBoundParticleTracer::vtkInternals::forgetTrace()
{
  this->invalidate();
  this->clear();
  this->LastRequested = -1;
}

void vtkBoundParticleTracer::vtkInternals::endFailedUpdate()
{
  this->clear();
  this->invalidate();
}

void vtkBoundParticleTracer::vtkInternals::decide(
  vtkBoundParticleTracer* self, vtkInformation* outInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  this->Steppers.select(bp::EngineChoice(self->Engine), outInfo, this->Layout);
  const std::string& software = this->Steppers.automaticCpuOn();
  if (!software.empty() && !this->SaidAutomaticCpu)
  {
    // Once per tracer: the display asks on every frame.
    this->SaidAutomaticCpu = true;
    const std::string text = "Bound Particle Tracer: Engine is Automatic and this render "
                             "window draws with a software renderer (" +
      software +
      "), on which the GPU engine is slower: the CPU engine traces. Set Engine to GPU to use the "
      "GPU engine anyway.\n";
    vtkOutputWindowDisplayText(text.c_str());
  }
  const double target = this->Plan.targetOf(
    outInfo->Has(SDDP::UPDATE_TIME_STEP()), outInfo->Get(SDDP::UPDATE_TIME_STEP()));
  this->Decision =
    this->Plan.decide(target, this->stepper().cursor, this->ProducerId, this->Configuration);
  this->RequestIndex = this->Plan.firstRequest(this->Decision, this->Cache, this->LastRequested);
}

void vtkBoundParticleTracer::vtkInternals::begin(vtkBoundParticleTracer* self)
{
  bp::Stepper& stepper = this->stepper();
  const bool replay = this->Decision.replay;
  this->ReplayPending = replay;
  this->StepsInLastUpdate = 0;
  this->Migrated = 0;
  this->LastUpdateReplayed = replay;
  this->ReadThisUpdate = false;
  this->IntervalAtStart = replay || !this->Plan.unsteady()
    ? -1
    : this->Plan.intervalAt(stepper.cursor.committed, false).front();
  if (!replay && stepper.cursor.showsPartialStep)
  {
    // Take back the short step the last update showed: the trace stays on
    // the step boundaries, so a replay and a continued run agree bit for bit.
    stepper.restore();
  }
  stepper.cursor.showsPartialStep = false;
  // An abort ends the update it was asked in, not every later one: VTK 9.2
  // to 9.5 leave the request set (ParaView 6.1 clears it itself). Cleared
  // without Modified(), which would make this update's output look stale.
  self->AbortExecute = 0;
  // Progress runs over the whole update, across its passes.
  this->ProgressFrom = replay ? this->Plan.startTime() : stepper.cursor.committed;
  this->ProgressAt = this->ProgressFrom;
  if (replay && this->Layout.distributed() && this->Layout.Piece == 0 && self->Engine == GPU)
  {
    vtkWarningWithObjectMacro(self,
      "The GPU engine runs in one process; with "
        << this->Layout.Pieces
        << " processes the CPU engine traces and the Bound Particles display draws its "
           "particles on every process.");
  }
  if (replay)
  {
    stepper.cursor.valid = false;
    // A steady input's single time step is read again at every replay; an
    // unsteady input's stay valid (RequestInformation drops them when the
    // input changes).
    if (!this->Plan.unsteady())
    {
      this->Cache.clear();
    }
  }
}

std::string vtkBoundParticleTracer::vtkInternals::takeTimeStep(
  vtkBoundParticleTracer* self, vtkInformationVector** inputVector)
{
  // A first pass with every time step in hand asked for whatever upstream
  // held: take it only if the work needs it.
  const std::vector<int> planned = this->Plan.needed(this->steppingFrom(), this->target());
  const bool wanted = this->Continuing ||
    std::find(planned.begin(), planned.end(), this->RequestIndex) != planned.end();
  if (!wanted || this->Cache.has(this->RequestIndex))
  {
    return std::string();
  }
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  bp::GridGeometry grid;
  bp::FieldSlice slice;
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  std::string requested = vectorsName(self);
  vtkSmartPointer<vtkImageData> resampled;
  if (bpvtk::FieldResampler::needed(input))
  {
    const std::string resampleError = this->resampleInput(self, input, resampled);
    if (!resampleError.empty())
    {
      return resampleError; // every process fails alike
    }
    input = resampled;
    requested = this->Resampler.arrayName();
  }
  // Only a dataset has point data to choose from (readSlice says what else came).
  vtkDataArray* vectors = resampled   ? resampled->GetPointData()->GetArray(requested.c_str())
    : vtkDataSet::SafeDownCast(input) ? self->GetInputArrayToProcess(0, inputVector, association)
                                      : nullptr;
  int extent[6];
  std::size_t nonFinite = 0;
  std::string maskProblem;
  std::string error = bpvtk::readSlice(
    input, vectors, association, grid, slice, extent, nonFinite, requested, &maskProblem);
  this->Resampled = resampled != nullptr;
  if (error.empty() && !maskProblem.empty() && !this->WarnedMask)
  {
    this->WarnedMask = true; // once per configuration, as below
    vtkWarningWithObjectMacro(self, << maskProblem);
  }
  if (error.empty() && nonFinite > 0 && !this->WarnedNonFinite)
  {
    // Once per configuration: an unsteady input would say it every frame.
    this->WarnedNonFinite = true;
    vtkWarningWithObjectMacro(
      self, << nonFinite << " of " << grid.pointCount() << " grid points ("
            << 100.0 * double(nonFinite) / double(grid.pointCount())
            << "%) have a NaN or Inf vector; they count as outside the flow's domain, and elements "
               "that reach them are released again.");
  }
  std::array<double, 3> offset = grid.origin;
  if (this->Layout.distributed())
  {
    // Every process reads in this pass: agree on the pieces (and fail together).
    error = this->Layout.share(error, grid, extent, offset);
    for (int a = 0; a < 3; ++a)
    {
      grid.firstIndex[a] = extent[2 * a] - this->Layout.WholeExtent[2 * a];
    }
  }
  if (!error.empty())
  {
    return error;
  }
  slice.time = this->Plan.unsteady() ? this->Plan.inputTimes()[this->RequestIndex] : 0.0;
  vtkInformation* data = input->GetInformation();
  if (this->Plan.unsteady() && data->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    const double delivered = data->Get(vtkDataObject::DATA_TIME_STEP());
    if (std::abs(delivered - slice.time) > this->Plan.epsilon())
    {
      vtkWarningWithObjectMacro(self,
        "Asked the input for time " << slice.time << " but it delivered time " << delivered
                                    << "; using it as time " << slice.time << ".");
    }
  }
  const std::string kept = this->keepTimeStep(grid, offset, slice);
  // Each process checks its own piece (its velocities, its grid): one
  // process's failure must be every process's before the next collective step.
  return this->Layout.distributed() ? this->Layout.agree(kept) : kept;
}

bpvtk::VectorsChoice vtkBoundParticleTracer::vtkInternals::vectorsChoice(
  vtkBoundParticleTracer* self)
{
  bpvtk::VectorsChoice choice;
  choice.name = vectorsName(self);
  vtkInformation* info = self->GetInputArrayInformation(0);
  choice.association = info && info->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? info->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  return choice;
}

std::string vtkBoundParticleTracer::vtkInternals::resampleInput(
  vtkBoundParticleTracer* self, vtkDataObject* input, vtkSmartPointer<vtkImageData>& piece)
{
  vtkNew<vtkImageData> whole;
  std::string warning;
  const int* dims = self->ResampleDimensions;
  const std::string error =
    this->Resampler.resample(input, vectorsChoice(self), { dims[0], dims[1], dims[2] },
      this->Layout.Controller, this->Steppers.runner(), whole, warning);
  if (!warning.empty() && !this->WarnedResample)
  {
    this->WarnedResample = true; // once per configuration, as the mask's
    vtkWarningWithObjectMacro(self, << warning);
  }
  if (error.empty())
  {
    piece = this->Layout.cutPiece(whole);
  }
  return error;
}

vtkDataArray* vtkBoundParticleTracer::vtkInternals::probeGrid(
  vtkBoundParticleTracer* self, vtkDataObject* data, vtkSmartPointer<vtkDataObject>& grid)
{
  vtkMultiProcessController* global = vtkMultiProcessController::GetGlobalController();
  vtkMultiProcessController* controller =
    global && global->GetNumberOfProcesses() > 1 ? global : nullptr;
  vtkNew<vtkImageData> image;
  std::string warning;
  const int* dims = self->ResampleDimensions;
  if (!this->Resampler
         .resample(data, vectorsChoice(self), { dims[0], dims[1], dims[2] }, controller,
           this->Steppers.runner(), image, warning)
         .empty())
  {
    return nullptr; // the update says why
  }
  grid = image;
  return image->GetPointData()->GetArray(this->Resampler.arrayName().c_str());
}

std::string vtkBoundParticleTracer::vtkInternals::keepTimeStep(
  bp::GridGeometry grid, const std::array<double, 3>& offset, const bp::FieldSlice& slice)
{
  // In world coordinates first, so how far from the origin the data lies counts too.
  const std::string worldError = grid.validate();
  if (!worldError.empty())
  {
    return "Unusable input: " + worldError + ".";
  }
  // The engine works in coordinates relative to the grid's first point (the
  // whole grid's, in parallel), so float positions keep their precision far
  // from the world origin.
  grid.translate(offset);
  if (this->Cache.size() > 0)
  {
    const double tolerance = 1e-9 * std::max(1.0, this->Grid.diagonal());
    bool same = grid.sameAs(this->Grid, tolerance);
    for (int a = 0; a < 3; ++a)
    {
      same = same && std::abs(offset[a] - this->Offset[a]) <= tolerance;
    }
    if (!same)
    {
      return "The input's time steps do not share one grid; every time step must have the same "
             "dimensions and point coordinates.";
    }
  }
  this->Offset = offset;
  this->Grid = grid;
  const std::string fieldError = bp::VectorField(grid, slice).validate();
  if (!fieldError.empty())
  {
    return "Unusable input: " + fieldError + ".";
  }
  this->Cache.insert(
    this->RequestIndex, slice, this->Plan.needed(this->steppingFrom(), this->target()));
  this->ReadThisUpdate = true;
  return std::string();
}

bp::FieldFacts vtkBoundParticleTracer::vtkInternals::fieldFacts(const bp::VectorField& field)
{
  bp::FieldFacts facts;
  // The whole field's, also in parallel where this process holds a piece.
  facts.bounds = this->Layout.domainBounds(this->Grid);
  facts.offset = this->Offset;
  facts.dims = this->Grid.dims;
  facts.cellLength = this->Layout.cellLength(this->Grid);
  facts.maxSpeed = field.maxSpeed();
  if (this->Layout.distributed())
  {
    facts.maxSpeed = this->Layout.globalMax(facts.maxSpeed);
  }
  const std::vector<double>& times = this->Plan.outputTimes();
  facts.timeSpan = times.back() - times.front();
  return facts;
}

std::string vtkBoundParticleTracer::vtkInternals::elementTemplate(
  vtkBoundParticleTracer* self, vtkInformationVector** inputVector, bp::ElementTemplate& shape)
{
  shape = bp::builtinTemplate(bp::BuiltinShape(self->ElementShape));
  if (self->GetNumberOfInputConnections(1) == 0)
  {
    return std::string();
  }
  std::string error;
  vtkPolyData* mesh = bpvtk::templateMesh(vtkDataObject::GetData(inputVector[1], 0), error);
  return error.empty()
    ? bpvtk::templateFromPolyData(mesh, bp::MeshSprings(self->TemplateSprings), shape)
    : error;
}

std::string vtkBoundParticleTracer::vtkInternals::readSeeds(
  vtkBoundParticleTracer* self, vtkInformationVector** inputVector, std::vector<double>& xyz) const
{
  xyz.clear();
  if (self->GetNumberOfInputConnections(2) == 0)
  {
    return std::string();
  }
  std::string error = bpvtk::appendSeedPoints(vtkDataObject::GetData(inputVector[2], 0), xyz);
  if (!this->Layout.distributed())
  {
    return error;
  }
  // Collective from here: every process takes part whatever it read.
  error = this->Layout.agree(error);
  if (!error.empty())
  {
    return error;
  }
  if (this->Layout.shareFirst(xyz) > 0)
  {
    vtkWarningWithObjectMacro(self,
      "The Seed Source gives a different number of points on different processes; every "
      "process releases from the first process's "
        << xyz.size() / 3 << ".");
  }
  return std::string();
}

vtkBoundParticlePass vtkBoundParticleTracer::vtkInternals::replay(
  vtkBoundParticleTracer* self, vtkInformationVector** inputVector)
{
  const std::vector<int> ids = this->Plan.needed(this->Plan.startTime(), this->target());
  const int missing = this->Cache.firstMissing(ids);
  if (missing >= 0)
  {
    return Pass::need(missing);
  }
  if (this->Layout.distributed() && self->Linking != NO_LINKING)
  {
    return Pass::fail("Super sets (Linking) run in one process; in parallel (" +
      std::to_string(this->Layout.Pieces) + " processes) set Linking to None.");
  }
  vtkBoundParticleSeeds seeds;
  const std::string seedError = this->readSeeds(self, inputVector, seeds.xyz);
  if (!seedError.empty())
  {
    return Pass::fail(seedError);
  }
  seeds.total = seeds.xyz.size() / 3;
  const bool seedSource = self->GetNumberOfInputConnections(2) > 0;
  if (seedSource && seeds.xyz.empty())
  {
    vtkWarningWithObjectMacro(
      self, "The Seed Source has no points; elements are released in the emitter box.");
  }
  if (seedSource && self->SeedType)
  {
    // A connected input is the more deliberate choice, and kept its meaning
    // in scripts and state files made before there were Seed Types.
    vtkWarningWithObjectMacro(self,
      "A Seed Source is connected: its points are the release positions, and Seed Type "
        << self->SeedType->GetSeedTypeName()
        << " is not used. Disconnect it (SeedSource = None) to release from the "
        << self->SeedType->GetSeedTypeName() << ".");
  }
  const bp::VectorField field = this->Cache.field(this->Grid, ids);
  if (!seedSource)
  {
    this->seedTypePoints(self, field, seeds);
  }
  const bp::FieldFacts facts = this->fieldFacts(field);
  bp::TraceSettings settings = self->Settings();
  settings.seeded = !seeds.xyz.empty() && self->Linking == NO_LINKING;
  if (!seeds.xyz.empty() && self->Linking != NO_LINKING)
  {
    vtkWarningWithObjectMacro(self,
      "Linking places each super set as one structure in the emitter box: the "
        << seeds.name << " is not used. Set Linking to None to release from the seeds.");
    seeds.xyz.clear();
  }
  const bp::Resolution resolved = bp::resolveSettings(settings, facts);
  for (const std::string& warning : resolved.warnings)
  {
    vtkWarningWithObjectMacro(self, << warning);
  }
  if (!resolved.error.empty())
  {
    return Pass::fail(resolved.error);
  }
  this->ResolvedDt = resolved.dt;
  this->ResolvedElementSize = resolved.elementSize;
  if (this->Layout.distributed())
  {
    // Enough ghost layers for an element and a step at twice the start's
    // largest speed (an unsteady flow may speed up); if the pieces in hand
    // have fewer, ask for them again with more. Every process computes the
    // same number from the same global values.
    const int needed = bp::ghostCellsNeeded(
      resolved.elementSize, 2.0 * facts.maxSpeed, resolved.dt, this->Layout.DomainSmallestCell);
    if (needed > this->Layout.GhostCells)
    {
      this->Layout.GhostCells = needed;
      this->Cache.clear();
      return Pass::need(ids.front());
    }
  }
  const Pass configured = this->configureStepper(self, inputVector, field, resolved, seeds);
  if (configured.kind == Pass::Done)
  {
    this->startTrace();
  }
  return configured;
}

void vtkBoundParticleTracer::vtkInternals::seedTypePoints(
  vtkBoundParticleTracer* self, const bp::VectorField& field, vtkBoundParticleSeeds& seeds) const
{
  vtkBoundParticleSeedType* type = self->SeedType;
  if (!type)
  {
    return; // the emitter box
  }
  // The whole field's flat axes, as every process sees them.
  const bp::Domain& domain = this->Layout.distributed() ? this->Layout.Domain : field.domain();
  bool flat[3];
  for (int a = 0; a < 3; ++a)
  {
    flat[a] = domain.degenerate[a];
  }
  seeds.name = type->GetSeedTypeName();
  seeds.total = std::size_t(std::max<vtkIdType>(type->GetNumberOfSeedPoints(), 0));
  seeds.advice = std::string("Raise the ") + seeds.name + "'s " + type->GetPointCountName() +
    ", or use fewer elements.";
  seeds.xyz.clear();
  // Only what releases can take: a Resolution of a billion costs no memory.
  type->AppendPoints(std::uint32_t(self->Seed), flat, vtkIdType(bp::MaxSeedPoints), seeds.xyz);
  // On a 2D slice the seeds lie in its plane, as the emitter box does (it is
  // clamped to the field's bounds): elsewhere no element would be released.
  for (std::size_t i = 0; i < seeds.xyz.size(); ++i)
  {
    const std::size_t a = i % 3;
    if (flat[a])
    {
      seeds.xyz[i] = double(domain.lower[a]) + this->Offset[a];
    }
  }
}

std::string vtkBoundParticleTracer::vtkInternals::seedPoints(vtkBoundParticleTracer* self,
  const vtkBoundParticleSeeds& seeds, const bp::VectorField& field, bp::Parameters& p) const
{
  const std::vector<double>& xyz = seeds.xyz;
  const std::string& name = seeds.name;
  const std::size_t count = seeds.total;
  if (count > bp::MaxSeedPoints)
  {
    vtkWarningWithObjectMacro(self,
      "The " << name << " has " << count << " points; releases take the first " << bp::MaxSeedPoints
             << ".");
  }
  // Releases take only the points in the field: one outside (or one too far
  // to hold in the engine's floats) would place an element where no flow is.
  // Every process decides alike, from the whole field's bounds.
  const bp::Domain& domain = this->Layout.distributed() ? this->Layout.Domain : field.domain();
  std::size_t outside = 0, noFlow = 0, nonFinite = 0, atBoundary = 0, still = 0;
  // Seeds where the flow barely moves at the start (below 1% of its top
  // speed): their elements sit where they were released.
  const double stillSpeed = 0.01 * field.maxSpeed();
  const double start = this->Plan.startTime();
  p.seedPoints.clear();
  for (std::size_t i = 0; i < std::min(xyz.size() / 3, bp::MaxSeedPoints); ++i)
  {
    float x[3];
    bool finite = true;
    for (int a = 0; a < 3; ++a)
    {
      const double local = xyz[3 * i + std::size_t(a)] - this->Offset[a];
      finite = finite && std::isfinite(local) && std::abs(local) < 1e30;
      x[a] = finite ? float(local) : 0.0f;
    }
    if (!finite)
    {
      ++nonFinite;
      continue;
    }
    if (!domain.contains(x))
    {
      ++outside;
      continue;
    }
    // Releases pass over points in cells outside the flow's domain (masked or
    // NaN) at their time; count those at the start (one process sees them all).
    noFlow += !this->Layout.distributed() && field.outsideCellAt(x, 0.0f) ? 1 : 0;
    if (!this->Layout.distributed())
    {
      float v[3];
      field.sample(x, start, v);
      still +=
        std::sqrt(double(v[0]) * v[0] + double(v[1]) * v[1] + double(v[2]) * v[2]) < stillSpeed ? 1
                                                                                                : 0;
    }
    bool nearBoundary = false;
    for (int a = 0; a < 3; ++a)
    {
      const float radius = 0.5f * p.elementSize;
      nearBoundary = nearBoundary ||
        (!domain.degenerate[a] &&
          (x[a] - domain.lower[a] < radius || domain.upper[a] - x[a] < radius));
    }
    atBoundary += nearBoundary ? 1 : 0;
    p.seedPoints.insert(p.seedPoints.end(), x, x + 3);
  }
  // Where releases land: the seeds' box (the GPU display's colour ranges of
  // Layer and Radius are taken over the emitter box).
  for (std::size_t i = 0; i < p.seedPoints.size(); ++i)
  {
    const int a = int(i % 3);
    const float x = p.seedPoints[i];
    p.emitterMin[a] = i < 3 ? x : std::min(p.emitterMin[a], x);
    p.emitterMax[a] = i < 3 ? x : std::max(p.emitterMax[a], x);
  }
  const std::size_t used = std::min(count, bp::MaxSeedPoints);
  if (p.seedPoints.empty() || noFlow == p.seedPoints.size() / 3)
  {
    std::ostringstream err;
    err << "None of the " << name << "'s " << used << " points lies in the flow (" << outside
        << " outside the field, " << noFlow << " in cells outside the flow's domain";
    if (nonFinite > 0)
    {
      err << ", " << nonFinite << " not finite";
    }
    err << "): no element can be released. Move the seeds into the field.";
    return err.str();
  }
  if (outside + nonFinite > 0)
  {
    vtkWarningWithObjectMacro(
      self, << outside + nonFinite << " of the " << name << "'s " << used
            << " points lie outside the field" << (nonFinite ? " or are not finite" : "")
            << "; releases take only the other " << p.seedPoints.size() / 3 << ".");
  }
  if (atBoundary > 0 && p.resetWhen == bp::ResetWhen::AnyParticleLeaves)
  {
    vtkWarningWithObjectMacro(
      self, << atBoundary << " of the " << name << "'s points lie within half an element of the "
            << "field's boundary: with Reset When = Any Particle Leaves, elements released there "
            << "leave at once and are released again every step. Move the seeds inward, or reset "
            << "when the centre leaves.");
  }
  const std::size_t kept = p.seedPoints.size() / 3;
  if (still > noFlow)
  {
    vtkWarningWithObjectMacro(
      self, << still - noFlow << " of the " << name << "'s " << kept
            << " points in the flow lie where it is slower than 1% of its top speed at the start: "
               "elements released there barely move. Move the seeds into faster flow.");
  }
  if (p.numberOfElements > 2 * kept)
  {
    vtkWarningWithObjectMacro(
      self, << p.numberOfElements << " elements share the " << name << "'s " << kept
            << " points: about " << (p.numberOfElements + kept - 1) / kept
            << " start at each point, on top of one another. " << seeds.advice);
  }
  if (noFlow > 0)
  {
    vtkWarningWithObjectMacro(
      self, << noFlow << " of the " << name << "'s points lie in cells outside the flow's domain "
            << "(vtkValidPointMask 0 or a non-finite vector) at the start; releases pass over them "
            << "to the next point in the flow.");
  }
  return std::string();
}

std::string vtkBoundParticleTracer::vtkInternals::checkConfiguration(vtkBoundParticleTracer* self,
  vtkInformationVector** inputVector, const bp::VectorField& field,
  const vtkBoundParticleSeeds& seeds, bp::ElementTemplate& shape, bp::Parameters& p)
{
  const std::string templateError = this->elementTemplate(self, inputVector, shape);
  if (!templateError.empty())
  {
    return templateError;
  }
  p.trailStart = this->Plan.startTime(); // trail poses on the schedule's own steps
  if (!seeds.xyz.empty())
  {
    const std::string seedError = this->seedPoints(self, seeds, field, p);
    if (!seedError.empty())
    {
      return seedError;
    }
  }
  const std::vector<double>& times = this->Plan.outputTimes();
  if (!times.empty() && (p.releaseStop < times.front() || p.releaseStart > times.back()))
  {
    vtkWarningWithObjectMacro(self,
      "No element is released: the Release Window ["
        << p.releaseStart << ", " << p.releaseStop << "] lies outside the offered times ["
        << times.front() << ", " << times.back() << "].");
  }
  else if (times.size() > 1 && p.releaseStart == times.back())
  {
    // A step releases what is due in [t, t + h): the last offered time ends
    // the last step, so a window that starts there releases in none.
    vtkWarningWithObjectMacro(self,
      "No element is shown released: the Release Window starts at the last offered time ("
        << times.back() << "), after the last step. Start it earlier.");
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
    vtkWarningWithObjectMacro(self,
      "Relaxation Factor " << p.relaxation
                           << " would make Jacobi diverge on this element (a particle's springs "
                           << "add up to " << 1.0f / stable << " shares); using " << stable
                           << ", the largest stable factor. Averaged Jacobi needs no factor.");
    p.relaxation = stable;
  }
  const std::string fallback = this->Steppers.fallBackIfTooLarge(shape, p);
  if (!fallback.empty())
  {
    vtkErrorWithObjectMacro(self, << fallback);
  }
  const std::string error = this->stepper().configure(shape, p);
  return error.empty() ? error : error + ".";
}

vtkBoundParticlePass vtkBoundParticleTracer::vtkInternals::configureStepper(
  vtkBoundParticleTracer* self, vtkInformationVector** inputVector, const bp::VectorField& field,
  const bp::Resolution& resolved, const vtkBoundParticleSeeds& seeds)
{
  bp::ElementTemplate shape;
  bp::Parameters p = resolved.parameters;
  std::string error = this->checkConfiguration(self, inputVector, field, seeds, shape, p);
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
  this->Parameters = p;
  this->ParticlesPerElement = shape.particleCount();
  if (this->Steppers.queue())
  {
    // The display's output has no particles: it carries the ranges they span.
    this->RangeFacts = bp::rangeFactsOf(field, p, resolved.dt, self->ColoringAxis, this->Offset,
      this->Grid.bounds(), shape.particleCount());
  }
  return Pass();
}

void vtkBoundParticleTracer::vtkInternals::startTrace()
{
  this->Storage.reset(); // the element count or shape may have changed
  this->Schedule.reset(new bp::StepSchedule(this->Plan.startTime(), this->ResolvedDt,
    this->Plan.unsteady() ? this->Plan.inputTimes() : std::vector<double>()));
  bp::TraceCursor& cursor = this->stepper().cursor;
  cursor.committed = this->Plan.startTime();
  cursor.valid = true;
  cursor.configuration = this->Configuration;
  cursor.producer = this->ProducerId;
  cursor.showsPartialStep = false;
  this->ReplayPending = false;
}

vtkBoundParticlePass vtkBoundParticleTracer::vtkInternals::stepToTarget(
  vtkBoundParticleTracer* self)
{
  bp::Stepper& stepper = this->stepper();
  double& committed = stepper.cursor.committed;
  const double target = this->target();
  const std::string tooMuch = this->Plan.checkWork(committed, target, this->Schedule->dt());
  if (!tooMuch.empty())
  {
    return Pass::fail(tooMuch);
  }
  bool aborted = false;
  auto keepGoing = [&](double t)
  {
    ++this->StepsInLastUpdate;
    this->ProgressAt = t;
    self->UpdateProgress(this->progress());
    // In parallel every process must take every step (each exchanges
    // elements with the others), so one process alone cannot stop.
    aborted = !this->Layout.distributed() && self->CheckAbort();
    return !aborted;
  };
  // One data interval at a time.
  while (true)
  {
    const std::vector<int> ids = this->Plan.needed(committed, target);
    const int missing = this->Cache.firstMissing(ids);
    if (missing >= 0)
    {
      // Drop what no later step needs before asking for the next time step.
      this->Cache.dropBefore(ids.front());
      return Pass::need(missing);
    }
    const double intervalEnd = ids.size() == 2 ? this->Plan.inputTimes()[ids[1]] : target;
    const double limit = std::min(target, intervalEnd);
    const double before = committed;
    const std::string fieldError = stepper.setField(this->Cache.field(this->Grid, ids));
    if (!fieldError.empty())
    {
      return Pass::fail(fieldError + ".");
    }
    committed = bp::advance(
      *this->Schedule, committed, limit, [&](double t, double h) { stepper.step(t, h); },
      keepGoing);
    if (aborted)
    {
      return { Pass::Aborted, -1, std::string() };
    }
    if (committed < intervalEnd && intervalEnd - committed <= this->Schedule->epsilon())
    {
      // Input times closer than the schedule resolves (epsilon): no step
      // lands inside such an interval, so the trace stands at its end.
      committed = intervalEnd;
    }
    if (limit >= target || committed < intervalEnd - this->Schedule->epsilon())
    {
      return Pass();
    }
    if (committed == before)
    {
      // Never spin: the schedule lands on every data time step, so this is a bug.
      return Pass::fail("Time stepping made no progress at t = " + std::to_string(before) +
        "; please report this with the input's time steps.");
    }
  }
}

vtkBoundParticlePass vtkBoundParticleTracer::vtkInternals::readAhead()
{
  bp::Stepper& stepper = this->stepper();
  if (!stepper.readsAhead())
  {
    return Pass();
  }
  // Read the time step after this interval ahead of need, so the display can
  // upload it a slab per frame before a step crosses into it. Only in an
  // update that stays in its interval and read nothing: a frame that crosses
  // a time step has had its share.
  const int upcoming = this->Plan.readAheadIndex(this->target());
  const bool quietFrame = !this->ReadThisUpdate &&
    this->IntervalAtStart == this->Plan.intervalAt(this->target(), false).front();
  if (upcoming >= 0 && !this->Cache.has(upcoming) && quietFrame)
  {
    return Pass::need(upcoming);
  }
  stepper.offerUpcoming(
    upcoming >= 0 && this->Cache.has(upcoming) ? this->Cache.at(upcoming) : bp::FieldSlice());
  return Pass();
}

vtkBoundParticlePass vtkBoundParticleTracer::vtkInternals::show(
  vtkBoundParticleTracer* self, vtkPolyData* output)
{
  // The output at the target: the committed state, finished with a shorter
  // step that the next update takes back, so the trace stays on the step
  // boundaries.
  bp::Stepper& stepper = this->stepper();
  const double target = this->target();
  const bp::VectorField field = this->Cache.field(this->Grid, this->Plan.intervalAt(target, false));
  const std::string fieldError = stepper.setField(field);
  if (!fieldError.empty())
  {
    return Pass::fail(fieldError + ".");
  }
  const double committed = stepper.cursor.committed;
  if (target - committed > this->Schedule->epsilon())
  {
    stepper.save();
    stepper.step(committed, target - committed);
    stepper.cursor.showsPartialStep = true;
    ++this->StepsInLastUpdate;
  }
  if (this->Layout.distributed())
  {
    if (this->StepsInLastUpdate > 0 || this->LastUpdateReplayed)
    {
      // Collective, so only in an update that every process runs in step
      // with the others: one that took steps (each exchanges elements) or
      // replayed (each shares the field's largest speed).
      const bp::Engine* held = stepper.particles();
      this->ElementsPerProcess = this->Layout.gather(held ? (long long)held->elementCount() : 0);
    }
    this->Migrated += this->Steppers.distributed().takeMigrated();
    const std::string error = this->Steppers.distributed().takeExchangeError();
    if (!error.empty())
    {
      vtkWarningWithObjectMacro(self, "An element exchange failed: " << error);
    }
  }
  const bp::Engine* particles = stepper.particles();
  self->UpdateProgress(1.0);
  if (particles)
  {
    bpvtk::OutputFrame frame;
    frame.time = target;
    frame.offset = this->Offset;
    frame.domain = this->Layout.domainBounds(this->Grid);
    const auto local = this->Grid.bounds();
    for (int a = 0; a < 3; ++a)
    {
      frame.reach = std::max(frame.reach, std::abs(this->Offset[a]) + std::abs(local[2 * a + 1]));
    }
    frame.cellLength = this->Grid.cellLength();
    frame.coloringAxis = self->ColoringAxis;
    for (const bp::OutputArray& row : bp::outputArrays())
    {
      frame.wanted[std::size_t(row.id)] = self->GetOutputArrayStatus(row.name) != 0 &&
        (row.id != bp::OutputArrayId::Vorticity || self->ComputeVorticity);
    }
    bpvtk::fillParticleOutput(
      output, *particles, field, frame, this->Storage, this->Steppers.runner());
  }
  else
  {
    this->handToDisplay(self, output);
  }
  this->addSettingsFieldData(output);
  return Pass();
}

void vtkBoundParticleTracer::vtkInternals::handToDisplay(
  vtkBoundParticleTracer* self, vtkPolyData* output)
{
  bp::WorkQueue& queue = *this->Steppers.queue();
  bp::DrawSettings& d = queue.draw;
  d.time = this->target();
  d.offset = this->Offset;
  const auto bounds = this->Grid.bounds();
  for (int a = 0; a < 3; ++a)
  {
    d.bounds[2 * a] = bounds[2 * a] + this->Offset[a];
    d.bounds[2 * a + 1] = bounds[2 * a + 1] + this->Offset[a];
  }
  d.coloringAxis = self->ColoringAxis;
  const int u = (self->ColoringAxis + 1) % 3, v = (self->ColoringAxis + 2) % 3;
  d.radialCenter = { 0.5 * (bounds[2 * u] + bounds[2 * u + 1]),
    0.5 * (bounds[2 * v] + bounds[2 * v + 1]) };
  ++d.serial;
  // Two points spanning the field (for the camera and the axes grid).
  bpvtk::fillRangeOutput(output, this->RangeFacts, d.bounds);
  vtkNew<vtkIntArray> id;
  id->SetName("BoundParticlesWorkQueue");
  id->InsertNextValue(queue.id());
  output->GetFieldData()->AddArray(id);
}

void vtkBoundParticleTracer::vtkInternals::addSettingsFieldData(vtkPolyData* output)
{
  // What the automatic settings came to, for the Information panel and scripts.
  bpvtk::addFieldValue(output, "TimeStep", this->ResolvedDt);
  bpvtk::addFieldValue(output, "ElementSize", this->ResolvedElementSize);
  bpvtk::addFieldValue(output, "SimulationTime", this->target());
  if (this->Parameters.trailLength > 0)
  {
    // The age at which a trail pose has faded out on the Bound Particles
    // display: one interval past the oldest pose (as its GPU mapper fades).
    bpvtk::addFieldValue(
      output, "TrailFadeSpan", (this->Parameters.trailLength + 1) * this->Parameters.trailInterval);
  }
  if (this->Resampled)
  {
    // The grid a mesh was resampled onto (TracerResample.h).
    const bp::ResampleGrid& g = this->Resampler.grid();
    vtkNew<vtkIntArray> dims;
    dims->SetName("ResampledDimensions");
    vtkNew<vtkDoubleArray> spacing;
    spacing->SetName("ResampledSpacing");
    for (int a = 0; a < 3; ++a)
    {
      dims->InsertNextValue(g.dims[a]);
      spacing->InsertNextValue(g.spacing[a]);
    }
    output->GetFieldData()->AddArray(dims);
    output->GetFieldData()->AddArray(spacing);
  }
  if (this->Layout.distributed())
  {
    // This process's share: ghost layers read, elements sent to other pieces;
    // and the balance: every process's element count (the same on each).
    bpvtk::addFieldValue(output, "GhostLayers", this->Layout.GhostCells);
    bpvtk::addFieldValue(output, "MigratedElements", double(this->Migrated));
    vtkNew<vtkIdTypeArray> perProcess;
    perProcess->SetName("ElementsPerProcess");
    for (long long c : this->ElementsPerProcess)
    {
      perProcess->InsertNextValue(vtkIdType(c));
    }
    output->GetFieldData()->AddArray(perProcess);
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->target());
}

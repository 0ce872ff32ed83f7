// SPDX-License-Identifier: BSD-3-Clause
// The tracer's internals, reading a time step: the input a pass brought
// (resampled first when it is a mesh), checked against the held ones and put
// in the field cache. See vtkBoundParticleTracerInternals.h.
#include "vtkBoundParticleTracerInternals.h"

#include "TracerInput.h"
#include "TracerReleaseWeights.h"
#include "VectorField.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkPointData.h"

#include <algorithm>
#include <cmath>

namespace
{
/**
 * A source shared with another tracer that asked for more ghost layers gave
 * its piece with those (the executive does not run it again for fewer): cut
 * to this process's block and layers, so the step is read on the extent every
 * other step comes on, with `vectors` found again in the cut. Null, and
 * `input` and `vectors` as they were, where the piece is already that.
 */
vtkSmartPointer<vtkDataSet> cropToPiece(
  const bpvtk::PieceLayout& layout, int association, vtkDataObject*& input, vtkDataArray*& vectors)
{
  vtkSmartPointer<vtkDataSet> cropped = layout.cropToPiece(vtkDataSet::SafeDownCast(input));
  if (cropped)
  {
    vtkFieldData* arrays = association == vtkDataObject::FIELD_ASSOCIATION_CELLS
      ? static_cast<vtkFieldData*>(cropped->GetCellData())
      : static_cast<vtkFieldData*>(cropped->GetPointData());
    vectors = vectors && vectors->GetName() ? arrays->GetArray(vectors->GetName()) : nullptr;
    input = cropped;
  }
  return cropped;
}
} // namespace

bool vtkBoundParticleTracerInternals::wantsTimeStep()
{
  // A first pass with every time step in hand asked for whatever upstream
  // held: take it only if the work needs it.
  const std::vector<int> planned = this->Plan.needed(this->steppingFrom(), this->target());
  // In situ the present step is taken whenever it comes: it will not come again.
  const bool present =
    this->Plan.streaming() && this->Held.requestIndex == int(this->Plan.inputTimes().size()) - 1;
  const bool wanted = this->Update.continuing || present ||
    std::find(planned.begin(), planned.end(), this->Held.requestIndex) != planned.end();
  return wanted && !this->Held.cache.has(this->Held.requestIndex);
}

std::string vtkBoundParticleTracerInternals::takeTimeStep(
  const Config& config, const bpvtk::TracerInputStep& step)
{
  if (!this->wantsTimeStep())
  {
    return std::string();
  }
  vtkDataObject* input = step.data;
  if (step.vectorsFromCells.empty())
  {
    this->noteVectors(config, input);
  }
  else if (this->Said.first(bpvtk::Topic::CellVectors))
  {
    // Instead of the choice's note, which would list the cell array as another.
    // Once per configuration, as the mask's; in situ at the first step that
    // holds only the cell array.
    vtkWarningWithObjectMacro(this->Owner, << step.vectorsFromCells);
  }
  vtkDataArray* vectors = step.vectors;
  int association = step.association;
  std::string requested = config.vectors.name;
  vtkSmartPointer<vtkImageData> resampled;
  if (bpvtk::FieldResampler::needed(input))
  {
    const std::string resampleError = this->resampleInput(config, input, resampled);
    if (!resampleError.empty())
    {
      return resampleError; // every process fails alike
    }
    input = resampled;
    requested = this->Held.resampler.arrayName();
    vectors = resampled->GetPointData()->GetArray(requested.c_str());
    association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  }
  vtkSmartPointer<vtkDataSet> cropped;
  if (!resampled && !this->Plan.streaming() && this->Layout.distributed())
  {
    cropped = cropToPiece(this->Layout, association, input, vectors);
  }
  vtkSmartPointer<vtkImageData> gathered;
  if (!resampled && this->Plan.streaming() && this->Layout.distributed() &&
    vtkImageData::SafeDownCast(input) &&
    config.vectors.association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    // In situ a process holds the piece its simulation gave it: its block
    // and ghost layers are gathered from every process's piece.
    std::string gatherError;
    gathered = this->Layout.gatherPiece(vtkImageData::SafeDownCast(input), gatherError);
    if (!gatherError.empty())
    {
      return gatherError; // every process fails alike
    }
    input = gathered;
    // By name: a process whose piece held no points (a bare image) found no
    // array there, but its gathered block has the others'.
    const std::string name = vectors && vectors->GetName() ? vectors->GetName() : requested;
    vectors = name.empty() ? vectors : gathered->GetPointData()->GetArray(name.c_str());
  }
  bp::GridGeometry grid;
  bp::FieldSlice slice;
  int extent[6];
  std::size_t nonFinite = 0;
  std::string maskProblem;
  std::string error = bpvtk::readSlice(
    input, vectors, association, grid, slice, extent, nonFinite, requested, &maskProblem);
  this->Held.resampled = resampled != nullptr;
  if (error.empty())
  {
    this->warnOfSlice(maskProblem, nonFinite, grid.pointCount());
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
  this->keepInPlane(grid, slice);
  if (!config.releaseWeights.empty())
  {
    this->takeReleaseWeights(config, input, slice);
  }
  slice.time = this->sliceTime(input);
  // Backward: the trace samples the data's mirror in time, its flow reversed.
  slice = bp::traceSlice(this->Plan.direction(), slice);
  grid.periodic = config.periodic;
  const std::string kept = this->keepTimeStep(grid, offset, slice);
  // Each process checks its own piece (its velocities, its grid): one
  // process's failure must be every process's before the next collective step.
  return this->Layout.distributed() ? this->Layout.agree(kept) : kept;
}

void vtkBoundParticleTracerInternals::noteVectors(const Config& config, vtkDataObject* input)
{
  // Said once for each choice among an input's arrays, by one process.
  // The Vectors default that preferred an array whose units fit says so.
  const std::string note = bpvtk::describeVectorsChoice(
    input, config.vectors.name, config.vectors.association, config.vectorsUnitsReason);
  if (note != this->SaidVectors && (!this->Layout.distributed() || this->Layout.Piece == 0))
  {
    if (!note.empty())
    {
      vtkOutputWindowDisplayText(note.c_str());
    }
  }
  this->SaidVectors = note;
}

void vtkBoundParticleTracerInternals::keepInPlane(
  const bp::GridGeometry& grid, bp::FieldSlice& slice)
{
  // The whole field's flat axes (a process's block of an image may be thin);
  // resolveSettings drops Gravity's component along them (fieldFacts).
  const std::array<int, 3> dims = this->Layout.wholeDims(grid);
  std::array<bool, 3> flat;
  bool any = false;
  for (int a = 0; a < 3; ++a)
  {
    flat[a] = dims[a] == 1;
    any = any || flat[a];
  }
  if (!any || !slice.velocity)
  {
    return;
  }
  // Copied only where a component crosses the plane.
  const std::vector<float>& given = *slice.velocity;
  bool crosses = false;
  for (std::size_t i = 0; i + 2 < given.size() && !crosses; i += 3)
  {
    for (int a = 0; a < 3; ++a)
    {
      crosses = crosses || (flat[a] && given[i + std::size_t(a)] != 0.0f);
    }
  }
  double dropped = 0.0;
  float inPlane = 0.0f;
  if (crosses)
  {
    auto velocity = std::make_shared<std::vector<float>>(given);
    dropped = bp::dropFlatComponents(*velocity, flat, inPlane);
    slice.velocity = velocity;
  }
  if (this->Layout.distributed())
  {
    // Collective: every process reads in this pass.
    dropped = this->Layout.globalMax(dropped);
    inPlane = float(this->Layout.globalMax(inPlane));
  }
  if (dropped > 0.0 && this->Said.first(bpvtk::Topic::OutOfPlane)) // once, as the mask's
  {
    std::string axes;
    for (int a = 0; a < 3; ++a)
    {
      axes += flat[a] ? std::string(axes.empty() ? "" : " and ") + "XYZ"[a] : "";
    }
    vtkWarningWithObjectMacro(this->Owner,
      "The field is flat along " << axes << " (one point) but its vectors cross its plane (up to "
                                 << dropped << ", against a top speed in the plane of " << inPlane
                                 << "): elements stay in the plane, the crossing component is "
                                    "not traced.");
  }
}

void vtkBoundParticleTracerInternals::takeReleaseWeights(
  const Config& config, vtkDataObject* input, bp::FieldSlice& slice)
{
  // Collective in a distributed run, as every process reads in this pass.
  // A resampled mesh's weights are the grid's point array, whichever
  // association the mesh's had (FieldResampler::setReleaseWeights).
  const int association = this->Held.resampled ? int(vtkDataObject::FIELD_ASSOCIATION_POINTS)
                                               : config.releaseWeightsAssociation;
  const std::string warning = bpvtk::readReleaseWeights(input, config.releaseWeights, association,
    this->Layout.distributed() ? this->Layout.Controller : nullptr, slice);
  if (!warning.empty() && this->Said.first(bpvtk::Topic::Weights)) // once, as the mask's
  {
    vtkWarningWithObjectMacro(this->Owner, << warning);
  }
}

void vtkBoundParticleTracerInternals::warnOfSlice(
  const std::string& maskProblem, std::size_t nonFinite, std::size_t points)
{
  if (!maskProblem.empty() && this->Said.first(bpvtk::Topic::Mask)) // once, as below
  {
    vtkWarningWithObjectMacro(this->Owner, << maskProblem);
  }
  if (nonFinite > 0 && this->Said.first(bpvtk::Topic::NonFinite))
  {
    // Once per configuration: an unsteady input would say it every frame.
    vtkWarningWithObjectMacro(this->Owner,
      << nonFinite << " of " << points << " grid points ("
      << 100.0 * double(nonFinite) / double(points)
      << "%) have a NaN or Inf vector; they count as outside the flow's domain, and elements "
         "that reach them are released again.");
  }
}

double vtkBoundParticleTracerInternals::sliceTime(vtkDataObject* input)
{
  // In situ the first step is shown steady but is the start of the time line.
  const double time = this->Plan.unsteady() || this->Plan.streaming()
    ? this->Plan.dataTimeOf(this->Held.requestIndex)
    : 0.0;
  vtkInformation* data = input->GetInformation();
  if (this->Plan.unsteady() && data->Has(vtkDataObject::DATA_TIME_STEP()))
  {
    const double delivered = data->Get(vtkDataObject::DATA_TIME_STEP());
    if (std::abs(delivered - time) > this->Plan.epsilon())
    {
      vtkWarningWithObjectMacro(this->Owner,
        "Asked the input for time " << time << " but it delivered time " << delivered
                                    << "; using it as time " << time << ".");
    }
  }
  return time;
}

std::string vtkBoundParticleTracerInternals::resampleInput(
  const Config& config, vtkDataObject* input, vtkSmartPointer<vtkImageData>& piece)
{
  vtkNew<vtkImageData> whole;
  std::string warning;
  this->Held.resampler.setReleaseWeights(config.releaseWeights, config.releaseWeightsAssociation);
  if (this->Held.cache.size() == 0)
  {
    this->Held.resampler.forgetGrid(); // no time step holds the last one
  }
  const std::string error = this->Held.resampler.resample(input, config.vectors,
    config.resampleDimensions, this->Layout.Controller, this->Steppers.runner(), whole, warning);
  if (!warning.empty() && this->Said.first(bpvtk::Topic::Resample, warning))
  {
    // Once per configuration, as the mask's, and again only when it says
    // something new (a later time step's mesh beyond the grid).
    vtkWarningWithObjectMacro(this->Owner, << warning);
  }
  if (error.empty())
  {
    piece = this->Layout.cutPiece(whole);
  }
  return error;
}

vtkDataArray* vtkBoundParticleTracerInternals::probeGrid(
  const Config& config, vtkDataObject* data, vtkSmartPointer<vtkDataObject>& grid)
{
  vtkMultiProcessController* global = vtkMultiProcessController::GetGlobalController();
  vtkMultiProcessController* controller =
    global && global->GetNumberOfProcesses() > 1 ? global : nullptr;
  vtkNew<vtkImageData> image;
  std::string warning;
  if (this->Held.cache.size() == 0)
  {
    this->Held.resampler.forgetGrid(); // no time step holds the last one
  }
  if (!this->Held.resampler
         .resample(data, config.vectors, config.resampleDimensions, controller,
           this->Steppers.runner(), image, warning)
         .empty())
  {
    return nullptr; // the update says why
  }
  grid = image;
  return image->GetPointData()->GetArray(this->Held.resampler.arrayName().c_str());
}

std::string vtkBoundParticleTracerInternals::keepTimeStep(
  bp::GridGeometry grid, std::array<double, 3> offset, const bp::FieldSlice& slice)
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
  const std::string gridError =
    this->Held.cache.size() > 0 ? this->matchHeldGrid(grid, offset, slice) : std::string();
  if (!gridError.empty())
  {
    return gridError;
  }
  this->Held.offset = offset;
  this->Held.grid = grid;
  const std::string fieldError = bp::VectorField(grid, slice).validate();
  if (!fieldError.empty())
  {
    return "Unusable input: " + fieldError + ".";
  }
  this->Held.cache.insert(
    this->Held.requestIndex, slice, this->Plan.needed(this->steppingFrom(), this->target()));
  this->Held.readThisUpdate = true;
  if (this->Plan.streaming() && this->Schedule && !this->Update.decision.replay)
  {
    // Steps end on every data time step, as post hoc: the present one is
    // new (a step skipped before it got here adds none).
    this->Schedule->addBreak(this->Plan.inputTimes()[this->Held.requestIndex]);
  }
  return std::string();
}

std::string vtkBoundParticleTracerInternals::matchHeldGrid(
  bp::GridGeometry& grid, std::array<double, 3>& offset, const bp::FieldSlice& slice)
{
  const double tolerance = 1e-9 * std::max(1.0, this->Held.grid.diagonal());
  bool same = grid.sameAs(this->Held.grid, tolerance);
  for (int a = 0; a < 3; ++a)
  {
    same = same && std::abs(offset[a] - this->Held.offset[a]) <= tolerance;
  }
  if (same)
  {
    return std::string();
  }
  if (!this->Plan.streaming() || this->Layout.distributed())
  {
    return "The input's time steps do not share one grid; every time step must have the same "
           "dimensions and point coordinates" +
      std::string(this->Plan.streaming() ? " (in situ under MPI, too)." : ".");
  }
  // In situ the engine's frame stays the held steps' (after a grid change,
  // the first step's): the elements keep their coordinates.
  std::array<double, 3> shift;
  for (int a = 0; a < 3; ++a)
  {
    shift[a] = this->Held.offset[a] - offset[a];
  }
  grid.translate(shift);
  offset = this->Held.offset;
  if (!grid.sameAs(this->Held.grid, tolerance))
  {
    this->relocate(grid, slice);
  }
  return std::string();
}

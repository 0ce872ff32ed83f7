// SPDX-License-Identifier: BSD-3-Clause
// vtkBoundParticleTracer's properties gathered as its core and internals
// take them: bp::TraceSettings for the settings the core resolves,
// bpvtk::TracerConfig for everything the internals read (they read nothing
// else of the filter), and the time line's settings.
#include "vtkBoundParticleTracer.h"

#include "OutputArrays.h"
#include "TraceSettings.h"
#include "TracerConfig.h"
#include "TracerTimeLine.h"
#include "vtkBoundParticleSeedType.h"

#include "vtkDataArraySelection.h"
#include "vtkDataObject.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationStringKey.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>

bp::TraceSettings vtkBoundParticleTracer::Settings() const
{
  bp::TraceSettings s;
  s.numberOfElements = this->NumberOfElements;
  s.elementSize = this->ElementSize;
  std::copy(this->EmitterCenter, this->EmitterCenter + 3, s.emitterCenter.begin());
  std::copy(this->EmitterSize, this->EmitterSize + 3, s.emitterSize.begin());
  std::copy(this->ElementRotation, this->ElementRotation + 3, s.rotationDegrees.begin());
  s.lifetimeRange = { this->LifetimeRange[0], this->LifetimeRange[1] };
  s.stepSize = this->StepSize;
  s.stepInCellLengths = this->StepSizeUnit == bp::StepUnit::CellLength;
  s.minimumReleaseSpeed = this->MinimumReleaseSpeed;
  s.trailLength = this->Trails ? this->TrailLength : 0;
  s.trailSpacing = this->TrailSpacing;
  s.latticeSpacing = this->LatticeSpacing;
  bp::Parameters& p = s.engine;
  p.iterations = this->RestorationIterations;
  p.relaxation = bp::settingAsFloat(this->RelaxationFactor);
  p.shapeStiffness = bp::settingAsFloat(this->ShapeMatchingStiffness);
  p.integrator = this->Integrator;
  p.restoration = this->Restoration;
  p.linearShapeMatching = this->ShapeMatchingMode == bp::ShapeFit::Linear;
  p.linearBlend = bp::settingAsFloat(this->LinearShapeMatchingBeta);
  p.orientation = this->ReleaseOrientation;
  p.releasePattern = this->ReleasePattern;
  p.anchor = this->Anchor;
  p.inertia = this->Inertia;
  p.linking = this->Linking;
  p.resetWhen = this->ResetWhen;
  p.boundary = this->Boundary;
  p.restitution = bp::settingAsFloat(this->Restitution);
  p.latticeWidth = this->LatticeWidth;
  p.linkStiffness = bp::settingAsFloat(this->LinkStiffness);
  p.responseTime = bp::settingAsFloat(this->ResponseTime);
  p.densityRatio = bp::settingAsFloat(this->DensityRatio);
  std::transform(this->Gravity, this->Gravity + 3, p.gravity.begin(), bp::settingAsFloat);
  s.timeDirection = this->TimeDirection;
  if (this->ReleaseWindow)
  {
    // Backward in the trace's own time: its mirror (TimeDirection.h). A window
    // that ends before it starts stays as given: validate() says so, in the data's times.
    const auto window = this->ReleaseStart <= this->ReleaseStop
      ? bp::traceWindow(this->TimeDirection, this->ReleaseStart, this->ReleaseStop)
      : std::array<double, 2>{ this->ReleaseStart, this->ReleaseStop };
    p.releaseStart = window[0];
    p.releaseStop = window[1];
  }
  p.seed = std::uint32_t(this->Seed);
  // The engine fits poses only for an output that shows them.
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    p.trackPoses =
      p.trackPoses || (row.needsPoses && this->OutputArraySelection->ArrayIsEnabled(row.name) != 0);
  }
  return s;
}

bpvtk::TracerConfig vtkBoundParticleTracer::Config()
{
  bpvtk::TracerConfig c;
  c.trace = this->Settings();
  c.engine = this->Engine;
  c.shape = this->ElementShape;
  c.templateSprings = this->TemplateSprings;
  std::copy(this->ResampleDimensions, this->ResampleDimensions + 3, c.resampleDimensions.begin());
  std::transform(
    this->Periodic, this->Periodic + 3, c.periodic.begin(), [](int flag) { return flag != 0; });
  c.coloringAxis = this->ColoringAxis;
  c.checkpointMemory = this->CheckpointMemory;
  c.initialStateFile = this->InitialStateFile;
  for (const bp::OutputArray& row : bp::outputArrays())
  {
    c.wanted[std::size_t(row.id)] = this->GetOutputArrayStatus(row.name) != 0 &&
      (row.id != bp::OutputArrayId::Vorticity || this->ComputeVorticity);
  }
  // Trails fade by their poses' Age (the Bound Particles display's fade of
  // the CPU output): it comes with them whatever Output Arrays holds.
  c.wanted[std::size_t(bp::OutputArrayId::Age)] =
    c.wanted[std::size_t(bp::OutputArrayId::Age)] || this->Trails;
  c.seedType = this->SeedType;
  c.templateInput = this->GetNumberOfInputConnections(1) > 0;
  c.seedSource = this->GetNumberOfInputConnections(2) > 0;
  vtkInformation* vectors = this->GetInputArrayInformation(0);
  const char* name = vectors && vectors->Has(vtkDataObject::FIELD_NAME())
    ? vectors->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  c.vectors.name = name ? name : "";
  c.vectors.association = vectors && vectors->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? vectors->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  c.vectorsUnitsReason = this->TimeLine->reasonFor(c.vectors.name, c.vectors.association);
  // Release Weights: input array 1, "None" (the panel's) or unset for none.
  vtkInformation* weights = this->GetInputArrayInformation(1);
  const char* weightsName = weights && weights->Has(vtkDataObject::FIELD_NAME())
    ? weights->Get(vtkDataObject::FIELD_NAME())
    : nullptr;
  c.releaseWeights = weightsName && std::string(weightsName) != "None" ? weightsName : "";
  c.releaseWeightsAssociation = weights && weights->Has(vtkDataObject::FIELD_ASSOCIATION())
    ? weights->Get(vtkDataObject::FIELD_ASSOCIATION())
    : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  c.trace.weighted = !c.releaseWeights.empty();
  // The Surfaces: input 3, with the interaction of every cell, or of each
  // by a cell array of the Surfaces ("None", the panel's, or empty for none).
  c.surfaces = this->GetNumberOfInputConnections(3) > 0;
  c.surfaceInteraction = this->SurfaceInteraction;
  c.surfaceInteractionArray =
    this->SurfaceInteractionArray != "None" ? this->SurfaceInteractionArray : "";
  return c;
}

bpvtk::TimeLineSettings vtkBoundParticleTracer::TimeLineProperties() const
{
  bpvtk::TimeLineSettings s;
  s.duration = this->Duration;
  s.framesPerInputStep = this->FramesPerInputStep;
  s.numberOfTimeSteps = this->NumberOfTimeSteps;
  s.stepSize = this->StepSize;
  s.stepInCellLengths = this->StepSizeUnit == bp::StepUnit::CellLength;
  return s;
}

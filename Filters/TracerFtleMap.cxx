// SPDX-License-Identifier: BSD-3-Clause
// The FTLE map (TracerFtleMap.h), and the tracer's step that shows it
// (vtkInternals::showFtleMap): from the CPU engine's state, gathered on
// process 0 in a distributed run.
#include "TracerFtleMap.h"

#include "vtkBoundParticleTracerInternals.h"

#include "ElementStretch.h"
#include "Engine.h"
#include "TracerConfig.h"
#include "TracerFieldProbe.h"

#include "vtkCommunicator.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <vector>

namespace bpvtk
{

namespace
{
/// Per lattice point: FTLE, largest and smallest stretch, shown (1 or 0),
/// age (an element released again early is younger than its neighbours).
constexpr int Fields = 5;

/// This process's elements' values at their lattice points; 0 elsewhere.
std::vector<float> localValues(const bp::Engine& engine, std::size_t points)
{
  std::vector<float> values(Fields * points, 0.0f);
  const std::size_t n = engine.particlesPerElement();
  const bp::StretchFit fit(engine.shape().rest, engine.parameters().elementSize);
  if (fit.span() == 0)
  {
    return values; // one particle measures no stretch: every point invalid
  }
  for (std::size_t e = 0; e < engine.elementCount(); ++e)
  {
    const std::size_t id = engine.elementIds()[e];
    const bool hidden = engine.resetFlags()[e] & bp::HiddenFlags;
    const double age = double(engine.drawnLifetime(e)) - double(engine.lifetimes()[e]);
    // Too young for an FTLE: invalid, as a point not yet released.
    if (id >= points || hidden || !(age >= engine.parameters().ftleMinimumAge))
    {
      continue;
    }
    const std::array<float, 3> d =
      bp::elementDeformation(fit, engine.positions().data() + 3 * e * n, age, false);
    float* v = values.data() + Fields * id;
    v[0] = d[2];
    v[1] = d[0];
    v[2] = d[1];
    v[3] = 1.0f;
    v[4] = float(age);
  }
  return values;
}
} // namespace

void fillFtleMap(vtkImageData* image, const bp::Engine& engine, const std::array<double, 3>& offset,
  vtkMultiProcessController* controller)
{
  image->Initialize();
  const bp::Parameters& p = engine.parameters();
  const std::size_t points = p.lattice.size();
  if (p.releasePattern != bp::ReleasePattern::Lattice || points != p.numberOfElements)
  {
    return;
  }
  std::vector<float> values = localValues(engine, points);
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    // Each element lives on one process: the sum is every element's values.
    std::vector<float> sum(values.size(), 0.0f);
    controller->Reduce(
      values.data(), sum.data(), vtkIdType(values.size()), vtkCommunicator::SUM_OP, 0);
    if (controller->GetLocalProcessId() != 0)
    {
      return;
    }
    values.swap(sum);
  }
  image->SetDimensions(p.lattice.counts[0], p.lattice.counts[1], p.lattice.counts[2]);
  double origin[3], spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    origin[a] = double(p.lattice.origin[a]) + offset[a];
    spacing[a] = p.lattice.spacing[a] > 0.0f ? double(p.lattice.spacing[a]) : 1.0;
  }
  image->SetOrigin(origin);
  image->SetSpacing(spacing);
  vtkNew<vtkFloatArray> ftle, stretch, age;
  vtkNew<vtkUnsignedCharArray> valid;
  ftle->SetName("FTLE");
  stretch->SetName("Stretch");
  stretch->SetNumberOfComponents(2);
  age->SetName("Age");
  valid->SetName("vtkValidPointMask");
  ftle->SetNumberOfTuples(vtkIdType(points));
  stretch->SetNumberOfTuples(vtkIdType(points));
  valid->SetNumberOfTuples(vtkIdType(points));
  age->SetNumberOfTuples(vtkIdType(points));
  for (std::size_t k = 0; k < points; ++k)
  {
    const float* v = values.data() + Fields * k;
    const bool shown = v[3] > 0.5f;
    ftle->SetValue(vtkIdType(k), shown ? v[0] : 0.0f);
    stretch->SetTypedComponent(vtkIdType(k), 0, shown ? v[1] : 1.0f);
    stretch->SetTypedComponent(vtkIdType(k), 1, shown ? v[2] : 1.0f);
    valid->SetValue(vtkIdType(k), shown ? 1 : 0);
    age->SetValue(vtkIdType(k), shown ? v[4] : 0.0f);
  }
  image->GetPointData()->SetScalars(ftle);
  image->GetPointData()->AddArray(stretch);
  image->GetPointData()->AddArray(valid);
  image->GetPointData()->AddArray(age);
}

bool mapsLattice(const TracerConfig& config)
{
  return config.trace.engine.releasePattern == bp::ReleasePattern::Lattice && !config.seedSource &&
    !config.seedType && !config.linking();
}

void announceFtleMap(vtkInformation* info, const TracerConfig& config, const FieldProbe& probe)
{
  int extent[6] = { 0, -1, 0, -1, 0, -1 };
  double origin[3] = { 0, 0, 0 }, spacing[3] = { 1, 1, 1 };
  const bp::Resolution resolved = mapsLattice(config) && probe.read
    ? bp::resolveSettings(config.trace, probe.facts)
    : bp::Resolution();
  const bp::Parameters& p = resolved.parameters;
  if (resolved.error.empty() && p.releasePattern == bp::ReleasePattern::Lattice)
  {
    // As fillFtleMap places the image (one point per lattice point).
    for (int a = 0; a < 3; ++a)
    {
      extent[2 * a + 1] = p.lattice.counts[a] - 1;
      origin[a] = double(p.lattice.origin[a]) + probe.facts.offset[a];
      spacing[a] = p.lattice.spacing[a] > 0.0f ? double(p.lattice.spacing[a]) : 1.0;
    }
  }
  using SDDP = vtkStreamingDemandDrivenPipeline;
  info->Set(SDDP::WHOLE_EXTENT(), extent, 6);
  info->Set(vtkDataObject::ORIGIN(), origin, 3);
  info->Set(vtkDataObject::SPACING(), spacing, 3);
}

} // namespace bpvtk

void vtkBoundParticleTracerInternals::showFtleMap(vtkImageData* image)
{
  const bp::Engine* particles = this->stepper().particles();
  if (!particles)
  {
    // The GPU engine's state stays in the display: no map.
    image->Initialize();
  }
  else if (!this->Layout.distributed())
  {
    bpvtk::fillFtleMap(image, *particles, this->Held.offset, nullptr);
  }
  else
  {
    // Collective, so only in an update every process runs in step (as
    // gatherExchange); otherwise nothing moved since the map last gathered.
    if (this->Update.stepsInLastUpdate > 0 || this->Update.lastUpdateReplayed)
    {
      bpvtk::fillFtleMap(this->FtleMap, *particles, this->Held.offset, this->Layout.Controller);
    }
    image->ShallowCopy(this->FtleMap);
  }
  // The time shown, as the elements' (the executive would stamp the last
  // input step read: a neighbour of the time shown, between two of them).
  image->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
}

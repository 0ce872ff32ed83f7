// SPDX-License-Identifier: BSD-3-Clause
// The Interactions output (TracerInteractions.h), and the tracer's step that
// shows it (vtkInternals::showInteractions): from the CPU engine's log,
// gathered on process 0 in a distributed run.
#include "TracerInteractions.h"

#include "vtkBoundParticleTracerInternals.h"

#include "Engine.h"
#include "TimeDirection.h"

#include "vtkCellArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>

namespace bpvtk
{

namespace
{
/// One event as doubles, for the gather: time, element, particle, kind,
/// side, position (3), velocity (3).
constexpr int Fields = 11;

void pack(const bp::InteractionEvent& x, double* v)
{
  v[0] = x.time;
  v[1] = double(x.element);
  v[2] = double(x.particle);
  v[3] = double(int(x.kind));
  v[4] = double(x.side);
  for (int k = 0; k < 3; ++k)
  {
    v[5 + k] = double(x.position[std::size_t(k)]);
    v[8 + k] = double(x.velocity[std::size_t(k)]);
  }
}

bp::InteractionEvent unpack(const double* v)
{
  bp::InteractionEvent x;
  x.time = v[0];
  x.element = std::uint32_t(v[1]);
  x.particle = std::int32_t(v[2]);
  x.kind = bp::Interaction(int(v[3]));
  x.side = std::int8_t(v[4]);
  for (int k = 0; k < 3; ++k)
  {
    x.position[std::size_t(k)] = float(v[5 + k]);
    x.velocity[std::size_t(k)] = float(v[8 + k]);
  }
  return x;
}

/// Every process's events on process 0 (false elsewhere: nothing to write).
bool gather(std::vector<bp::InteractionEvent>& events, vtkMultiProcessController* controller)
{
  vtkNew<vtkDoubleArray> mine, all;
  mine->SetNumberOfComponents(Fields);
  mine->SetNumberOfTuples(vtkIdType(events.size()));
  for (std::size_t k = 0; k < events.size(); ++k)
  {
    pack(events[k], mine->GetPointer(vtkIdType(Fields * k)));
  }
  all->SetNumberOfComponents(Fields);
  controller->GatherV(mine, all, 0);
  if (controller->GetLocalProcessId() != 0)
  {
    return false;
  }
  events.clear();
  for (vtkIdType k = 0; k < all->GetNumberOfTuples(); ++k)
  {
    events.push_back(unpack(all->GetPointer(Fields * k)));
  }
  std::sort(events.begin(), events.end(), bp::interactionBefore);
  return true;
}

template <class A>
vtkNew<A> named(const char* name, int components, vtkIdType tuples)
{
  vtkNew<A> a;
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}
} // namespace

void fillInteractions(vtkPolyData* out, std::vector<bp::InteractionEvent> events,
  const std::array<double, 3>& offset, bool backward, vtkMultiProcessController* controller)
{
  out->Initialize();
  if (controller && controller->GetNumberOfProcesses() > 1 && !gather(events, controller))
  {
    return;
  }
  const vtkIdType count = vtkIdType(events.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  auto element = named<vtkIntArray>("ElementId", 1, count);
  auto particle = named<vtkIntArray>("ParticleIndex", 1, count);
  auto time = named<vtkDoubleArray>("Time", 1, count);
  auto velocity = named<vtkFloatArray>("ElementVelocity", 3, count);
  auto normal = named<vtkFloatArray>("Normal", 3, count);
  auto surface = named<vtkIntArray>("SurfaceId", 1, count);
  auto kind = named<vtkIntArray>("Interaction", 1, count);
  const float sign = backward ? -1.0f : 1.0f;
  const bp::TimeDirection direction =
    backward ? bp::TimeDirection::Backward : bp::TimeDirection::Forward;
  for (vtkIdType k = 0; k < count; ++k)
  {
    const bp::InteractionEvent& x = events[std::size_t(k)];
    const std::array<float, 3> n = bp::sideNormal(x.side);
    double p[3];
    float v[3];
    for (int a = 0; a < 3; ++a)
    {
      p[a] = double(x.position[std::size_t(a)]) + offset[std::size_t(a)];
      v[a] = sign * x.velocity[std::size_t(a)];
    }
    points->SetPoint(k, p);
    element->SetValue(k, int(x.element));
    particle->SetValue(k, x.particle);
    time->SetValue(k, bp::traceTime(direction, x.time));
    velocity->SetTypedTuple(k, v);
    normal->SetTypedTuple(k, n.data());
    surface->SetValue(k, x.side);
    kind->SetValue(k, int(x.kind));
  }
  out->SetPoints(points);
  vtkNew<vtkCellArray> vertices;
  for (vtkIdType k = 0; k < count; ++k)
  {
    vertices->InsertNextCell(1, &k);
  }
  out->SetVerts(vertices);
  vtkPointData* pd = out->GetPointData();
  for (vtkAbstractArray* a : std::initializer_list<vtkAbstractArray*>{
         element, particle, time, velocity, normal, surface, kind })
  {
    pd->AddArray(a);
  }
  pd->SetNormals(normal);
  pd->SetActiveScalars("Interaction");
  vtkNew<vtkStringArray> names;
  names->SetName("InteractionNames");
  for (const char* name : bp::InteractionNames)
  {
    names->InsertNextValue(name);
  }
  out->GetFieldData()->AddArray(names);
}

} // namespace bpvtk

void vtkBoundParticleTracerInternals::decideInteractionsOnly()
{
  bp::Stepper& stepper = this->stepper();
  const bp::TracePlan::Update& u = this->Update.decision;
  const bp::TraceCursor& at = stepper.cursor;
  // Shown here last by the CPU engine, which stands on the target (the short
  // step to it shown, or a boundary there) or, where a State update took
  // the short step back since, on the last boundary before it.
  this->Update.interactionsOnly = !this->Plan.streaming() && this->Schedule && this->Shown.valid &&
    this->Shown.queue == 0 && this->Shown.target == u.target && !u.replay && u.resume < 0 &&
    at.valid && stepper.particles() &&
    (at.showsPartialStep ||
      this->Schedule->next(at.committed) > u.target + this->Schedule->epsilon());
}

void vtkBoundParticleTracerInternals::showInteractionsAlone(vtkPolyData* out)
{
  if (!this->stepper().cursor.showsPartialStep)
  {
    // The short step to the time shown again, as show() takes it (collective
    // in parallel); the last update's report stays.
    const vtkIdType steps = this->Update.stepsInLastUpdate;
    const Pass shortStep = this->stepShort(false);
    this->Update.stepsInLastUpdate = steps;
    if (shortStep.kind != Pass::Done)
    {
      vtkErrorWithObjectMacro(this->Owner, << shortStep.message);
      out->Initialize();
      return;
    }
  }
  this->showInteractions(out);
}

void vtkBoundParticleTracerInternals::showInteractions(vtkPolyData* out)
{
  const bp::Engine* particles = this->stepper().particles();
  const bool backward = this->Plan.direction() == bp::TimeDirection::Backward;
  if (!particles)
  {
    out->Initialize(); // the GPU engine records no events
  }
  else if (!this->Layout.distributed())
  {
    bpvtk::fillInteractions(
      out, particles->interactions().events(), this->Held.offset, backward, nullptr);
  }
  else
  {
    // Collective, so only where the trace moved in this update: its steps,
    // a replay, or a checkpoint resumed or short step taken back (the
    // cursor, alike on every process, stands elsewhere).
    const bp::TraceCursor& cursor = this->stepper().cursor;
    const std::array<double, 3> at = { double(cursor.steps), cursor.showsPartialStep ? 1.0 : 0.0,
      this->target() };
    if (this->Update.stepsInLastUpdate > 0 || this->Update.lastUpdateReplayed ||
      at != this->InteractionsAt)
    {
      bpvtk::fillInteractions(this->Interactions, particles->interactions().events(),
        this->Held.offset, backward, this->Layout.Controller);
      this->InteractionsAt = at;
    }
    out->ShallowCopy(this->Interactions);
  }
  if (particles && particles->interactions().full() && this->Said.first(bpvtk::Topic::Interactions))
  {
    vtkWarningWithObjectMacro(this->Owner,
      << "The Interactions output keeps the first " << particles->interactions().capacity()
      << " events of the trace on each process (about "
      << particles->interactions().capacity() * sizeof(bp::InteractionEvent) / (1024 * 1024)
      << " MiB); the later ones are not recorded. Fewer elements or a shorter trace record all.");
  }
  // The time shown, as the elements'.
  out->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
}

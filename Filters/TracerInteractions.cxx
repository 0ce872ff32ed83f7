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
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkIntArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSetGet.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace bpvtk
{

namespace
{
/// One event as doubles, for the gather: time, element, particle, kind,
/// side, cell, position (3), velocity (3), normal (3).
constexpr int Fields = 15;

void pack(const bp::InteractionEvent& x, double* v)
{
  v[0] = x.time;
  v[1] = double(x.element);
  v[2] = double(x.particle);
  v[3] = double(int(x.kind));
  v[4] = double(x.side);
  v[5] = double(x.cell);
  for (int k = 0; k < 3; ++k)
  {
    v[6 + k] = double(x.position[std::size_t(k)]);
    v[9 + k] = double(x.velocity[std::size_t(k)]);
    v[12 + k] = double(x.normal[std::size_t(k)]);
  }
}

bp::InteractionEvent unpack(const double* v)
{
  bp::InteractionEvent x;
  x.time = v[0];
  x.element = std::uint32_t(v[1]);
  x.particle = std::int32_t(v[2]);
  x.kind = bp::Interaction(int(v[3]));
  x.side = std::int32_t(v[4]);
  x.cell = std::int32_t(v[5]);
  for (int k = 0; k < 3; ++k)
  {
    x.position[std::size_t(k)] = float(v[6 + k]);
    x.velocity[std::size_t(k)] = float(v[9 + k]);
    x.normal[std::size_t(k)] = float(v[12 + k]);
  }
  return x;
}

template <class A>
vtkSmartPointer<A> named(const char* name, int components)
{
  auto a = vtkSmartPointer<A>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  return a;
}

/// At most this many events are gathered on process 0: GatherV's counts
/// (Fields doubles an event) stay ints.
constexpr vtkIdType GatherBound = vtkIdType(std::numeric_limits<int>::max() / Fields);

/// Of `offered[r]` events on each process r, how many each sends so that
/// `room` are sent at most: every one where they fit, else the room
/// divided evenly among the processes that offer some (the rest to the
/// lowest ids). Alike on every process: it is computed from gathered counts.
std::vector<vtkIdType> quotas(const std::vector<vtkIdType>& offered, vtkIdType room)
{
  std::vector<vtkIdType> take(offered.size(), 0);
  vtkIdType left = std::max<vtkIdType>(room, 0);
  for (;;)
  {
    vtkIdType wanting = 0;
    for (std::size_t r = 0; r < offered.size(); ++r)
    {
      wanting += take[r] < offered[r] ? 1 : 0;
    }
    if (wanting == 0 || left == 0)
    {
      return take;
    }
    const vtkIdType share = std::max<vtkIdType>(left / wanting, 1);
    for (std::size_t r = 0; r < offered.size() && left > 0; ++r)
    {
      const vtkIdType more = std::min({ offered[r] - take[r], share, left });
      take[r] += more;
      left -= more;
    }
  }
}
} // namespace

struct InteractionsOutput::Arrays
{
  vtkSmartPointer<vtkDoubleArray> points = named<vtkDoubleArray>("Points", 3);
  vtkSmartPointer<vtkIntArray> element = named<vtkIntArray>("ElementId", 1);
  vtkSmartPointer<vtkIntArray> particle = named<vtkIntArray>("ParticleIndex", 1);
  vtkSmartPointer<vtkDoubleArray> time = named<vtkDoubleArray>("Time", 1);
  vtkSmartPointer<vtkFloatArray> velocity = named<vtkFloatArray>("ElementVelocity", 3);
  vtkSmartPointer<vtkFloatArray> normal = named<vtkFloatArray>("Normal", 3);
  vtkSmartPointer<vtkIntArray> surface = named<vtkIntArray>("SurfaceId", 1);
  vtkSmartPointer<vtkIntArray> cell = named<vtkIntArray>("SurfaceCell", 1);
  vtkSmartPointer<vtkIntArray> kind = named<vtkIntArray>("Interaction", 1);
  vtkSmartPointer<vtkIdTypeArray> offsets = vtkSmartPointer<vtkIdTypeArray>::New();
  vtkSmartPointer<vtkIdTypeArray> connectivity = vtkSmartPointer<vtkIdTypeArray>::New();

  Arrays() { this->offsets->InsertNextValue(0); }

  /// Appends `events` (in the output's order), vertex cells included.
  void append(const bp::InteractionEvent* events, std::size_t count,
    const std::array<double, 3>& offset, bool backward)
  {
    const float sign = backward ? -1.0f : 1.0f;
    const bp::TimeDirection direction =
      backward ? bp::TimeDirection::Backward : bp::TimeDirection::Forward;
    vtkIdType id = this->element->GetNumberOfTuples();
    for (std::size_t k = 0; k < count; ++k, ++id)
    {
      const bp::InteractionEvent& x = events[k];
      double p[3];
      float v[3];
      for (int a = 0; a < 3; ++a)
      {
        p[a] = double(x.position[std::size_t(a)]) + offset[std::size_t(a)];
        v[a] = sign * x.velocity[std::size_t(a)];
      }
      // Insert* grows each array geometrically: appending costs the events added.
      this->points->InsertNextTypedTuple(p);
      this->element->InsertNextValue(int(x.element));
      this->particle->InsertNextValue(x.particle);
      this->time->InsertNextValue(bp::traceTime(direction, x.time));
      this->velocity->InsertNextTypedTuple(v);
      this->normal->InsertNextTypedTuple(x.normal.data());
      this->surface->InsertNextValue(x.side);
      this->cell->InsertNextValue(x.cell);
      this->kind->InsertNextValue(int(x.kind));
      this->connectivity->InsertNextValue(id);
      this->offsets->InsertNextValue(id + 1);
    }
    for (vtkAbstractArray* a : this->all())
    {
      a->Modified();
    }
    this->points->Modified();
    this->offsets->Modified();
    this->connectivity->Modified();
  }

  /// Keeps the first `events` (fewer than held), without reallocating:
  /// the arrays' memory stays for the events appended next.
  void truncate(vtkIdType events)
  {
    for (vtkDataArray* a :
      { static_cast<vtkDataArray*>(this->points), static_cast<vtkDataArray*>(this->connectivity) })
    {
      shorten(a, events);
    }
    for (vtkAbstractArray* a : this->all())
    {
      shorten(vtkDataArray::SafeDownCast(a), events);
    }
    shorten(this->offsets, events + 1);
  }

  /// `a` cut to its first `tuples` (Reset keeps the memory; inserting the
  /// last value kept sets the count back without a reallocation).
  static void shorten(vtkDataArray* a, vtkIdType tuples)
  {
    if (tuples >= a->GetNumberOfTuples())
    {
      return;
    }
    const int last = a->GetNumberOfComponents() - 1;
    const double value = tuples > 0 ? a->GetComponent(tuples - 1, last) : 0.0;
    a->Reset();
    if (tuples > 0)
    {
      a->InsertComponent(tuples - 1, last, value);
    }
    a->Modified();
  }

  std::array<vtkAbstractArray*, 8> all() const
  {
    return { { element, particle, time, velocity, normal, surface, cell, kind } };
  }

  /// `out` made of these arrays: points, one vertex cell an event (the
  /// cell array set at once on its offsets and connectivity), point data.
  void show(vtkPolyData* out) const
  {
    out->Initialize();
    vtkNew<vtkPoints> pts;
    pts->SetData(this->points);
    out->SetPoints(pts);
    vtkNew<vtkCellArray> vertices;
    vertices->SetData(this->offsets.Get(), this->connectivity.Get());
    out->SetVerts(vertices);
    vtkPointData* pd = out->GetPointData();
    for (vtkAbstractArray* a : this->all())
    {
      pd->AddArray(a);
    }
    pd->SetNormals(this->normal);
    pd->SetActiveScalars("Interaction");
    vtkNew<vtkStringArray> names;
    names->SetName("InteractionNames");
    for (const char* name : bp::InteractionNames)
    {
      names->InsertNextValue(name);
    }
    out->GetFieldData()->AddArray(names);
  }
};

void InteractionsOutput::clear()
{
  this->Data.reset();
  this->Mark = bp::InteractionLog::Mark();
  this->Filled = false;
  this->Clipped = false;
  this->Count = 0;
}

void InteractionsOutput::gather(const bp::InteractionLog& log, bool same, std::size_t shared,
  std::vector<bp::InteractionEvent>& added, const std::array<double, 3>& offset, bool backward,
  vtkMultiProcessController* controller)
{
  // Every process learns every one's (valid, events dropped since the
  // last fill, events added, all events, capacity): the decisions below
  // are alike everywhere, and so is each call.
  const int processes = controller->GetNumberOfProcesses();
  constexpr int Said = 5;
  const vtkIdType mine[Said] = { same ? 1 : 0, vtkIdType(this->Mark.size() - shared),
    vtkIdType(added.size()), vtkIdType(log.size()), vtkIdType(log.capacity()) };
  std::vector<vtkIdType> every(std::size_t(Said * processes), 0);
  controller->AllGather(mine, every.data(), Said);
  auto of = [&](int r, int k) { return every[std::size_t(Said * r + k)]; };
  // Appended to where nothing was clipped: the events dropped on each
  // process are those of steps after the last both logs share, which on
  // every process (stepping alike) come after every event kept, so they
  // are the output's last ones.
  bool appends = !this->Clipped;
  vtkIdType bound = GatherBound, dropped = 0;
  for (int r = 0; r < processes; ++r)
  {
    appends = appends && of(r, 0) == 1;
    dropped += of(r, 1);
    bound = std::min(bound, of(r, 4));
  }
  appends = appends && dropped <= this->Count;
  std::vector<vtkIdType> offered(std::size_t(processes), 0);
  for (int r = 0; r < processes; ++r)
  {
    offered[std::size_t(r)] = of(r, appends ? 2 : 3);
  }
  const vtkIdType keep = appends ? this->Count - dropped : 0;
  if (!appends)
  {
    this->Clipped = false;
    if (same)
    {
      added = log.events();
    }
  }
  const std::vector<vtkIdType> take = quotas(offered, bound - keep);
  const vtkIdType sent = take[std::size_t(controller->GetLocalProcessId())];
  vtkNew<vtkDoubleArray> packed, all;
  packed->SetNumberOfComponents(Fields);
  packed->SetNumberOfTuples(sent);
  for (vtkIdType k = 0; k < sent; ++k)
  {
    pack(added[std::size_t(k)], packed->GetPointer(Fields * k));
  }
  added = std::vector<bp::InteractionEvent>();
  all->SetNumberOfComponents(Fields);
  controller->GatherV(packed, all, 0);
  vtkIdType total = 0, wanted = 0;
  for (int r = 0; r < processes; ++r)
  {
    total += take[std::size_t(r)];
    wanted += offered[std::size_t(r)];
  }
  this->Count = keep + total;
  this->Clipped = total < wanted;
  if (controller->GetLocalProcessId() == 0)
  {
    std::vector<bp::InteractionEvent> gathered;
    gathered.reserve(std::size_t(all->GetNumberOfTuples()));
    for (vtkIdType k = 0; k < all->GetNumberOfTuples(); ++k)
    {
      gathered.push_back(unpack(all->GetPointer(Fields * k)));
    }
    // The steps added follow every event kept: sorting them alone keeps
    // the trace's order.
    std::sort(gathered.begin(), gathered.end(), bp::interactionBefore);
    if (!appends || keep == 0 || !this->Data)
    {
      this->Data = std::make_shared<Arrays>();
    }
    else
    {
      this->Data->truncate(keep);
    }
    this->Data->append(gathered.data(), gathered.size(), offset, backward);
  }
  else
  {
    this->Data.reset();
  }
}

void InteractionsOutput::fill(vtkPolyData* out, const bp::InteractionLog& log,
  const std::array<double, 3>& offset, bool backward, vtkMultiProcessController* controller)
{
  const bool distributed = controller && controller->GetNumberOfProcesses() > 1;
  std::vector<bp::InteractionEvent> added;
  // The events this log shares with the one shown last (the steps both
  // hold), the rest in `added`; none where the offset or direction changed.
  const bool same = this->Filled && offset == this->Offset && backward == this->Backward;
  const std::size_t shared = same ? log.eventsSince(this->Mark, added) : 0;
  if (!same)
  {
    added = log.events();
  }
  if (!distributed)
  {
    if (shared == 0 || !this->Data)
    {
      this->Data = std::make_shared<Arrays>(); // new arrays: the last output's stay as they are
      if (shared > 0)
      {
        added = log.events();
      }
    }
    else
    {
      this->Data->truncate(vtkIdType(shared));
    }
    this->Data->append(added.data(), added.size(), offset, backward);
    this->Count = this->Data->element->GetNumberOfTuples();
  }
  else
  {
    this->gather(log, same, shared, added, offset, backward, controller);
  }
  this->Mark = log.mark();
  this->Offset = offset;
  this->Backward = backward;
  this->Filled = true;
  if (this->Data)
  {
    this->Data->show(out);
  }
  else
  {
    out->Initialize();
  }
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
    // Appends the steps added since the last update where the log only grew.
    this->InteractionsOut.fill(
      out, particles->interactions(), this->Held.offset, backward, nullptr);
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
      this->InteractionsOut.fill(this->Interactions, particles->interactions(), this->Held.offset,
        backward, this->Layout.Controller);
      this->InteractionsAt = at;
    }
    out->ShallowCopy(this->Interactions);
  }
  const bool distributed = this->Layout.distributed();
  if (particles && (particles->interactions().full() || this->InteractionsOut.clipped()) &&
    this->Said.first(bpvtk::Topic::Interactions))
  {
    const std::size_t capacity = particles->interactions().capacity();
    const std::size_t mib = capacity * sizeof(bp::InteractionEvent) / (1024 * 1024);
    if (!distributed)
    {
      vtkWarningWithObjectMacro(this->Owner,
        << "The trace's events are recorded up to " << capacity << " (about " << mib
        << " MiB); the later ones are not, and the Interactions output shows the first " << capacity
        << ". Fewer elements or a shorter trace record all.");
    }
    else
    {
      vtkWarningWithObjectMacro(this->Owner,
        << "Each process records up to " << capacity << " events of its elements (about " << mib
        << " MiB), and the Interactions output gathers at most " << capacity
        << " from all on process 0, the first steps' events; "
        << (particles->interactions().full() ? "this process's later events are not recorded."
                                             : "the later events are left out of it.")
        << " Fewer elements or a shorter trace show all.");
    }
  }
  // The time shown, as the elements'.
  out->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), this->dataTarget());
}

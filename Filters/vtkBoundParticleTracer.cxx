// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleTracer.h"

#include "ElementTemplate.h"
#include "Engine.h"
#include "Partition.h"
#include "VectorField.h"
#include "WorkQueue.h"

#include "vtkArrayDispatch.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCommunicator.h"
#include "vtkDataArrayRange.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkExtentTranslator.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMatrix3x3.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSMPTools.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>
#include <sstream>
#include <vector>

namespace
{
/// Debian's VTK starts on the Sequential SMP backend; the engine is parallel
/// over elements, so take the threaded one unless the user chose a backend.
void preferThreadedBackend()
{
  static std::once_flag once;
  std::call_once(once,
    []
    {
      if (!std::getenv("VTK_SMP_BACKEND_IN_USE"))
      {
        vtkSMPTools::SetBackend("STDThread");
      }
    });
}

bp::RangeRunner smpRunner()
{
  return [](std::size_t count, const bp::RangeFunction& f)
  {
    vtkSMPTools::For(vtkIdType(0), vtkIdType(count),
      [&f](vtkIdType begin, vtkIdType end) { f(std::size_t(begin), std::size_t(end)); });
  };
}

struct CopyToFloat
{
  template <typename ArrayT>
  void operator()(ArrayT* array, std::vector<float>& out) const
  {
    const auto values = vtk::DataArrayValueRange(array);
    out.resize(values.size());
    std::transform(values.begin(), values.end(), out.begin(),
      [](typename decltype(values)::ValueType v) { return static_cast<float>(v); });
  }
};
/// The global controller when the pipeline asks for one of as many pieces as
/// it has processes (pvbatch, pvserver under MPI), else null.
vtkMultiProcessController* pieceController(int pieces)
{
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  return pieces > 1 && c && c->GetNumberOfProcesses() == pieces ? c : nullptr;
}

/// Sends each process its records, pairwise in one global order of pairs (so
/// blocking sends never wait on each other in a cycle); only pairs with
/// something to send talk.
bp::ExchangeFunction controllerExchange(vtkMultiProcessController* controller)
{
  return [controller](const std::vector<std::vector<std::uint32_t>>& outgoing)
  {
    const int P = controller->GetNumberOfProcesses(), me = controller->GetLocalProcessId();
    const std::size_t processes = std::size_t(P);
    std::vector<long long> counts(processes), all(processes * processes);
    for (int q = 0; q < P; ++q)
    {
      counts[std::size_t(q)] = q == me ? 0 : (long long)outgoing[std::size_t(q)].size();
    }
    controller->AllGather(counts.data(), all.data(), P);
    constexpr int tag = 8731;
    std::vector<std::uint32_t> incoming, buffer;
    for (int q = 0; q < P; ++q)
    {
      if (q == me)
      {
        continue;
      }
      const long long sending = all[std::size_t(me) * P + q];
      const long long receiving = all[std::size_t(q) * P + me];
      auto send = [&]
      {
        if (sending > 0)
          controller->Send(outgoing[std::size_t(q)].data(), vtkIdType(sending), q, tag);
      };
      auto receive = [&]
      {
        if (receiving > 0)
        {
          buffer.resize(std::size_t(receiving));
          controller->Receive(buffer.data(), vtkIdType(receiving), q, tag);
          incoming.insert(incoming.end(), buffer.begin(), buffer.end());
        }
      };
      if (me < q)
      {
        send();
        receive();
      }
      else
      {
        receive();
        send();
      }
    }
    return incoming;
  };
}
} // namespace

// The request key's DataKey is where the output keeps the value it was made for.
class vtkInformationGpuWorkQueueRequestKey : public vtkInformationIntegerRequestKey
{
public:
  vtkInformationGpuWorkQueueRequestKey(const char* name, const char* location)
    : vtkInformationIntegerRequestKey(name, location)
  {
    this->DataKey = vtkBoundParticleTracer::DATA_GPU_WORK_QUEUE();
  }
};
vtkInformationKeyMacro(vtkBoundParticleTracer, DATA_GPU_WORK_QUEUE, Integer);
vtkInformationKeySubclassMacro(
  vtkBoundParticleTracer, GPU_WORK_QUEUE, GpuWorkQueueRequest, IntegerRequest);

namespace
{
std::mutex& queueRegistryMutex()
{
  static std::mutex m;
  return m;
}
std::map<int, std::weak_ptr<bp::WorkQueue>>& queueRegistry()
{
  static std::map<int, std::weak_ptr<bp::WorkQueue>> r;
  return r;
}
std::uint64_t nextProducerId()
{
  static std::uint64_t next = 0;
  std::lock_guard<std::mutex> lock(queueRegistryMutex());
  return ++next;
}
} // namespace

std::shared_ptr<bp::WorkQueue> vtkBoundParticleTracer::NewWorkQueue()
{
  std::lock_guard<std::mutex> lock(queueRegistryMutex());
  static int nextId = 0;
  auto& registry = queueRegistry();
  for (auto it = registry.begin(); it != registry.end();)
    it = it->second.expired() ? registry.erase(it) : std::next(it);
  auto queue = std::make_shared<bp::WorkQueue>(++nextId);
  registry[queue->id()] = queue;
  return queue;
}

std::shared_ptr<bp::WorkQueue> vtkBoundParticleTracer::FindWorkQueue(int id)
{
  std::lock_guard<std::mutex> lock(queueRegistryMutex());
  const auto it = queueRegistry().find(id);
  return it == queueRegistry().end() ? nullptr : it->second.lock();
}

namespace
{
/// An array of the CPU output and the range it is expected to span.
struct ExpectedRange
{
  std::string name;
  double low = 0.0, high = 1.0;
};

/**
 * The ranges the CPU output's arrays are expected to span, for the GPU
 * output, which has no particles: exact where the parameters fix them
 * (Lifetime, Layer, Radius), from the field otherwise (Speed and Velocity from
 * its largest speed; Vorticity from central differences on a lattice of at
 * most 32^3 of its points); Force is bounded by the largest relative motion
 * of two particles in a step.
 */
std::vector<ExpectedRange> expectedRanges(const bp::VectorField& field, const bp::Parameters& p,
  double dt, int axis, const std::array<double, 3>& offset)
{
  const double speed = field.maxSpeed();
  const bp::GridGeometry& g = field.grid();
  float vorticity = 0.0f;
  int stride[3];
  for (int a = 0; a < 3; ++a)
    stride[a] = std::max(1, g.dims[a] / 32);
  for (int k = 0; k < g.dims[2]; k += stride[2])
    for (int j = 0; j < g.dims[1]; j += stride[1])
      for (int i = 0; i < g.dims[0]; i += stride[0])
      {
        const float q[3] = { float(g.coordinate(0, i)), float(g.coordinate(1, j)),
          float(g.coordinate(2, k)) };
        vorticity = std::max(vorticity, field.vorticityMagnitude(q, field.firstSlice().time));
      }
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const auto b = g.bounds();
  const double cu = 0.5 * (b[2 * u] + b[2 * u + 1]), cv = 0.5 * (b[2 * v] + b[2 * v + 1]);
  double radius = 0.0;
  for (int corner = 0; corner < 4; ++corner)
  {
    const double x = (corner & 1) ? p.emitterMax[u] : p.emitterMin[u];
    const double y = (corner & 2) ? p.emitterMax[v] : p.emitterMin[v];
    radius = std::max(radius, std::hypot(x - cu, y - cv));
  }
  return { { "Velocity", -speed, speed }, { "Speed", 0.0, speed },
    { "Vorticity", 0.0, double(vorticity) }, { "Force", 0.0, dt * speed },
    { "Lifetime", 0.0, double(p.lifetimeMax) },
    { "Layer", p.emitterMin[axis] + offset[axis], p.emitterMax[axis] + offset[axis] },
    { "Radius", 0.0, radius }, { "Normals", -1.0, 1.0 } };
}
} // namespace

struct vtkBoundParticleTracer::vtkInternals
{
  using Track = bp::TraceCursor;

  bp::Engine Engine;
  Track Cpu; // where Engine stands
  std::unique_ptr<bp::StepSchedule> Schedule;
  // Bumped whenever the filter or its input changes: a track made for an
  // older configuration replays.
  std::uint64_t Configuration = 1;
  const std::uint64_t ProducerId = nextProducerId();
  // This update's engine: the CPU one, or a GPU work queue.
  std::shared_ptr<bp::WorkQueue> Queue;
  Track* Active = &Cpu;
  // For the GPU output's summary points.
  std::vector<ExpectedRange> ExpectedRanges;
  int TemplateParticles = 1;
  bool ResetPending = false; // this update replays from the start
  double Target = 0.0;
  double StartTime = 0.0;

  bool Unsteady = false;
  std::vector<double> InputTimes; // unsteady input's time steps
  std::vector<double> OutputTimes;
  bp::GridGeometry Grid; // with its origin at 0: the engine works in grid-local coordinates
  std::array<double, 3> Offset = { 0, 0, 0 }; // world position of the grid's first point
  std::map<int, bp::FieldSlice> Slices;       // by input time index, at most three
  int RequestIndex = 0;
  int LastRequested = -1; // the input time step last asked for: what upstream holds
  bool Continuing = false;
  bool ReadThisUpdate = false; // a time step came from upstream in this update
  int IntervalAtStart = -1;    // the data interval shown before this update (-1: a replay)

  double ResolvedDt = 0.0;
  double ResolvedElementSize = 0.0;
  vtkIdType StepsInLastUpdate = 0;
  bool LastUpdateReplayed = false;

  // A distributed run (Pieces > 1): this process's piece of the field.
  vtkMultiProcessController* Controller = nullptr;
  int Piece = 0;
  int Pieces = 1;
  int RequestedPiece = 0; ///< the output piece asked for (without a controller)
  int GhostCells = 2;     ///< around the owned block; grown at a replay if too few
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int OwnedExtent[6] = { 0, -1, 0, -1, 0, -1 };
  std::unique_ptr<bp::Partition> Partition; ///< every piece's block, grid-local
  bp::Domain Domain;                        ///< the whole field's, grid-local
  double DomainCellLength = 1.0, DomainSmallestCell = 1.0;
  long long Migrated = 0; ///< elements this process sent away in the last update

  bool distributed() const { return this->Controller != nullptr; }

  /// The whole field's bounds in grid-local coordinates.
  std::array<double, 6> domainBounds() const
  {
    return this->distributed() && this->Partition ? this->Partition->domain() : this->Grid.bounds();
  }

  /// A step of a piece: resets first, so that an element reset into another
  /// piece moves there before it samples the field; then the exchange; then
  /// the step proper (which has nothing left to reset).
  void distributedStep(bp::Engine& engine, const bp::VectorField& field, double t, double h,
    const bp::RangeRunner& run)
  {
    engine.resetDue(run);
    std::string error;
    const long long left = bp::migrate(
      engine, *this->Partition, this->Piece, controllerExchange(this->Controller), error);
    this->Migrated += std::max(left, 0LL);
    if (!error.empty())
    {
      vtkGenericWarningMacro("Bound Particle Tracer: an element exchange failed: " << error);
    }
    engine.step(field, t, h, run);
  }

  /**
   * Gathers every process's block of the field (its owned extent's bounds)
   * into the Partition and the whole field's Domain, and sets `offset` to the
   * whole grid's first point. Collective; a process that could not read its
   * piece makes every process fail. Returns the error, if any.
   */
  std::string sharePieces(std::string error, const bp::GridGeometry& grid, const int extent[6],
    std::array<double, 3>& offset)
  {
    const int* owned = this->OwnedExtent;
    const bool owns = owned[0] <= owned[1] && owned[2] <= owned[3] && owned[4] <= owned[5];
    constexpr int Values = 8; // box, status, smallest cell width
    double mine[Values] = { 1, 0, 1, 0, 1, 0, 1, 0 };
    double smallest = std::numeric_limits<double>::infinity();
    for (int a = 0; a < 3 && error.empty(); ++a)
    {
      if (owns && (owned[2 * a] < extent[2 * a] || owned[2 * a + 1] > extent[2 * a + 1]))
      {
        std::ostringstream err;
        err << "The input delivered extent [" << extent[0] << " " << extent[1] << " " << extent[2]
            << " " << extent[3] << " " << extent[4] << " " << extent[5]
            << "], which lacks this process's block [" << owned[0] << " " << owned[1] << " "
            << owned[2] << " " << owned[3] << " " << owned[4] << " " << owned[5]
            << "]; the source must produce the extent it is asked for.";
        error = err.str();
        break;
      }
      if (owns)
      {
        mine[2 * a] = grid.coordinate(a, owned[2 * a] - extent[2 * a]);
        mine[2 * a + 1] = grid.coordinate(a, owned[2 * a + 1] - extent[2 * a]);
      }
      for (int i = 0; i + 1 < grid.dims[a]; ++i)
      {
        smallest = std::min(smallest, std::abs(grid.coordinate(a, i + 1) - grid.coordinate(a, i)));
        if (!grid.isRectilinear(a))
          break;
      }
    }
    mine[6] = error.empty() ? 1.0 : 0.0;
    mine[7] = smallest;
    std::vector<double> all(std::size_t(Values) * this->Pieces);
    this->Controller->AllGather(mine, all.data(), Values);
    std::vector<bp::Box> boxes(std::size_t(this->Pieces));
    this->DomainSmallestCell = std::numeric_limits<double>::infinity();
    for (int q = 0; q < this->Pieces; ++q)
    {
      const double* v = all.data() + std::size_t(q) * Values;
      if (v[6] == 0.0 && error.empty())
      {
        error = "Process " + std::to_string(q) +
          " could not read its piece of the input; see its error message.";
      }
      std::copy(v, v + 6, boxes[std::size_t(q)].begin());
      this->DomainSmallestCell = std::min(this->DomainSmallestCell, v[7]);
    }
    if (error.empty())
    {
      error = bp::Partition::validate(boxes);
      error =
        error.empty() ? error : "The processes' pieces of the input do not fit: " + error + ".";
    }
    if (!error.empty())
    {
      return error;
    }
    const bp::Box world = bp::Partition(boxes).domain();
    offset = { world[0], world[2], world[4] };
    for (bp::Box& b : boxes)
    {
      for (int k = 0; k < 6 && !bp::isEmptyBox(b); ++k)
        b[k] -= offset[std::size_t(k / 2)];
    }
    this->Partition.reset(new bp::Partition(boxes));
    const bp::Box& local = this->Partition->domain();
    double sum = 0.0;
    int axes = 0;
    for (int a = 0; a < 3; ++a)
    {
      const int cells = this->WholeExtent[2 * a + 1] - this->WholeExtent[2 * a];
      this->Domain.lower[a] = float(local[2 * a]);
      this->Domain.upper[a] = float(local[2 * a + 1]);
      this->Domain.degenerate[a] = cells < 1;
      if (cells >= 1)
      {
        sum += (local[2 * a + 1] - local[2 * a]) / cells;
        ++axes;
      }
    }
    this->DomainCellLength = axes > 0 ? sum / axes : 1.0;
    return std::string();
  }

  // The output's cells, built at each replay (they depend on the element
  // count and the shape only).
  vtkSmartPointer<vtkCellArray> Cells;
  vtkSmartPointer<vtkCellArray> LinkCells; ///< a super set's links, as lines
  int CellsKind = -1;                      // 0 vertices, 1 lines, 2 triangles
  std::size_t CellsElements = 0;

  double timeEpsilon() const
  {
    const double span =
      this->InputTimes.empty() ? 1.0 : this->InputTimes.back() - this->InputTimes.front();
    return 1e-9 * std::max(1.0, std::abs(span));
  }

  /**
   * Input time indices of the field around time t. Stepping forward from t
   * needs the interval that starts at t; showing the state at t needs only an
   * interval that contains it, and at a data time step the one that ends
   * there is the one already in hand.
   */
  std::vector<int> slicesFor(double t, bool forward) const
  {
    if (!this->Unsteady || this->InputTimes.size() < 2)
    {
      return { 0 };
    }
    const double eps = this->timeEpsilon();
    const auto begin = this->InputTimes.begin(), end = this->InputTimes.end();
    int k = forward ? int(std::upper_bound(begin, end, t + eps) - begin) - 1
                    : int(std::lower_bound(begin, end, t - eps) - begin) - 1;
    k = std::max(0, std::min(k, int(this->InputTimes.size()) - 2));
    return { k, k + 1 };
  }

  /// The slices the next piece of work needs: stepping on from `from`, or
  /// showing `target` once there.
  std::vector<int> slicesNeeded(double from, double target) const
  {
    const bool forward = from < target - this->timeEpsilon();
    return this->slicesFor(forward ? from : target, forward);
  }

  /// The requested time, clamped to the time range the filter offers.
  double targetOf(vtkInformation* outInfo) const
  {
    double target = this->StartTime;
    if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    {
      target = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
    }
    if (!std::isfinite(target))
    {
      target = this->StartTime;
    }
    return std::min(std::max(target, this->StartTime), this->OutputTimes.back());
  }

  /// Whether reaching `target` on the active track means replaying from the start.
  bool needsReplay(double target) const
  {
    const Track& t = *this->Active;
    return t.producer != this->ProducerId || t.configuration != this->Configuration || !t.valid ||
      target < t.committed - this->timeEpsilon();
  }

  /// Chooses this update's engine: the GPU work queue the request names when
  /// the GPU engine is selected and the queue is alive, else the CPU engine.
  void selectEngine(int engine, vtkInformation* outInfo)
  {
    this->Queue = nullptr;
    if (engine == GPU && !this->distributed() &&
      outInfo->Has(vtkBoundParticleTracer::GPU_WORK_QUEUE()))
    {
      this->Queue = FindWorkQueue(outInfo->Get(vtkBoundParticleTracer::GPU_WORK_QUEUE()));
    }
    this->Active = this->Queue ? &this->Queue->cursor : &this->Cpu;
  }

  /// Forgets every track (after a failure or an abort).
  void invalidate()
  {
    ++this->Configuration;
    this->Cpu.valid = false;
    if (this->Queue)
    {
      this->Queue->clear();
      this->Queue->cursor.valid = false;
    }
  }

  int firstMissing(const std::vector<int>& needed) const
  {
    for (int i : needed)
    {
      if (!this->Slices.count(i))
      {
        return i;
      }
    }
    return -1;
  }

  /**
   * Makes room for time step `index`: with three held, only those the work in
   * progress needs stay. Memory stays bounded at three time steps whatever
   * the pipeline asks for (a replay from the start, a jump).
   */
  void makeRoomFor(int index)
  {
    if (this->Slices.size() < 3)
    {
      return;
    }
    std::vector<int> keep = this->ResetPending
      ? this->slicesNeeded(this->StartTime, this->Target)
      : this->slicesNeeded(this->Active->committed, this->Target);
    keep.push_back(index);
    for (auto it = this->Slices.begin(); it != this->Slices.end();)
    {
      const bool needed = std::find(keep.begin(), keep.end(), it->first) != keep.end();
      it = needed ? std::next(it) : this->Slices.erase(it);
    }
  }

  /// The input time step after the interval shown at Target (-1 if none):
  /// the one the next update forward will need.
  int upcomingIndex() const
  {
    if (!this->Unsteady)
    {
      return -1;
    }
    const int next = this->slicesFor(this->Target, false).back() + 1;
    return next < int(this->InputTimes.size()) ? next : -1;
  }

  bp::VectorField field(const std::vector<int>& ids) const
  {
    if (ids.size() == 1)
    {
      return bp::VectorField(this->Grid, this->Slices.at(ids[0]));
    }
    return bp::VectorField(this->Grid, this->Slices.at(ids[0]), this->Slices.at(ids[1]));
  }

  void clear()
  {
    this->Cpu.valid = false;
    this->Slices.clear();
    this->Continuing = false;
  }
};

vtkStandardNewMacro(vtkBoundParticleTracer);

vtkBoundParticleTracer::vtkBoundParticleTracer()
  : Internals(new vtkInternals)
{
  preferThreadedBackend();
  this->SetNumberOfInputPorts(2);
  this->SetNumberOfOutputPorts(1);
  // By default the active point vectors (or, failing that, the first
  // 3-component point array).
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::VECTORS);
}

vtkBoundParticleTracer::~vtkBoundParticleTracer() = default;

double vtkBoundParticleTracer::GetSimulationTime() const
{
  return this->Internals->Target;
}
vtkIdType vtkBoundParticleTracer::GetStepsInLastUpdate() const
{
  return this->Internals->StepsInLastUpdate;
}
bool vtkBoundParticleTracer::GetLastUpdateReplayed() const
{
  return this->Internals->LastUpdateReplayed;
}
int vtkBoundParticleTracer::GetNumberOfCachedTimeSteps() const
{
  return int(this->Internals->Slices.size());
}
double vtkBoundParticleTracer::GetResolvedTimeStep() const
{
  return this->Internals->ResolvedDt;
}
double vtkBoundParticleTracer::GetResolvedElementSize() const
{
  return this->Internals->ResolvedElementSize;
}

int vtkBoundParticleTracer::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  // Any dataset is accepted here so that a wrong type gets an error that says
  // what to do, rather than the pipeline's generic type mismatch.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
  return 1;
}

void vtkBoundParticleTracer::SetTemplateData(vtkPolyData* shape)
{
  this->SetInputDataInternal(1, shape);
}

int vtkBoundParticleTracer::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& I = *this->Internals;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  // The pipeline asks for information again only when this filter or
  // something upstream changed: the cached state is stale.
  I.invalidate();
  I.clear();

  I.InputTimes.clear();
  I.LastRequested = -1;
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()))
  {
    const double* steps = inInfo->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    const int count = inInfo->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    I.InputTimes.assign(steps, steps + count);
  }
  // One time step is no flow in time: treat it as steady.
  I.Unsteady = I.InputTimes.size() >= 2;
  I.OutputTimes.clear();
  if (I.Unsteady)
  {
    I.OutputTimes = I.InputTimes;
  }
  else
  {
    if (!(this->Duration > 0.0) || !std::isfinite(this->Duration) || this->NumberOfTimeSteps < 2 ||
      this->NumberOfTimeSteps > 100000)
    {
      vtkErrorMacro("For a steady input, Duration must be positive and finite and "
                    "NumberOfTimeSteps between 2 and 100000 (they are "
        << this->Duration << " and " << this->NumberOfTimeSteps << ").");
      outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
      outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
      return 1;
    }
    for (int k = 0; k < this->NumberOfTimeSteps; ++k)
    {
      I.OutputTimes.push_back(this->Duration * k / (this->NumberOfTimeSteps - 1));
    }
  }
  I.StartTime = I.OutputTimes.front();
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), I.OutputTimes.data(),
    int(I.OutputTimes.size()));
  const double range[2] = { I.OutputTimes.front(), I.OutputTimes.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  return 1;
}

int vtkBoundParticleTracer::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& I = *this->Internals;
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);

  // Pieces: one block of the grid each, with ghost layers, when the pipeline
  // asks for as many pieces as there are processes; otherwise piece 0 traces
  // the whole field and other pieces are empty.
  const int pieces = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES())
    : 1;
  I.RequestedPiece = outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    ? outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER())
    : 0;
  vtkMultiProcessController* controller = pieceController(pieces);
  if (controller != I.Controller || (controller && I.Piece != I.RequestedPiece))
  {
    // A change of pieces is a change of input: replay.
    I.invalidate();
    I.clear();
    I.LastRequested = -1;
  }
  I.Controller = controller;
  I.Pieces = controller ? pieces : 1;
  I.Piece = controller ? I.RequestedPiece : 0;
  if (inInfo->Has(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT()))
  {
    // The whole extent: in parallel, the executive of a source that can
    // produce sub-extents splits it by piece (blocks, as below) and adds the
    // ghost layers.
    int* whole = inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT());
    std::copy(whole, whole + 6, I.WholeExtent);
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), whole, 6);
    if (!I.distributed())
    {
      // Piece 0 traces the whole field (see above): ask for all of it.
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    }
    else
    {
      inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), I.GhostCells);
      vtkNew<vtkExtentTranslator> translator;
      if (!translator->PieceToExtentThreadSafe(
            I.Piece, I.Pieces, 0, whole, I.OwnedExtent, vtkExtentTranslator::BLOCK_MODE, 0))
      {
        // More processes than blocks: this one owns nothing.
        for (int a = 0; a < 3; ++a)
        {
          I.OwnedExtent[2 * a] = whole[2 * a] + 1;
          I.OwnedExtent[2 * a + 1] = whole[2 * a];
        }
      }
    }
  }

  if (!I.Continuing && !I.OutputTimes.empty())
  {
    // A new update. Only choose what to ask upstream for here: the pipeline may
    // ask for an update extent without executing, so the state changes wait
    // for RequestData, which makes the same decision.
    I.selectEngine(this->Engine, outInfo);
    const double target = I.targetOf(outInfo);
    const bool replay = I.needsReplay(target);
    const std::vector<int> needed =
      I.slicesNeeded(replay ? I.StartTime : I.Active->committed, target);
    const int missing = I.firstMissing(needed);
    // With every time step in hand, ask for the one upstream already holds,
    // so that nothing upstream runs again (a reader would read, ParaView
    // would gather its data information).
    I.RequestIndex = missing >= 0 ? missing
      : I.LastRequested >= 0      ? I.LastRequested
                                  : needed.back();
  }

  // The GPU request concerns this filter only. The pipeline copies request
  // keys upstream with every update-extent request; left there, each
  // alternation between the GPU display and another consumer would make
  // every algorithm upstream run again (a reader re-read its time step and
  // ParaView gathered its data information, every frame).
  inInfo->Remove(vtkBoundParticleTracer::GPU_WORK_QUEUE());
  if (I.Unsteady)
  {
    inInfo->Set(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP(), I.InputTimes[I.RequestIndex]);
    I.LastRequested = I.RequestIndex;
  }
  else
  {
    inInfo->Remove(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }
  return 1;
}

namespace
{
/// Reads `vectors` (the selected array, or null) of `input` into a slice;
/// empty on success, otherwise what the user should fix.
std::string readSlice(vtkDataObject* input, vtkDataArray* vectors, int association,
  bp::GridGeometry& grid, bp::FieldSlice& slice, int extent[6])
{
  std::ostringstream err;
  vtkImageData* image = vtkImageData::SafeDownCast(input);
  vtkRectilinearGrid* rectilinear = vtkRectilinearGrid::SafeDownCast(input);
  vtkDataSet* dataSet = image ? static_cast<vtkDataSet*>(image) : rectilinear;
  if (!dataSet)
  {
    err << "The input is a " << (input ? input->GetClassName() : "null data object")
        << "; Bound Particle Tracer needs a vtkImageData (a uniform grid) or a "
           "vtkRectilinearGrid. Resample the data onto an image first, e.g. with the Resample To "
           "Image filter.";
    return err.str();
  }
  if (dataSet->GetNumberOfPoints() == 0)
  {
    return "The input grid is empty: it has no points.";
  }
  const int* dataExtent = image ? image->GetExtent() : rectilinear->GetExtent();
  std::copy(dataExtent, dataExtent + 6, extent);
  if (!vectors && association == vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    // No array chosen and no active vectors: take the first 3-component point array.
    vtkPointData* pd = dataSet->GetPointData();
    for (int i = 0; i < pd->GetNumberOfArrays() && !vectors; ++i)
    {
      vtkDataArray* candidate = pd->GetArray(i);
      if (candidate && candidate->GetNumberOfComponents() == 3)
      {
        vectors = candidate;
      }
    }
  }
  if (!vectors)
  {
    return "The input has no point vector array. Select a 3-component point array with the "
           "Vectors property (pvpython: Vectors = ['POINTS', 'name']).";
  }
  const char* name = vectors->GetName() ? vectors->GetName() : "(unnamed)";
  if (association != vtkDataObject::FIELD_ASSOCIATION_POINTS)
  {
    err << "The array '" << name
        << "' is not point data; choose a point array (or apply Cell Data to Point Data).";
    return err.str();
  }
  if (vectors->GetNumberOfComponents() != 3)
  {
    err << "The array '" << name << "' has " << vectors->GetNumberOfComponents()
        << " component(s); Bound Particle Tracer needs a 3-component vector array.";
    return err.str();
  }
  if (vectors->GetNumberOfTuples() != dataSet->GetNumberOfPoints())
  {
    err << "The array '" << name << "' has " << vectors->GetNumberOfTuples() << " tuples for "
        << dataSet->GetNumberOfPoints() << " points.";
    return err.str();
  }
  bp::GridGeometry g;
  if (image)
  {
    if (!image->GetDirectionMatrix()->IsIdentity())
    {
      return "The input image is rotated (its direction matrix is not the identity); Bound "
             "Particle Tracer needs an axis-aligned grid. Resample it with Resample To Image.";
    }
    // Point 0 of an image lies at origin + extent_min * spacing (e.g. after Extract Subset).
    const int* extent = image->GetExtent();
    image->GetDimensions(g.dims.data());
    image->GetOrigin(g.origin.data());
    image->GetSpacing(g.spacing.data());
    for (int a = 0; a < 3; ++a)
    {
      g.origin[a] += extent[2 * a] * g.spacing[a];
    }
  }
  else
  {
    vtkDataArray* axes[3] = { rectilinear->GetXCoordinates(), rectilinear->GetYCoordinates(),
      rectilinear->GetZCoordinates() };
    int dims[3];
    rectilinear->GetDimensions(dims);
    for (int a = 0; a < 3; ++a)
    {
      if (!axes[a] || axes[a]->GetNumberOfTuples() != dims[a])
      {
        err << "The rectilinear grid's "
            << "XYZ"[a] << " coordinates do not match its " << dims[a]
            << " points along that axis.";
        return err.str();
      }
      std::vector<double> c(std::size_t(dims[a]));
      for (int i = 0; i < dims[a]; ++i)
      {
        c[std::size_t(i)] = axes[a]->GetComponent(i, 0);
      }
      // Evenly spaced axes are sampled the uniform way: fewer operations, and
      // images and rectilinear grids of the same points trace alike.
      bool even = c.size() > 1;
      const double h = even ? (c.back() - c.front()) / double(c.size() - 1) : 1.0;
      for (std::size_t i = 1; even && i < c.size(); ++i)
      {
        even = std::abs((c[i] - c[i - 1]) - h) <= 1e-6 * std::abs(h);
      }
      if (even)
      {
        g.dims[a] = dims[a];
        g.origin[a] = c.front();
        g.spacing[a] = h;
      }
      else if (c.size() == 1)
      {
        g.dims[a] = 1;
        g.origin[a] = c.front();
      }
      else
      {
        g.setCoordinates(a, std::move(c));
      }
    }
  }
  auto values = std::make_shared<std::vector<float>>();
  using Dispatch = vtkArrayDispatch::DispatchByValueType<vtkArrayDispatch::AllTypes>;
  if (!Dispatch::Execute(vectors, CopyToFloat{}, *values))
  {
    CopyToFloat{}(vectors, *values);
  }
  slice.velocity = values;
  grid = g;
  return std::string();
}

/// The element template of a polydata; empty on success, otherwise what is wrong.
std::string templateFromPolyData(vtkPolyData* mesh, bp::MeshSprings mode, bp::ElementTemplate& out)
{
  if (!mesh || mesh->GetNumberOfPoints() == 0)
  {
    return "The Element Template input has no points.";
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  std::vector<std::array<float, 3>> points(n);
  for (vtkIdType i = 0; i < n; ++i)
  {
    double x[3];
    mesh->GetPoint(i, x);
    points[i] = { float(x[0]), float(x[1]), float(x[2]) };
  }
  std::vector<std::array<std::uint32_t, 3>> triangles;
  vtkIdType count;
  const vtkIdType* ids;
  auto polys = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (polys->GoToFirstCell(); !polys->IsDoneWithTraversal(); polys->GoToNextCell())
  {
    polys->GetCurrentCell(count, ids);
    for (vtkIdType k = 1; k + 1 < count; ++k) // a fan over each polygon
    {
      triangles.push_back(
        { std::uint32_t(ids[0]), std::uint32_t(ids[k]), std::uint32_t(ids[k + 1]) });
    }
  }
  auto strips = vtk::TakeSmartPointer(mesh->GetStrips()->NewIterator());
  for (strips->GoToFirstCell(); !strips->IsDoneWithTraversal(); strips->GoToNextCell())
  {
    strips->GetCurrentCell(count, ids);
    for (vtkIdType k = 0; k + 2 < count; ++k) // every other triangle turned round
    {
      const auto a = std::uint32_t(ids[k]), b = std::uint32_t(ids[k + 1]),
                 c = std::uint32_t(ids[k + 2]);
      triangles.push_back(
        k % 2 ? std::array<std::uint32_t, 3>{ b, a, c } : std::array<std::uint32_t, 3>{ a, b, c });
    }
  }
  std::vector<std::array<std::uint32_t, 2>> springs;
  std::vector<float> stiffness;
  vtkDataArray* stiffnessArray = mesh->GetCellData()->GetArray("Stiffness");
  const vtkIdType firstLine = mesh->GetNumberOfVerts();
  vtkIdType line = 0;
  auto lines = vtk::TakeSmartPointer(mesh->GetLines()->NewIterator());
  for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++line)
  {
    lines->GetCurrentCell(count, ids);
    const float k =
      stiffnessArray ? float(stiffnessArray->GetComponent(firstLine + line, 0)) : 1.0f;
    for (vtkIdType j = 0; j + 1 < count; ++j)
    {
      springs.push_back({ std::uint32_t(ids[j]), std::uint32_t(ids[j + 1]) });
      stiffness.push_back(k);
    }
  }
  if (springs.empty())
  {
    springs = bp::meshSprings(std::size_t(n), triangles, mode);
    stiffness.assign(springs.size(), 1.0f);
  }
  out = bp::makeTemplate("Element Template", points, triangles, springs);
  for (std::size_t k = 0; k < out.springs.size() && k < stiffness.size(); ++k)
  {
    out.springs[k].stiffness = stiffness[k];
  }
  if (vtkDataArray* pinned = mesh->GetPointData()->GetArray("Pinned"))
  {
    out.pinned.assign(std::size_t(n), 0);
    for (vtkIdType i = 0; i < n; ++i)
    {
      out.pinned[i] = pinned->GetComponent(i, 0) != 0.0 ? 1 : 0;
    }
  }
  const std::string error = out.validate();
  return error.empty() ? error : "The Element Template input is unusable: " + error + ".";
}

/// A line per link of a super set: particle i of an element to particle i of
/// its neighbour, each link once.
vtkSmartPointer<vtkCellArray> buildLinkCells(const bp::LinkTable& links, std::size_t n)
{
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(vtkIdType(2 * links.linkCount() * n));
  vtkIdType* out = connectivity->GetPointer(0);
  const std::size_t elements = links.sites.size() / 3;
  for (std::size_t e = 0; e < elements; ++e)
  {
    for (int d : { 0, 2 }) // +u and +v: each link once
    {
      const std::int32_t f = links.neighbours[bp::LinkDirections * e + d];
      for (std::size_t i = 0; f >= 0 && i < n; ++i)
      {
        *out++ = vtkIdType(e * n + i);
        *out++ = vtkIdType(std::size_t(f) * n + i);
      }
    }
  }
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(2, connectivity);
  return cells;
}

vtkSmartPointer<vtkCellArray> buildCells(
  const bp::ElementTemplate& shape, std::size_t elements, int& kind)
{
  const std::size_t n = shape.particleCount();
  int cellSize;
  std::vector<std::uint32_t> local;
  if (!shape.triangles.empty())
  {
    kind = 2;
    cellSize = 3;
    for (const auto& t : shape.triangles)
      local.insert(local.end(), t.begin(), t.end());
  }
  else if (!shape.springs.empty())
  {
    kind = 1;
    cellSize = 2;
    for (const auto& s : shape.springs)
    {
      local.push_back(s.a);
      local.push_back(s.b);
    }
  }
  else
  {
    kind = 0;
    cellSize = 1;
    for (std::size_t i = 0; i < n; ++i)
      local.push_back(std::uint32_t(i));
  }
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(vtkIdType(local.size() * elements));
  vtkIdType* out = connectivity->GetPointer(0);
  vtkSMPTools::For(vtkIdType(0), vtkIdType(elements),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const vtkIdType offset = e * vtkIdType(n);
        vtkIdType* o = out + e * vtkIdType(local.size());
        for (std::size_t k = 0; k < local.size(); ++k)
          o[k] = offset + local[k];
      }
    });
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(cellSize, connectivity);
  return cells;
}

vtkSmartPointer<vtkFloatArray> floatArray(const char* name, int components, vtkIdType tuples)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  return a;
}
} // namespace

int vtkBoundParticleTracer::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInternals& I = *this->Internals;
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outInfo);
  vtkDataObject* input = vtkDataObject::GetData(inputVector[0], 0);
  output->Initialize();

  auto fail = [&](const std::string& message)
  {
    vtkErrorMacro(<< message);
    I.clear();
    I.invalidate();
    request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
    output->Initialize();
    return 1;
  };
  if (I.OutputTimes.empty())
  {
    return fail("The filter has no time range; see the previous error.");
  }
  if (!I.distributed() && I.RequestedPiece != 0)
  {
    // Asked for a piece of several with no process per piece: piece 0 holds
    // the whole trace.
    return 1;
  }

  if (!I.Continuing)
  {
    // The first pass of an update: replay from the start, or continue.
    I.selectEngine(this->Engine, outInfo);
    I.Target = I.targetOf(outInfo);
    I.ResetPending = I.needsReplay(I.Target);
    I.StepsInLastUpdate = 0;
    I.Migrated = 0;
    I.LastUpdateReplayed = I.ResetPending;
    I.ReadThisUpdate = false;
    I.IntervalAtStart =
      I.ResetPending || !I.Unsteady ? -1 : I.slicesFor(I.Active->committed, false).front();
    if (!I.ResetPending && I.Queue && I.Active->showsPartialStep)
    {
      // Take back the short step the last update showed, as the CPU path
      // steps a copy.
      I.Queue->restore();
      I.Active->showsPartialStep = false;
    }
    if (I.ResetPending && I.distributed() && I.Piece == 0 && this->Engine == GPU)
    {
      vtkWarningMacro("The GPU engine runs in one process; with "
        << I.Pieces
        << " processes the CPU engine traces and the Bound Particles display draws its "
           "particles on every process.");
    }
    if (I.ResetPending)
    {
      I.Active->valid = false;
      // A steady input's single slice is read again at every replay; an
      // unsteady input's slices stay valid (RequestInformation drops them when
      // the input changes).
      if (!I.Unsteady)
      {
        I.Slices.clear();
      }
    }
  }

  // Take the time step this pass asked for, if the work needs it: a first
  // pass with every time step in hand asked for whatever upstream held.
  const std::vector<int> planned = I.ResetPending ? I.slicesNeeded(I.StartTime, I.Target)
                                                  : I.slicesNeeded(I.Active->committed, I.Target);
  const bool wanted =
    I.Continuing || std::find(planned.begin(), planned.end(), I.RequestIndex) != planned.end();
  if (wanted && !I.Slices.count(I.RequestIndex))
  {
    bp::GridGeometry grid;
    bp::FieldSlice slice;
    int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
    vtkDataArray* vectors =
      input ? this->GetInputArrayToProcess(0, inputVector, association) : nullptr;
    int extent[6];
    std::string error = readSlice(input, vectors, association, grid, slice, extent);
    std::array<double, 3> offset = grid.origin;
    if (I.distributed())
    {
      // Every process reads in this pass: agree on the pieces (and fail together).
      error = I.sharePieces(error, grid, extent, offset);
    }
    if (!error.empty())
    {
      return fail(error);
    }
    slice.time = I.Unsteady ? I.InputTimes[I.RequestIndex] : 0.0;
    if (I.Unsteady && input->GetInformation()->Has(vtkDataObject::DATA_TIME_STEP()))
    {
      const double delivered = input->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
      if (std::abs(delivered - slice.time) > I.timeEpsilon())
      {
        vtkWarningMacro("Asked the input for time " << slice.time << " but it delivered time "
                                                    << delivered << "; using it as time "
                                                    << slice.time << ".");
      }
    }
    // The engine works in coordinates relative to the grid's first point (the
    // whole grid's, in parallel), so float positions keep their precision far
    // from the world origin.
    grid.translate(offset);
    if (!I.Slices.empty())
    {
      const double tolerance = 1e-9 * std::max(1.0, I.Grid.diagonal());
      bool same = grid.sameAs(I.Grid, tolerance);
      for (int a = 0; a < 3; ++a)
      {
        same = same && std::abs(offset[a] - I.Offset[a]) <= tolerance;
      }
      if (!same)
      {
        return fail("The input's time steps do not share one grid; every time step must have "
                    "the same dimensions and point coordinates.");
      }
    }
    I.Offset = offset;
    I.Grid = grid;
    const std::string gridError = grid.validate();
    if (!gridError.empty())
    {
      return fail("Unusable input: " + gridError + ".");
    }
    const std::string fieldError = bp::VectorField(grid, slice).validate();
    if (!fieldError.empty())
    {
      return fail("Unusable input: " + fieldError + ".");
    }
    I.makeRoomFor(I.RequestIndex);
    I.Slices[I.RequestIndex] = slice;
    I.ReadThisUpdate = true;
  }

  auto continueWith = [&](int index)
  {
    I.RequestIndex = index;
    I.Continuing = true;
    request->Set(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING(), 1);
    return 1;
  };

  if (I.ResetPending)
  {
    const std::vector<int> ids = I.slicesNeeded(I.StartTime, I.Target);
    const int missing = I.firstMissing(ids);
    if (missing >= 0)
    {
      return continueWith(missing);
    }
    const bp::VectorField field = I.field(ids);
    const bp::GridGeometry& grid = I.Grid;
    // The whole field's, also in parallel where this process holds a piece.
    const auto bounds = I.domainBounds();
    const double cell = I.distributed() ? I.DomainCellLength : grid.cellLength();
    const double diagonal = std::sqrt(std::pow(bounds[1] - bounds[0], 2) +
      std::pow(bounds[3] - bounds[2], 2) + std::pow(bounds[5] - bounds[4], 2));
    double speed = field.maxSpeed();
    if (I.distributed())
    {
      double global = speed;
      I.Controller->AllReduce(&speed, &global, 1, vtkCommunicator::MAX_OP);
      speed = global;
    }

    if (!(this->StepSize > 0.0) || !std::isfinite(this->StepSize))
    {
      return fail("StepSize must be positive (it is " + std::to_string(this->StepSize) + ").");
    }
    const double fieldSpeed = speed;
    if (!(speed > 0.0))
    {
      vtkWarningMacro("The vector field is zero everywhere at the start time; elements will "
                      "not move until it is not.");
      speed = 1.0;
    }
    I.ResolvedDt =
      this->StepSizeUnit == CELL_LENGTH ? this->StepSize * cell / speed : this->StepSize;
    if (this->ElementSize < 0.0 || !std::isfinite(this->ElementSize))
    {
      return fail("ElementSize must be positive, or 0 for automatic.");
    }
    I.ResolvedElementSize =
      this->ElementSize > 0.0 ? this->ElementSize : std::max(2.0 * cell, diagonal / 40.0);
    if (I.distributed())
    {
      // Enough ghost layers for an element and a step at twice the start's
      // largest speed (an unsteady flow may speed up); if the pieces in hand
      // have fewer, ask for them again with more. Every process computes the
      // same number from the same global values.
      const int needed = bp::ghostCellsNeeded(
        I.ResolvedElementSize, 2.0 * fieldSpeed, I.ResolvedDt, I.DomainSmallestCell);
      if (needed > I.GhostCells)
      {
        I.GhostCells = needed;
        I.Slices.clear();
        return continueWith(ids.front());
      }
      if (this->Linking != NO_LINKING)
      {
        return fail("Super sets (Linking) run in one process; in parallel (" +
          std::to_string(I.Pieces) + " processes) set Linking to None.");
      }
    }

    if (this->NumberOfElements < 1)
    {
      return fail("NumberOfElements must be at least 1 (it is " +
        std::to_string(this->NumberOfElements) + ").");
    }
    bp::Parameters p;
    p.numberOfElements = std::size_t(this->NumberOfElements);
    p.elementSize = float(I.ResolvedElementSize);
    for (int a = 0; a < 3; ++a)
    {
      // The user's box is in world coordinates; the engine's is grid-local.
      const bool whole = this->EmitterSize[a] < 0.0;
      const double center = this->EmitterCenter[a] - I.Offset[a];
      const double lo = whole ? bounds[2 * a] : center - 0.5 * this->EmitterSize[a];
      const double hi = whole ? bounds[2 * a + 1] : center + 0.5 * this->EmitterSize[a];
      p.emitterMin[a] = float(lo);
      p.emitterMax[a] = float(hi);
      if (this->ResetWhen == ANY_PARTICLE_LEAVES && grid.dims[a] > 1)
      {
        // Placed whole inside the field, so no particle is ever advected from
        // outside it: keep centres one element radius from the bounds.
        const double r = 0.5 * I.ResolvedElementSize;
        const double inLo = bounds[2 * a] + r, inHi = bounds[2 * a + 1] - r;
        if (inLo > inHi)
        {
          vtkWarningMacro("Elements of size "
            << I.ResolvedElementSize << " do not fit in the field along "
            << "XYZ"[a]
            << "; with Reset When = Any Particle Leaves they are "
               "reset every step. Choose a smaller Element Size.");
        }
        else
        {
          p.emitterMin[a] = float(std::min(std::max(lo, inLo), inHi));
          p.emitterMax[a] = float(std::max(std::min(hi, inHi), inLo));
        }
      }
    }
    p.randomOrientation = this->RandomOrientation != 0;
    for (double angle : this->ElementRotation)
    {
      if (!std::isfinite(angle))
      {
        return fail("ElementRotation must be finite.");
      }
    }
    p.frame = bp::rotationFromDegrees(
      this->ElementRotation[0], this->ElementRotation[1], this->ElementRotation[2]);
    double lifetime[2] = { this->LifetimeRange[0], this->LifetimeRange[1] };
    if (lifetime[0] == 0.0 && lifetime[1] == 0.0)
    {
      const double span = I.OutputTimes.back() - I.OutputTimes.front();
      const double scale = span > 0.0 ? span : 100.0 * I.ResolvedDt;
      lifetime[0] = 0.5 * scale;
      lifetime[1] = scale;
    }
    p.lifetimeMin = float(lifetime[0]);
    p.lifetimeMax = float(lifetime[1]);
    p.integrator = bp::Integrator(this->Integrator);
    p.restoration = bp::Restoration(this->Restoration);
    p.iterations = this->RestorationIterations;
    p.relaxation = float(this->RelaxationFactor);
    p.shapeStiffness = float(this->ShapeMatchingStiffness);
    p.linearShapeMatching = this->ShapeMatchingMode == LINEAR;
    p.linearBlend = float(this->LinearShapeMatchingBeta);
    p.linking = bp::Linking(this->Linking);
    p.latticeWidth = this->LatticeWidth;
    p.linkStiffness = float(this->LinkStiffness);
    p.resetWhen = bp::ResetWhen(this->ResetWhen);
    p.seed = std::uint32_t(this->Seed);

    bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape(this->ElementShape));
    if (this->GetNumberOfInputConnections(1) > 0)
    {
      const std::string templateError = templateFromPolyData(
        vtkPolyData::GetData(inputVector[1], 0), bp::MeshSprings(this->TemplateSprings), shape);
      if (!templateError.empty())
      {
        return fail(templateError);
      }
    }
    if (I.Queue)
    {
      const std::string error = bp::Engine::validate(shape, p);
      if (!error.empty())
      {
        return fail(error + ".");
      }
      const bp::ParticleLayout layout =
        bp::ParticleLayout::of(p.numberOfElements, shape.particleCount());
      const int maxSize = I.Queue->maxTextureSize;
      if (maxSize > 0 && (layout.width > maxSize || layout.height > maxSize))
      {
        // The display falls back to the CPU result, from this update on.
        const std::string message = std::to_string(p.numberOfElements) + " elements of " +
          std::to_string(shape.particleCount()) + " particles need a " +
          std::to_string(layout.width) + " x " + std::to_string(layout.height) +
          " GPU state texture, beyond this GPU's limit of " + std::to_string(maxSize) +
          " texels; the CPU engine runs this trace instead. Use fewer elements to run it on "
          "the GPU.";
        vtkErrorMacro(<< message);
        I.Queue->clear();
        I.Queue->cursor.valid = false;
        I.Queue->failure = message;
        I.Queue = nullptr;
        I.Active = &I.Cpu;
      }
    }
    if (I.Queue)
    {
      I.TemplateParticles = int(shape.particleCount());
      I.ExpectedRanges = expectedRanges(field, p, I.ResolvedDt, this->ColoringAxis, I.Offset);
      I.Queue->clear();
      I.Queue->configure(shape, p);
      I.Queue->setField(field);
      I.Queue->initialize();
      I.Active->showsPartialStep = false;
    }
    else
    {
      const std::string error = I.Engine.configure(shape, p);
      if (!error.empty())
      {
        return fail(error + ".");
      }
      I.Engine.initialize(smpRunner());
      if (I.distributed())
      {
        I.Engine.setDomain(I.Domain);
        bp::keepOwned(I.Engine, *I.Partition, I.Piece);
      }
      I.Cells = nullptr; // the element count or shape may have changed
    }
    I.Schedule.reset(new bp::StepSchedule(
      I.StartTime, I.ResolvedDt, I.Unsteady ? I.InputTimes : std::vector<double>()));
    I.Active->committed = I.StartTime;
    I.Active->valid = true;
    I.Active->configuration = I.Configuration;
    I.Active->producer = I.ProducerId;
    I.ResetPending = false;
  }

  // Step forward one data interval at a time.
  double& committed = I.Active->committed;
  const double span = std::max(I.Target - committed, 1e-300);
  const double progressStart = committed;
  bool aborted = false;
  auto keepGoing = [&](double t)
  {
    ++I.StepsInLastUpdate;
    this->UpdateProgress((t - progressStart) / span);
    // In parallel every process must take every step (each exchanges
    // elements with the others), so one process alone cannot stop.
    aborted = !I.distributed() && this->CheckAbort();
    return !aborted;
  };
  const bp::RangeRunner run = smpRunner();
  while (true)
  {
    const std::vector<int> ids = I.slicesNeeded(committed, I.Target);
    const int missing = I.firstMissing(ids);
    if (missing >= 0)
    {
      // Drop what no later step needs before asking for the next time step.
      for (auto it = I.Slices.begin(); it != I.Slices.end();)
        it = it->first < ids.front() ? I.Slices.erase(it) : std::next(it);
      return continueWith(missing);
    }
    const bp::VectorField field = I.field(ids);
    const double intervalEnd = ids.size() == 2 ? I.InputTimes[ids[1]] : I.Target;
    const double limit = std::min(I.Target, intervalEnd);
    const double before = committed;
    if (I.Queue)
    {
      I.Queue->setField(field);
      committed = bp::advance(
        *I.Schedule, committed, limit, [&](double t, double h) { I.Queue->step(t, h); }, keepGoing);
    }
    else if (I.distributed())
    {
      committed = bp::advance(
        *I.Schedule, committed, limit,
        [&](double t, double h) { I.distributedStep(I.Engine, field, t, h, run); }, keepGoing);
    }
    else
    {
      committed = bp::advance(I.Engine, field, *I.Schedule, committed, limit, run, keepGoing);
    }
    if (aborted)
    {
      I.clear();
      I.invalidate();
      request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());
      return 1;
    }
    if (limit >= I.Target || committed < intervalEnd - I.Schedule->epsilon())
    {
      break;
    }
    if (committed == before)
    {
      // Never spin: the schedule lands on every data time step, so this is a bug.
      return fail("Time stepping made no progress at t = " + std::to_string(before) +
        "; please report this with the input's time steps.");
    }
  }
  // The output at Target: the committed state, finished with a shorter step
  // on a copy when Target falls between two step boundaries, so that the
  // cache stays on the boundaries.
  if (I.Queue)
  {
    // Read the time step after this interval ahead of need, so the display
    // can upload it a slab per frame before a step crosses into it. Only in
    // an update that stays in its interval and read nothing: a frame that
    // crosses a time step has had its share.
    const int upcoming = I.Queue->streamTimeSteps ? I.upcomingIndex() : -1;
    const bool quietFrame =
      !I.ReadThisUpdate && I.IntervalAtStart == I.slicesFor(I.Target, false).front();
    if (upcoming >= 0 && !I.Slices.count(upcoming) && quietFrame)
    {
      return continueWith(upcoming);
    }
    I.Queue->upcoming =
      upcoming >= 0 && I.Slices.count(upcoming) ? I.Slices.at(upcoming) : bp::FieldSlice();
  }
  I.Continuing = false;
  request->Remove(vtkStreamingDemandDrivenPipeline::CONTINUE_EXECUTING());

  const bp::VectorField field = I.field(I.slicesFor(I.Target, false));
  if (I.Queue)
  {
    I.Queue->setField(field);
    if (I.Target - committed > I.Schedule->epsilon())
    {
      I.Queue->save();
      I.Queue->step(committed, I.Target - committed);
      I.Active->showsPartialStep = true;
      ++I.StepsInLastUpdate;
    }
    this->UpdateProgress(1.0);
    this->FillGpuOutput(output);
    return 1;
  }
  bp::Engine* shown = &I.Engine;
  bp::Engine partial;
  if (I.Target - committed > I.Schedule->epsilon())
  {
    partial = I.Engine;
    if (I.distributed())
    {
      I.distributedStep(partial, field, committed, I.Target - committed, run);
    }
    else
    {
      partial.step(field, committed, I.Target - committed, run);
    }
    ++I.StepsInLastUpdate;
    shown = &partial;
  }
  shown->updateNormals(run);
  this->UpdateProgress(1.0);

  // Assemble the polydata.
  const bp::Engine& engine = *shown;
  const std::size_t E = engine.elementCount(), n = engine.particlesPerElement();
  const vtkIdType N = vtkIdType(engine.particleCount());

  // World positions: grid-local ones plus the grid's offset, in double where
  // float would lose more than 1e-4 of a cell at the field's coordinates.
  vtkNew<vtkPoints> points;
  const auto localBounds = I.Grid.bounds();
  double reach = 0.0;
  for (int a = 0; a < 3; ++a)
  {
    reach = std::max(reach, std::abs(I.Offset[a]) + std::abs(localBounds[2 * a + 1]));
  }
  if (reach * std::ldexp(1.0, -23) > 1e-4 * I.Grid.cellLength())
  {
    points->SetDataTypeToDouble();
  }
  points->SetNumberOfPoints(N);
  vtkDataArray* coords = points->GetData();
  const float* local = engine.positions().data();
  const double offset[3] = { I.Offset[0], I.Offset[1], I.Offset[2] };
  vtkSMPTools::For(vtkIdType(0), N,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType id = begin; id < end; ++id)
      {
        for (int c = 0; c < 3; ++c)
        {
          coords->SetComponent(id, c, double(local[3 * id + c]) + offset[c]);
        }
      }
    });
  output->SetPoints(points);

  if (!I.Cells || I.CellsElements != E)
  {
    I.CellsElements = E; // in parallel, the count changes as elements move
    I.Cells = buildCells(engine.shape(), E, I.CellsKind);
    I.LinkCells = engine.links().empty() ? nullptr : buildLinkCells(engine.links(), n);
    if (I.LinkCells && I.CellsKind == 1)
    {
      // Springs drawn as lines: the links join them in the one line array.
      I.Cells->Append(I.LinkCells);
    }
  }
  switch (I.CellsKind)
  {
    case 0:
      output->SetVerts(I.Cells);
      break;
    case 1:
      output->SetLines(I.Cells);
      break;
    default:
      output->SetPolys(I.Cells);
  }
  if (I.LinkCells && I.CellsKind != 1)
  {
    output->SetLines(I.LinkCells);
  }

  vtkPointData* pd = output->GetPointData();
  auto normals = floatArray("Normals", 3, N);
  std::memcpy(normals->GetPointer(0), engine.normals().data(), sizeof(float) * 3 * N);
  auto velocity = floatArray("Velocity", 3, N);
  vtkSmartPointer<vtkFloatArray> vorticity =
    this->ComputeVorticity ? floatArray("Vorticity", 1, N) : nullptr;
  bp::sampleAtPositions(field, I.Target, engine.positions().data(), std::size_t(N),
    velocity->GetPointer(0), vorticity ? vorticity->GetPointer(0) : nullptr, run);
  auto speed = floatArray("Speed", 1, N);
  auto force = floatArray("Force", 1, N);
  std::memcpy(force->GetPointer(0), engine.forces().data(), sizeof(float) * N);
  auto lifetime = floatArray("Lifetime", 1, N);
  auto layer = floatArray("Layer", 1, N);
  auto radius = floatArray("Radius", 1, N);
  vtkNew<vtkIdTypeArray> elementId;
  elementId->SetName("ElementId");
  elementId->SetNumberOfValues(N);
  vtkNew<vtkIntArray> particleIndex;
  particleIndex->SetName("ParticleIndex");
  particleIndex->SetNumberOfValues(N);

  const auto bounds = I.domainBounds();
  const int axis = this->ColoringAxis;
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  const double cu = 0.5 * (bounds[2 * u] + bounds[2 * u + 1]);
  const double cv = 0.5 * (bounds[2 * v] + bounds[2 * v + 1]);
  const float* vel = velocity->GetPointer(0);
  vtkSMPTools::For(vtkIdType(0), vtkIdType(E),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType e = begin; e < end; ++e)
      {
        const float* c = engine.initialCenters().data() + 3 * e;
        const float lay = float(double(c[axis]) + I.Offset[axis]);
        const float rad = float(std::hypot(c[u] - cu, c[v] - cv));
        const float life = engine.lifetimes()[e];
        for (std::size_t i = 0; i < n; ++i)
        {
          const vtkIdType id = e * vtkIdType(n) + vtkIdType(i);
          const float* w = vel + 3 * id;
          speed->SetValue(id, std::sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]));
          lifetime->SetValue(id, life);
          layer->SetValue(id, lay);
          radius->SetValue(id, rad);
          elementId->SetValue(id, vtkIdType(engine.elementIds()[e]));
          particleIndex->SetValue(id, int(i));
        }
      }
    });
  pd->SetNormals(normals);
  pd->SetVectors(velocity);
  for (vtkDataArray* a : std::initializer_list<vtkDataArray*>{
         speed, force, lifetime, elementId, particleIndex, vorticity, layer, radius })
  {
    if (a)
    {
      pd->AddArray(a);
    }
  }

  // What the automatic settings came to, for the Information panel and scripts.
  this->AddSettingsFieldData(output);
  return 1;
}

void vtkBoundParticleTracer::FillGpuOutput(vtkPolyData* output)
{
  vtkInternals& I = *this->Internals;
  bp::DrawSettings& d = I.Queue->draw;
  d.time = I.Target;
  d.offset = I.Offset;
  const auto bounds = I.Grid.bounds();
  for (int a = 0; a < 3; ++a)
  {
    d.bounds[2 * a] = bounds[2 * a] + I.Offset[a];
    d.bounds[2 * a + 1] = bounds[2 * a + 1] + I.Offset[a];
  }
  d.coloringAxis = this->ColoringAxis;
  const int u = (this->ColoringAxis + 1) % 3, v = (this->ColoringAxis + 2) % 3;
  d.radialCenter = { 0.5 * (bounds[2 * u] + bounds[2 * u + 1]),
    0.5 * (bounds[2 * v] + bounds[2 * v + 1]) };
  ++d.serial;

  // No particles: two points spanning the field (its bounds, for the camera
  // and the axes grid) carry every array of the CPU output with two values,
  // the range it is expected to span, so displays offer the arrays for
  // colouring and colour maps rescale to sensible ranges.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(d.bounds[0], d.bounds[2], d.bounds[4]);
  points->InsertNextPoint(d.bounds[1], d.bounds[3], d.bounds[5]);
  output->SetPoints(points);
  vtkPointData* pd = output->GetPointData();
  for (const ExpectedRange& r : I.ExpectedRanges)
  {
    auto a = floatArray(r.name.c_str(), r.name == "Velocity" || r.name == "Normals" ? 3 : 1, 2);
    for (int c = 0; c < a->GetNumberOfComponents(); ++c)
    {
      a->SetTypedComponent(0, c, float(r.low));
      a->SetTypedComponent(1, c, float(r.high));
    }
    if (r.name == "Velocity")
      pd->SetVectors(a);
    else if (r.name == "Normals")
      pd->SetNormals(a);
    else
      pd->AddArray(a);
  }
  for (const char* name : { "ElementId", "ParticleIndex" })
  {
    const double high = std::string(name) == "ElementId" ? double(this->NumberOfElements - 1)
                                                         : double(I.TemplateParticles - 1);
    vtkNew<vtkIntArray> ids;
    ids->SetName(name);
    ids->InsertNextValue(0);
    ids->InsertNextValue(int(high));
    pd->AddArray(ids);
  }

  vtkNew<vtkIntArray> queue;
  queue->SetName("BoundParticlesWorkQueue");
  queue->InsertNextValue(I.Queue->id());
  output->GetFieldData()->AddArray(queue);
  this->AddSettingsFieldData(output);
}

void vtkBoundParticleTracer::AddSettingsFieldData(vtkPolyData* output)
{
  vtkInternals& I = *this->Internals;
  auto addValue = [&](const char* name, double value)
  {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->InsertNextValue(value);
    output->GetFieldData()->AddArray(a);
  };
  addValue("TimeStep", I.ResolvedDt);
  addValue("ElementSize", I.ResolvedElementSize);
  addValue("SimulationTime", I.Target);
  if (I.distributed())
  {
    // This process's share: ghost layers read, elements sent to other pieces.
    addValue("GhostLayers", I.GhostCells);
    addValue("MigratedElements", double(I.Migrated));
  }
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), I.Target);
}

void vtkBoundParticleTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ElementShape: " << bp::builtinShapeName(bp::BuiltinShape(this->ElementShape))
     << "\n";
  os << indent << "NumberOfElements: " << this->NumberOfElements << "\n";
  os << indent << "ElementSize: " << this->ElementSize << "\n";
  os << indent << "EmitterCenter: " << this->EmitterCenter[0] << " " << this->EmitterCenter[1]
     << " " << this->EmitterCenter[2] << "\n";
  os << indent << "EmitterSize: " << this->EmitterSize[0] << " " << this->EmitterSize[1] << " "
     << this->EmitterSize[2] << "\n";
  os << indent << "RandomOrientation: " << this->RandomOrientation << "\n";
  os << indent << "LifetimeRange: " << this->LifetimeRange[0] << " " << this->LifetimeRange[1]
     << "\n";
  os << indent << "StepSize: " << this->StepSize << " ("
     << (this->StepSizeUnit == CELL_LENGTH ? "cell lengths" : "time") << ")\n";
  os << indent << "Integrator: " << this->Integrator << "\n";
  os << indent << "Restoration: " << this->Restoration << " x " << this->RestorationIterations
     << "\n";
  os << indent << "ResetWhen: " << this->ResetWhen << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "Duration: " << this->Duration
     << ", NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
  os << indent << "ComputeVorticity: " << this->ComputeVorticity << "\n";
  os << indent << "Engine: " << (this->Engine == GPU ? "GPU" : "CPU") << "\n";
}

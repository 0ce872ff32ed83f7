// SPDX-License-Identifier: BSD-3-Clause
// A trace's saved state as a vtkPolyData, and the Initial State File read
// back (TracerState.h).
#include "TracerState.h"

#include "Memory.h"
#include "TracerParallel.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedIntArray.h"
#include "vtkXMLPPolyDataReader.h"
#include "vtkXMLPolyDataReader.h"

#include <sys/stat.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <numeric>
#include <sstream>
#include <utility>

namespace bpvtk
{
namespace
{
constexpr const char* FormatName = "BoundParticlesState";

float floatOf(std::uint32_t word)
{
  float f;
  std::memcpy(&f, &word, sizeof f);
  return f;
}

std::uint32_t wordOf(float f)
{
  std::uint32_t u;
  std::memcpy(&u, &f, sizeof u);
  return u;
}

vtkSmartPointer<vtkDataArray> newArrayOf(bp::StateArray::Type type)
{
  switch (type)
  {
    case bp::StateArray::Type::UInt32:
      return vtkSmartPointer<vtkUnsignedIntArray>::New();
    case bp::StateArray::Type::UInt8:
      return vtkSmartPointer<vtkUnsignedCharArray>::New();
    case bp::StateArray::Type::Float32:
      break;
  }
  return vtkSmartPointer<vtkFloatArray>::New();
}

/// Whether `array` holds values of `type`, exactly as the engine's.
bool holds(vtkDataArray* array, bp::StateArray::Type type)
{
  switch (type)
  {
    case bp::StateArray::Type::UInt32:
      return vtkUnsignedIntArray::SafeDownCast(array) != nullptr;
    case bp::StateArray::Type::UInt8:
      return vtkUnsignedCharArray::SafeDownCast(array) != nullptr;
    case bp::StateArray::Type::Float32:
      break;
  }
  return vtkFloatArray::SafeDownCast(array) != nullptr;
}

/// One layout array's words of every record as a named cell array.
void addRecordArray(const bp::EngineState& engine, std::size_t first, const bp::StateArray& layout,
  vtkCellData* cells)
{
  const std::size_t E = engine.elementCount(), C = layout.components;
  vtkSmartPointer<vtkDataArray> array = newArrayOf(layout.type);
  array->SetName(("bp" + layout.name).c_str());
  array->SetNumberOfComponents(int(C));
  array->SetNumberOfTuples(vtkIdType(E));
  for (std::size_t e = 0; e < E; ++e)
  {
    const std::uint32_t* words = engine.records.data() + e * engine.recordWords + first;
    for (std::size_t k = 0; k < C; ++k)
    {
      const vtkIdType at = vtkIdType(e * C + k);
      if (layout.type == bp::StateArray::Type::UInt32)
      {
        vtkUnsignedIntArray::SafeDownCast(array)->SetValue(at, words[k]);
      }
      else if (layout.type == bp::StateArray::Type::UInt8)
      {
        vtkUnsignedCharArray::SafeDownCast(array)->SetValue(
          at, static_cast<unsigned char>(words[k]));
      }
      else
      {
        vtkFloatArray::SafeDownCast(array)->SetValue(at, floatOf(words[k]));
      }
    }
  }
  cells->AddArray(array);
}

/// A named cell array's values back into every record's words.
std::string takeRecordArray(
  vtkCellData* cells, std::size_t first, const bp::StateArray& layout, bp::EngineState& engine)
{
  const std::string name = "bp" + layout.name;
  vtkDataArray* array = cells->GetArray(name.c_str());
  const std::size_t E = engine.elementCount(), C = layout.components;
  if (!array || !holds(array, layout.type))
  {
    return "it has no cell array " + name + " of the engine's type";
  }
  if (std::size_t(array->GetNumberOfComponents()) != C ||
    std::size_t(array->GetNumberOfTuples()) != E)
  {
    return "its cell array " + name + " has " + std::to_string(array->GetNumberOfTuples()) +
      " tuples of " + std::to_string(array->GetNumberOfComponents()) + " components, not " +
      std::to_string(E) + " of " + std::to_string(C);
  }
  for (std::size_t e = 0; e < E; ++e)
  {
    std::uint32_t* words = engine.records.data() + e * engine.recordWords + first;
    for (std::size_t k = 0; k < C; ++k)
    {
      const vtkIdType at = vtkIdType(e * C + k);
      if (layout.type == bp::StateArray::Type::UInt32)
      {
        words[k] = vtkUnsignedIntArray::SafeDownCast(array)->GetValue(at);
      }
      else if (layout.type == bp::StateArray::Type::UInt8)
      {
        words[k] = vtkUnsignedCharArray::SafeDownCast(array)->GetValue(at);
      }
      else
      {
        words[k] = wordOf(vtkFloatArray::SafeDownCast(array)->GetValue(at));
      }
    }
  }
  return std::string();
}

void addDoubles(vtkFieldData* fields, const char* name, const std::vector<double>& values)
{
  vtkNew<vtkDoubleArray> array;
  array->SetName(name);
  array->SetNumberOfTuples(vtkIdType(values.size()));
  std::copy(values.begin(), values.end(), array->GetPointer(0));
  fields->AddArray(array);
}

bool takeDoubles(vtkFieldData* fields, const char* name, std::vector<double>& values)
{
  vtkDoubleArray* array = vtkDoubleArray::SafeDownCast(fields->GetAbstractArray(name));
  if (!array || array->GetNumberOfComponents() != 1)
  {
    return false;
  }
  values.assign(array->GetPointer(0), array->GetPointer(0) + array->GetNumberOfTuples());
  return true;
}

void addStrings(vtkFieldData* fields, const char* name, const std::vector<std::string>& values)
{
  vtkNew<vtkStringArray> array;
  array->SetName(name);
  array->SetNumberOfValues(vtkIdType(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
  {
    array->SetValue(vtkIdType(k), values[k]);
  }
  fields->AddArray(array);
}

bool takeStrings(vtkFieldData* fields, const char* name, std::vector<std::string>& values)
{
  vtkStringArray* array = vtkStringArray::SafeDownCast(fields->GetAbstractArray(name));
  if (!array)
  {
    return false;
  }
  values.clear();
  for (vtkIdType k = 0; k < array->GetNumberOfValues(); ++k)
  {
    values.push_back(array->GetValue(k));
  }
  return true;
}

/// A list of named values as two field arrays, "<prefix>Names" and "<prefix>Values".
void addNamed(
  vtkFieldData* fields, const std::string& prefix, const std::vector<bp::NamedValue>& list)
{
  std::vector<std::string> names;
  std::vector<double> values;
  for (const bp::NamedValue& v : list)
  {
    names.push_back(v.name);
    values.push_back(v.value);
  }
  addStrings(fields, (prefix + "Names").c_str(), names);
  addDoubles(fields, (prefix + "Values").c_str(), values);
}

bool takeNamed(vtkFieldData* fields, const std::string& prefix, std::vector<bp::NamedValue>& list)
{
  std::vector<std::string> names;
  std::vector<double> values;
  if (!takeStrings(fields, (prefix + "Names").c_str(), names) ||
    !takeDoubles(fields, (prefix + "Values").c_str(), values) || names.size() != values.size())
  {
    return false;
  }
  list.clear();
  for (std::size_t k = 0; k < names.size(); ++k)
  {
    list.push_back({ names[k], values[k] });
  }
  return true;
}

std::string hex(std::uint64_t value)
{
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

/// The layout's names and types as strings ("Positions:f48"), to read back.
std::vector<std::string> layoutText(const std::vector<bp::StateArray>& layout)
{
  std::vector<std::string> text;
  for (const bp::StateArray& a : layout)
  {
    const char type = a.type == bp::StateArray::Type::UInt32 ? 'u'
      : a.type == bp::StateArray::Type::UInt8                ? 'b'
                                                             : 'f';
    text.push_back(a.name + ":" + type + std::to_string(a.components));
  }
  return text;
}

bool layoutOf(const std::vector<std::string>& text, std::vector<bp::StateArray>& layout)
{
  layout.clear();
  for (const std::string& entry : text)
  {
    const std::size_t colon = entry.rfind(':');
    if (colon == std::string::npos || colon + 2 >= entry.size())
    {
      return false;
    }
    bp::StateArray a;
    a.name = entry.substr(0, colon);
    const char type = entry[colon + 1];
    a.type = type == 'u' ? bp::StateArray::Type::UInt32
      : type == 'b'      ? bp::StateArray::Type::UInt8
                         : bp::StateArray::Type::Float32;
    char* end = nullptr;
    const unsigned long long components = std::strtoull(entry.c_str() + colon + 2, &end, 10);
    if ((type != 'u' && type != 'b' && type != 'f') || *end != '\0' || components == 0 ||
      components > (1ull << 24))
    {
      return false;
    }
    a.components = std::size_t(components);
    layout.push_back(a);
  }
  return true;
}

/// The particle positions of every record, in the world, as the points.
void addPoints(const bp::EngineState& engine, const std::array<double, 3>& offset, vtkPolyData* out)
{
  std::size_t first = 0, count = 0;
  for (const bp::StateArray& a : engine.layout)
  {
    if (a.name == "Positions")
    {
      count = a.components / 3;
      break;
    }
    first += a.components;
  }
  const std::size_t E = engine.elementCount();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  points->SetNumberOfPoints(vtkIdType(E * count));
  vtkNew<vtkIdTypeArray> offsets, connectivity;
  offsets->SetNumberOfTuples(vtkIdType(E + 1));
  connectivity->SetNumberOfTuples(vtkIdType(E * count));
  for (std::size_t e = 0; e < E; ++e)
  {
    offsets->SetValue(vtkIdType(e), vtkIdType(e * count));
    const std::uint32_t* words = engine.records.data() + e * engine.recordWords + first;
    for (std::size_t i = 0; i < count; ++i)
    {
      const vtkIdType id = vtkIdType(e * count + i);
      points->SetPoint(id, double(floatOf(words[3 * i])) + offset[0],
        double(floatOf(words[3 * i + 1])) + offset[1],
        double(floatOf(words[3 * i + 2])) + offset[2]);
      connectivity->SetValue(id, id);
    }
  }
  offsets->SetValue(vtkIdType(E), vtkIdType(E * count));
  vtkNew<vtkCellArray> cells;
  cells->SetData(offsets, connectivity);
  out->SetPoints(points);
  out->SetVerts(cells);
}
} // namespace

void writeStatePolyData(
  const bp::TraceState& state, const std::array<double, 3>& offset, vtkPolyData* out)
{
  out->Initialize();
  const bp::EngineState& engine = state.engine;
  addPoints(engine, offset, out);
  std::size_t first = 0;
  for (const bp::StateArray& layout : engine.layout)
  {
    addRecordArray(engine, first, layout, out->GetCellData());
    first += layout.components;
  }
  vtkFieldData* fields = out->GetFieldData();
  addStrings(fields, "bpStateFormat", { FormatName });
  addDoubles(fields, "bpStateVersion", { double(state.version) });
  addStrings(fields, "bpLayout", layoutText(engine.layout));
  addDoubles(fields, "bpTime", { state.time });
  addDoubles(fields, "bpSteps", { double(state.steps) });
  addDoubles(fields, "bpScheduleStart", { state.scheduleStart });
  addDoubles(fields, "bpDt", { state.dt });
  addDoubles(fields, "bpTrailTimes", engine.trailTimes);
  addDoubles(fields, "bpTrailNewest", { double(engine.trailNewest) });
  addDoubles(
    fields, "bpEmitterMin", { engine.emitterMin[0], engine.emitterMin[1], engine.emitterMin[2] });
  addDoubles(
    fields, "bpEmitterMax", { engine.emitterMax[0], engine.emitterMax[1], engine.emitterMax[2] });
  addNamed(fields, "bpParameter", state.parameters);
  addNamed(fields, "bpShape", state.shape);
  addNamed(fields, "bpField", state.field);
  addStrings(fields, "bpChecksum", { hex(bp::stateChecksum(state)) });
}

namespace
{
/// The field data's scalars and named values into `state`.
std::string readStateFields(vtkFieldData* fields, bp::TraceState& state)
{
  std::vector<double> version, time, steps, start, dt, newest, emitterMin, emitterMax;
  std::vector<std::string> layout;
  if (!takeDoubles(fields, "bpStateVersion", version) || version.size() != 1 ||
    !takeStrings(fields, "bpLayout", layout) || !takeDoubles(fields, "bpTime", time) ||
    time.size() != 1 || !takeDoubles(fields, "bpSteps", steps) || steps.size() != 1 ||
    !takeDoubles(fields, "bpScheduleStart", start) || start.size() != 1 ||
    !takeDoubles(fields, "bpDt", dt) || dt.size() != 1 ||
    !takeDoubles(fields, "bpTrailTimes", state.engine.trailTimes) ||
    !takeDoubles(fields, "bpTrailNewest", newest) || newest.size() != 1 ||
    !takeDoubles(fields, "bpEmitterMin", emitterMin) || emitterMin.size() != 3 ||
    !takeDoubles(fields, "bpEmitterMax", emitterMax) || emitterMax.size() != 3 ||
    !takeNamed(fields, "bpParameter", state.parameters) ||
    !takeNamed(fields, "bpShape", state.shape) || !takeNamed(fields, "bpField", state.field))
  {
    return "its field data lacks one of the state's values (bpStateVersion, bpTime, ...): it "
           "was cut short or edited";
  }
  if (!layoutOf(layout, state.engine.layout))
  {
    return "its record layout (bpLayout) is not one this plugin wrote";
  }
  const auto whole = [](double v, double least, double most)
  { return v >= least && v <= most && v == std::floor(v); };
  if (!whole(version[0], 0.0, 4294967295.0) || !whole(steps[0], 0.0, 9.0e15) ||
    !whole(newest[0], -1.0, double(bp::MaxTrailLength)))
  {
    return "its version, step count or trail slot is not a count";
  }
  for (int k = 0; k < 3; ++k)
  {
    // Checked as doubles: float() of one beyond float's range is undefined.
    if (!(std::abs(emitterMin[k]) <= 3.0e38 && std::abs(emitterMax[k]) <= 3.0e38))
    {
      return "its emitter box is not finite";
    }
  }
  state.version = std::uint32_t(version[0]);
  state.time = time[0];
  state.steps = (long long)steps[0];
  state.scheduleStart = start[0];
  state.dt = dt[0];
  state.engine.trailNewest = int(newest[0]);
  for (int k = 0; k < 3; ++k)
  {
    state.engine.emitterMin[k] = float(emitterMin[k]);
    state.engine.emitterMax[k] = float(emitterMax[k]);
  }
  state.engine.recordWords = 0;
  for (const bp::StateArray& a : state.engine.layout)
  {
    state.engine.recordWords += a.components;
  }
  return std::string();
}
} // namespace

void writeStateNote(const std::string& why, vtkPolyData* out)
{
  out->Initialize();
  // No points, but a Points array: VTK's XML reader refuses a piece without one.
  out->SetPoints(vtkNew<vtkPoints>());
  addStrings(out->GetFieldData(), "bpStateNote", { why });
}

std::string readStatePolyData(vtkPolyData* data, bp::TraceState& state)
{
  std::vector<std::string> format, note;
  if (data && takeStrings(data->GetFieldData(), "bpStateNote", note) && note.size() == 1)
  {
    return "it holds no state: " + note[0];
  }
  if (!data || !takeStrings(data->GetFieldData(), "bpStateFormat", format) || format.size() != 1 ||
    format[0] != FormatName)
  {
    return "it is not a Bound Particles state (it has no bpStateFormat field array, or was saved "
           "as ASCII, which cannot be read back whole): save the tracer's State output with Data "
           "Mode Binary";
  }
  state = bp::TraceState();
  const std::string fieldError = readStateFields(data->GetFieldData(), state);
  if (!fieldError.empty())
  {
    return fieldError;
  }
  bp::EngineState& engine = state.engine;
  const std::size_t elements = std::size_t(data->GetNumberOfCells());
  if (engine.recordWords == 0 || elements > std::size_t(0xffffffffu))
  {
    return "its record layout holds no values, or its element count is out of range";
  }
  const std::string memory =
    bp::checkAllocatable(4.0 * double(elements) * double(engine.recordWords),
      std::to_string(elements) + " elements of the state");
  if (!memory.empty())
  {
    return memory;
  }
  engine.records.assign(elements * engine.recordWords, 0u);
  std::size_t first = 0;
  for (const bp::StateArray& layout : engine.layout)
  {
    const std::string error = takeRecordArray(data->GetCellData(), first, layout, engine);
    if (!error.empty())
    {
      return error;
    }
    first += layout.components;
  }
  std::vector<std::string> checksum;
  if (!takeStrings(data->GetFieldData(), "bpChecksum", checksum) || checksum.size() != 1 ||
    checksum[0] != hex(bp::stateChecksum(state)))
  {
    return "its checksum does not match its values (the file was altered, or saved as ASCII, "
           "which rounds them): save the State output again with Data Mode Binary";
  }
  return std::string();
}

namespace
{
/// Keeps a reader's errors as text instead of letting them reach the
/// Output Messages as the reader's own.
class ErrorCatcher : public vtkCommand
{
public:
  static ErrorCatcher* New() { return new ErrorCatcher; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    if (this->Text.empty() && data)
    {
      this->Text = static_cast<const char*>(data);
    }
  }
  std::string Text;
};

std::string firstLine(std::string text)
{
  const std::size_t end = text.find('\n');
  return end == std::string::npos ? text : text.substr(0, end);
}

bool endsWith(const std::string& text, const std::string& tail)
{
  return text.size() >= tail.size() &&
    text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
}
} // namespace

std::string readStateFile(const std::string& path, bp::TraceState& state)
{
  const std::string named = "Initial State File '" + path + "': ";
  if (StateFileStamp::of(path).size < 0)
  {
    return named + "no such file";
  }
  vtkSmartPointer<vtkXMLReader> reader;
  if (endsWith(path, ".pvtp"))
  {
    reader = vtkSmartPointer<vtkXMLPPolyDataReader>::New();
  }
  else if (endsWith(path, ".vtp"))
  {
    reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
  }
  else
  {
    return named + "not a .vtp or .pvtp file (save the tracer's State output as one)";
  }
  vtkNew<ErrorCatcher> catcher;
  reader->AddObserver(vtkCommand::ErrorEvent, catcher);
  reader->AddObserver(vtkCommand::WarningEvent, catcher);
  reader->SetFileName(path.c_str());
  // Whole on every process, as the Seed Source is.
  reader->UpdatePiece(0, 1, 0);
  vtkPolyData* data = vtkPolyData::SafeDownCast(reader->GetOutputDataObject(0));
  if (!catcher->Text.empty())
  {
    return named + "cannot be read (" + firstLine(catcher->Text) + ")";
  }
  const std::string error = readStatePolyData(data, state);
  return error.empty() ? error : named + error + ".";
}

std::string gatherStateElements(vtkMultiProcessController* controller, bp::EngineState& state)
{
  const int processes = controller->GetNumberOfProcesses();
  const int me = controller->GetLocalProcessId();
  std::vector<vtkIdType> lengths(std::size_t(processes), 0), offsets(std::size_t(processes), 0);
  const vtkIdType mine = vtkIdType(state.records.size());
  controller->Gather(&mine, lengths.data(), 1, 0);
  vtkIdType total = 0;
  for (int p = 0; p < processes; ++p)
  {
    offsets[std::size_t(p)] = total;
    total += lengths[std::size_t(p)];
  }
  // Process 0 holds them all, sorted once more, then as arrays: refused
  // alike on every process where that cannot be had, before any is sent.
  std::string error;
  if (me == 0)
  {
    error = total > vtkIdType(0x7fffffff) // the communicator's counts are int
      ? "the state's " + std::to_string(total) + " words are more than one process can gather"
      : bp::checkAllocatable(12.0 * double(total), "the whole state on process 0");
  }
  error = agreeOnError(controller, error);
  if (!error.empty())
  {
    return "The State output cannot be saved: " + error +
      ". Save fewer elements, or trace on fewer processes.";
  }
  std::vector<std::uint32_t> all(me == 0 ? std::size_t(total) : std::size_t(0));
  // As unsigned int, which vtkCommunicator sends (32 bits on every platform we build for).
  static_assert(sizeof(unsigned int) == sizeof(std::uint32_t), "32-bit words");
  controller->GatherV(reinterpret_cast<const unsigned int*>(state.records.data()),
    reinterpret_cast<unsigned int*>(all.data()), mine, lengths.data(), offsets.data(), 0);
  if (me != 0)
  {
    state.records.clear();
    return std::string();
  }
  // Ids increasing, as one process holds them (a record starts with its id).
  const std::size_t words = state.recordWords, count = words ? all.size() / words : 0;
  std::vector<std::size_t> order(count);
  std::iota(order.begin(), order.end(), std::size_t(0));
  std::sort(order.begin(), order.end(),
    [&](std::size_t a, std::size_t b) { return all[a * words] < all[b * words]; });
  state.records.resize(all.size());
  for (std::size_t r = 0; r < count; ++r)
  {
    std::copy_n(all.begin() + std::ptrdiff_t(order[r] * words), words,
      state.records.begin() + std::ptrdiff_t(r * words));
  }
  return std::string();
}

StateFileStamp StateFileStamp::of(const std::string& path)
{
  StateFileStamp stamp;
  stamp.path = path;
  struct stat facts;
  if (!path.empty() && ::stat(path.c_str(), &facts) == 0 && S_ISREG(facts.st_mode))
  {
    stamp.size = (long long)facts.st_size;
    // To the nanosecond: a state saved again within a second is read again.
    stamp.modified = (long long)facts.st_mtim.tv_sec * 1000000000LL + facts.st_mtim.tv_nsec;
  }
  return stamp;
}

void InitialState::take(const std::string& path)
{
  const StateFileStamp now = StateFileStamp::of(path);
  if (now == this->stamp && this->stamp.size >= 0)
  {
    return;
  }
  this->stamp = now;
  this->state = bp::TraceState();
  this->error = readStateFile(path, this->state);
}

} // namespace bpvtk

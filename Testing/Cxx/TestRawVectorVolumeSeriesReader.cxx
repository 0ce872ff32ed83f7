// SPDX-License-Identifier: BSD-3-Clause
#include "vtkBoundParticleTracer.h"
#include "vtkRawVectorVolumeSeriesReader.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
/// Collects an object's error (or warning) messages instead of printing them.
struct MessageLog
{
  std::vector<std::string> messages;
  vtkNew<vtkCallbackCommand> callback;
  MessageLog(vtkObject* watched, unsigned long event = vtkCommand::ErrorEvent)
  {
    this->callback->SetClientData(this);
    this->callback->SetCallback([](vtkObject*, unsigned long, void* self, void* text)
      { static_cast<MessageLog*>(self)->messages.emplace_back(static_cast<const char*>(text)); });
    watched->AddObserver(event, this->callback);
  }
  bool mentions(const std::string& part) const
  {
    for (const auto& m : this->messages)
      if (m.find(part) != std::string::npos)
        return true;
    return false;
  }
  std::string all() const
  {
    std::string s;
    for (const auto& m : this->messages)
      s += m + "\n";
    return s;
  }
};

/// Small integers: exact in every scalar type used below.
float valueAt(int i, int j, int k, int c, int step)
{
  return float((i + 2 * j + 3 * k + 5 * c + 7 * step) % 40 - 10);
}

struct Layout
{
  bool threeFiles = false;
  bool big = false;
  std::string type = "float32"; // float32, float64 or int16
  int header = 0;
};

template <typename T>
void put(std::string& bytes, double value, bool big)
{
  const T t = static_cast<T>(value);
  char b[sizeof(T)];
  std::memcpy(b, &t, sizeof(T));
  const std::uint16_t one = 1;
  const bool hostLittle = *reinterpret_cast<const char*>(&one) == 1;
  if (big == hostLittle)
    std::reverse(b, b + sizeof(T));
  bytes.append(b, sizeof(T));
}

class RawVectorVolumeSeriesReaderTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    static int counter = 0;
    this->dir = fs::temp_directory_path() /
      ("bp-rawreader-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(this->dir);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(this->dir, ec);
  }

  /// Writes the data files of a series; returns the "files" JSON array.
  std::string writeData(const std::string& tag, const Layout& layout, int steps, const int dims[3],
    float (*field)(int, int, int, int, int) = valueAt)
  {
    std::ostringstream files;
    files << "[";
    for (int step = 0; step < steps; ++step)
    {
      std::vector<std::string> bytes(layout.threeFiles ? 3 : 1, std::string(layout.header, 'H'));
      for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
          for (int i = 0; i < dims[0]; ++i)
            for (int c = 0; c < 3; ++c)
            {
              std::string& out = bytes[layout.threeFiles ? c : 0];
              const double v = field(i, j, k, c, step);
              if (layout.type == "float64")
                put<double>(out, v, layout.big);
              else if (layout.type == "int16")
                put<std::int16_t>(out, v, layout.big);
              else
                put<float>(out, v, layout.big);
            }
      files << (step ? ", " : "") << (layout.threeFiles ? "[" : "");
      for (std::size_t f = 0; f < bytes.size(); ++f)
      {
        const std::string name = tag + "_" + std::to_string(step) + "_" + "uvw"[f] + ".raw";
        std::ofstream(this->dir / name, std::ios::binary) << bytes[f];
        files << (f ? ", " : "") << "\"" << name << "\"";
      }
      files << (layout.threeFiles ? "]" : "");
    }
    files << "]";
    return files.str();
  }

  std::string writeText(const std::string& name, const std::string& text)
  {
    const fs::path path = this->dir / name;
    std::ofstream(path) << text;
    return path.string();
  }

  /// A whole series: data files and descriptor; returns the descriptor's path.
  std::string writeSeries(const std::string& tag, const Layout& layout, int steps = 4,
    const std::string& extra = "", float (*field)(int, int, int, int, int) = valueAt)
  {
    const std::string files = this->writeData(tag, layout, steps, this->dims, field);
    std::ostringstream json;
    json << "{\n  \"dimensions\": [" << this->dims[0] << ", " << this->dims[1] << ", "
         << this->dims[2] << "],\n  \"origin\": [1, 2, 3],\n  \"spacing\": [0.5, 0.25, 2],\n"
         << "  \"scalar_type\": \"" << layout.type << "\",\n  \"byte_order\": \""
         << (layout.big ? "big" : "little") << "\",\n  \"header_bytes\": " << layout.header
         << ",\n  \"times\": [";
    for (int k = 0; k < steps; ++k)
      json << (k ? ", " : "") << this->times[std::size_t(k)];
    json << "],\n" << extra << "  \"files\": " << files << "\n}\n";
    return this->writeText(tag + ".bpvol", json.str());
  }

  std::vector<float> expected(int step) const
  {
    std::vector<float> v;
    for (int k = 0; k < this->dims[2]; ++k)
      for (int j = 0; j < this->dims[1]; ++j)
        for (int i = 0; i < this->dims[0]; ++i)
          for (int c = 0; c < 3; ++c)
            v.push_back(valueAt(i, j, k, c, step));
    return v;
  }

  fs::path dir;
  int dims[3] = { 5, 4, 3 };
  std::vector<double> times = { 0.0, 0.5, 1.25, 2.0, 3.0, 4.0, 5.0, 6.0 };
};

vtkSmartPointer<vtkRawVectorVolumeSeriesReader> open(const std::string& file, bool ahead = true)
{
  auto reader = vtkSmartPointer<vtkRawVectorVolumeSeriesReader>::New();
  reader->SetFileName(file.c_str());
  reader->SetReadAhead(ahead);
  return reader;
}

vtkDataSet* at(vtkRawVectorVolumeSeriesReader* reader, double t)
{
  reader->UpdateTimeStep(t);
  return vtkDataSet::SafeDownCast(reader->GetOutputDataObject(0));
}

std::vector<float> vectorsOf(vtkDataSet* data)
{
  vtkFloatArray* a = vtkFloatArray::SafeDownCast(data->GetPointData()->GetVectors());
  if (!a || a->GetNumberOfComponents() != 3)
    return {};
  return std::vector<float>(a->GetPointer(0), a->GetPointer(0) + 3 * a->GetNumberOfTuples());
}

double dataTime(vtkDataSet* data)
{
  return data->GetInformation()->Get(vtkDataObject::DATA_TIME_STEP());
}
} // namespace

TEST_F(RawVectorVolumeSeriesReaderTest, ReportsTimeStepsAndGridWithoutReading)
{
  auto reader = open(this->writeSeries("a", Layout()));
  EXPECT_TRUE(reader->CanReadFile(reader->GetFileName()));
  reader->UpdateInformation();
  vtkInformation* info = reader->GetOutputInformation(0);
  ASSERT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 4);
  const double* steps = info->Get(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  EXPECT_EQ(std::vector<double>(steps, steps + 4), std::vector<double>({ 0.0, 0.5, 1.25, 2.0 }));
  const double* range = info->Get(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  EXPECT_EQ(range[0], 0.0);
  EXPECT_EQ(range[1], 2.0);
  int extent[6];
  info->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
  EXPECT_EQ(std::vector<int>(extent, extent + 6), std::vector<int>({ 0, 4, 0, 3, 0, 2 }));
  const double* spacing = info->Get(vtkDataObject::SPACING());
  EXPECT_EQ(spacing[1], 0.25);
  EXPECT_EQ(reader->GetNumberOfTimeSteps(), 4);
  EXPECT_EQ(reader->GetNumberOfStepsRead(), 0);
  EXPECT_TRUE(vtkImageData::SafeDownCast(reader->GetOutputDataObject(0)));
}

TEST_F(RawVectorVolumeSeriesReaderTest, ReadsOnlyTheRequestedStep)
{
  auto reader = open(this->writeSeries("a", Layout()), false);
  vtkDataSet* out = at(reader, 1.25);
  EXPECT_EQ(reader->GetNumberOfStepsRead(), 1);
  auto* image = vtkImageData::SafeDownCast(out);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->GetNumberOfPoints(), 60);
  EXPECT_EQ(image->GetOrigin()[2], 3.0);
  EXPECT_EQ(image->GetSpacing()[2], 2.0);
  EXPECT_STREQ(image->GetPointData()->GetVectors()->GetName(), "velocity");
  EXPECT_EQ(vectorsOf(out), this->expected(2));
  EXPECT_EQ(dataTime(out), 1.25);

  // Between steps: the step at or before; before the first: the first; past the last: the last.
  out = at(reader, 1.0);
  EXPECT_EQ(dataTime(out), 0.5);
  EXPECT_EQ(vectorsOf(out), this->expected(1));
  out = at(reader, -5.0);
  EXPECT_EQ(dataTime(out), 0.0);
  EXPECT_EQ(vectorsOf(out), this->expected(0));
  out = at(reader, 99.0);
  EXPECT_EQ(dataTime(out), 2.0);
  EXPECT_EQ(vectorsOf(out), this->expected(3));
  EXPECT_EQ(reader->GetNumberOfStepsRead(), 4);
  EXPECT_EQ(reader->GetNumberOfReadAheadHits(), 0);

  // No time asked for: the first step.
  auto plain = open(reader->GetFileName(), false);
  plain->Update();
  out = vtkDataSet::SafeDownCast(plain->GetOutputDataObject(0));
  EXPECT_EQ(dataTime(out), 0.0);
  EXPECT_EQ(vectorsOf(out), this->expected(0));
  EXPECT_EQ(plain->GetNumberOfStepsRead(), 1);
}

TEST_F(RawVectorVolumeSeriesReaderTest, ReadAheadServesPlayingForward)
{
  auto reader = open(this->writeSeries("a", Layout()));
  EXPECT_TRUE(reader->GetReadAhead());
  for (int k = 0; k < 4; ++k)
    EXPECT_EQ(vectorsOf(at(reader, this->times[std::size_t(k)])), this->expected(k)) << k;
  EXPECT_EQ(reader->GetNumberOfStepsRead(), 4); // 0 directly, 1..3 ahead
  EXPECT_EQ(reader->GetNumberOfReadAheadHits(), 3);
  // Jumping back reads directly and still gives the right step.
  EXPECT_EQ(vectorsOf(at(reader, 0.5)), this->expected(1));
  EXPECT_EQ(vectorsOf(at(reader, 0.0)), this->expected(0));
  EXPECT_EQ(reader->GetNumberOfReadAheadHits(), 3);
}

TEST_F(RawVectorVolumeSeriesReaderTest, LayoutsAndByteOrdersGiveTheSameValues)
{
  const Layout layouts[] = { { false, false, "float32", 0 }, { false, true, "float64", 0 },
    { true, false, "int16", 0 }, { true, true, "float32", 12 }, { false, true, "int16", 7 } };
  int n = 0;
  for (const Layout& layout : layouts)
  {
    SCOPED_TRACE(std::string(layout.threeFiles ? "three files " : "interleaved ") +
      (layout.big ? "big " : "little ") + layout.type + " header " + std::to_string(layout.header));
    auto reader = open(this->writeSeries("l" + std::to_string(n++), layout));
    MessageLog errors(reader);
    for (int k : { 3, 0, 1 })
      EXPECT_EQ(vectorsOf(at(reader, this->times[std::size_t(k)])), this->expected(k)) << k;
    EXPECT_TRUE(errors.messages.empty()) << errors.all();
  }
}

TEST_F(RawVectorVolumeSeriesReaderTest, ZCoordinatesGiveARectilinearGrid)
{
  auto reader = open(this->writeSeries("r", Layout{ true, false, "float32", 0 }, 2,
    "  \"z_coordinates\": [0, 0.5, 2.5],\n  \"array_name\": \"wind\",\n"));
  vtkDataSet* out = at(reader, 0.5);
  auto* grid = vtkRectilinearGrid::SafeDownCast(out);
  ASSERT_TRUE(grid) << (out ? out->GetClassName() : "no output");
  int d[3];
  grid->GetDimensions(d);
  EXPECT_EQ(std::vector<int>(d, d + 3), std::vector<int>({ 5, 4, 3 }));
  EXPECT_EQ(grid->GetXCoordinates()->GetTuple1(0), 1.0);
  EXPECT_EQ(grid->GetXCoordinates()->GetTuple1(4), 3.0);
  EXPECT_EQ(grid->GetYCoordinates()->GetTuple1(3), 2.75);
  EXPECT_EQ(grid->GetZCoordinates()->GetTuple1(1), 0.5);
  EXPECT_EQ(grid->GetZCoordinates()->GetTuple1(2), 2.5);
  EXPECT_STREQ(grid->GetPointData()->GetVectors()->GetName(), "wind");
  EXPECT_EQ(vectorsOf(out), this->expected(1));
  EXPECT_EQ(dataTime(out), 0.5);
  // A point's position and its vector agree with the raw layout.
  double p[3];
  grid->GetPoint(4 + 5 * (3 + 4 * 2), p);
  EXPECT_EQ(p[0], 3.0);
  EXPECT_EQ(p[1], 2.75);
  EXPECT_EQ(p[2], 2.5);
}

TEST_F(RawVectorVolumeSeriesReaderTest, BrokenDescriptorsGiveAnErrorNamingTheFileAndAnEmptyOutput)
{
  const std::string files = this->writeData("d", Layout(), 2, this->dims);
  const std::string head = "{\"dimensions\": [5, 4, 3], \"scalar_type\": \"float32\", ";
  struct Case
  {
    std::string name, text, says;
  };
  const Case cases[] = {
    { "json.bpvol", head + "\"byte_order\": \"little\" \"files\": " + files + "}",
      "not valid JSON" },
    { "array.bpvol", "[1, 2]", "JSON object" },
    { "nodims.bpvol",
      "{\"scalar_type\": \"float32\", \"byte_order\": \"little\", \"files\": " + files + "}",
      "lacks 'dimensions'" },
    { "dims.bpvol",
      "{\"dimensions\": [5, 4], \"scalar_type\": \"float32\", "
      "\"byte_order\": \"little\", \"files\": " +
        files + "}",
      "'dimensions' must be an array of three" },
    { "type.bpvol",
      "{\"dimensions\": [5, 4, 3], \"scalar_type\": \"float\", "
      "\"byte_order\": \"little\", \"files\": " +
        files + "}",
      "unknown 'scalar_type' \"float\"; use one of uint8, int8" },
    { "order.bpvol", head + "\"byte_order\": \"network\", \"files\": " + files + "}",
      "'byte_order' that is neither" },
    { "noorder.bpvol", head + "\"files\": " + files + "}", "lacks 'byte_order'" },
    { "key.bpvol", head + "\"byteorder\": \"little\", \"files\": " + files + "}",
      "unknown key 'byteorder'" },
    { "nofiles.bpvol", head + "\"byte_order\": \"little\"}", "lacks 'files'" },
    { "times.bpvol", head + "\"byte_order\": \"little\", \"times\": [0], \"files\": " + files + "}",
      "one time per step" },
    { "z.bpvol",
      head + "\"byte_order\": \"little\", \"z_coordinates\": [0, 1], \"files\": " + files + "}",
      "z_coordinates has 2 values" },
    { "noz.bpvol",
      head + "\"byte_order\": \"little\", \"z_coordinates\": [], \"files\": " + files + "}",
      "empty 'z_coordinates'" },
    { "empty.bpvol", "", "is empty" },
  };
  for (const Case& c : cases)
  {
    SCOPED_TRACE(c.name);
    const std::string path = this->writeText(c.name, c.text);
    auto reader = open(path);
    MessageLog errors(reader);
    vtkDataSet* out = at(reader, 0.0);
    ASSERT_TRUE(out);
    EXPECT_EQ(out->GetNumberOfPoints(), 0);
    EXPECT_TRUE(errors.mentions(path)) << errors.all();
    EXPECT_TRUE(errors.mentions(c.says)) << errors.all();
    EXPECT_EQ(reader->GetNumberOfTimeSteps(), 0);
  }

  // A descriptor that does not exist.
  auto reader = open((this->dir / "nowhere.bpvol").string());
  EXPECT_FALSE(reader->CanReadFile(reader->GetFileName()));
  MessageLog errors(reader);
  vtkDataSet* out = at(reader, 0.0);
  ASSERT_TRUE(out);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions("nowhere.bpvol")) << errors.all();
  EXPECT_TRUE(errors.mentions("does not exist")) << errors.all();
}

TEST_F(RawVectorVolumeSeriesReaderTest, BrokenDataFilesGiveAnErrorNamingTheFileAndAnEmptyOutput)
{
  const std::string descriptor = this->writeSeries("b", Layout{ true, true, "float32", 0 });
  const fs::path missing = this->dir / "b_1_v.raw";
  const fs::path truncated = this->dir / "b_2_u.raw";
  const fs::path oversized = this->dir / "b_3_w.raw";
  const auto size = fs::file_size(truncated);
  fs::remove(missing);
  fs::resize_file(truncated, size - 4);
  fs::resize_file(oversized, size + 4);

  auto reader = open(descriptor);
  MessageLog errors(reader);
  MessageLog warnings(reader, vtkCommand::WarningEvent);
  reader->UpdateInformation();
  // Told up front, when the series is opened.
  EXPECT_TRUE(warnings.mentions("3 of 4 time steps cannot be read")) << warnings.all();
  EXPECT_TRUE(warnings.mentions(missing.string())) << warnings.all();

  EXPECT_EQ(vectorsOf(at(reader, 0.0)), this->expected(0));
  EXPECT_TRUE(errors.messages.empty()) << errors.all();

  vtkDataSet* out = at(reader, 0.5);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions(missing.string())) << errors.all();
  EXPECT_TRUE(errors.mentions("does not exist")) << errors.all();

  out = at(reader, 1.25);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions(truncated.string())) << errors.all();
  EXPECT_TRUE(errors.mentions("truncated")) << errors.all();

  out = at(reader, 2.0);
  EXPECT_EQ(out->GetNumberOfPoints(), 0);
  EXPECT_TRUE(errors.mentions(oversized.string())) << errors.all();
  EXPECT_TRUE(errors.mentions("expected " + std::to_string(size) + " bytes")) << errors.all();
  EXPECT_TRUE(errors.mentions("actual size " + std::to_string(size + 4))) << errors.all();
  EXPECT_EQ(dataTime(out), 2.0);

  // Fixed on disk and reloaded: the series reads again.
  fs::resize_file(oversized, size);
  reader->Modified();
  EXPECT_EQ(vectorsOf(at(reader, 2.0)), this->expected(3));
}

TEST_F(RawVectorVolumeSeriesReaderTest, FeedsTheTracerOverSeveralTimeSteps)
{
  // A uniform flow along +x that speeds up from step to step, on a 16^3 image.
  this->dims[0] = this->dims[1] = this->dims[2] = 16;
  const auto field = [](int, int, int, int c, int step) -> float
  { return c == 0 ? 0.2f + 0.05f * float(step) : 0.0f; };
  auto reader = open(this->writeSeries("t", Layout{ true, false, "float32", 0 }, 6, "", field));
  auto tracer = vtkSmartPointer<vtkBoundParticleTracer>::New();
  tracer->SetInputConnection(reader->GetOutputPort());
  tracer->SetNumberOfElements(40);
  tracer->SetSeed(11);
  tracer->SetElementSize(0.4);
  tracer->SetEmitterCenter(2.0, 3.0, 8.0); // the grid spans x 1..8.5, y 2..5.75, z 3..33
  tracer->SetEmitterSize(0.5, 0.5, 0.5);
  tracer->SetLifetimeRange(100, 100);
  MessageLog tracerErrors(tracer);
  MessageLog readerErrors(reader);
  tracer->UpdateInformation();
  // The reader's 6 steps, 20 frames apart: the automatic time line's 101.
  EXPECT_EQ(
    tracer->GetOutputInformation(0)->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 101);

  double previousMeanX = 0.0;
  for (double t : { 0.0, 0.5, 1.25, 2.0, 3.0, 4.0 })
  {
    tracer->UpdateTimeStep(t);
    vtkPolyData* out = tracer->GetOutput();
    ASSERT_EQ(out->GetNumberOfPoints(), 40 * 8) << "t = " << t;
    EXPECT_NEAR(tracer->GetSimulationTime(), t, 1e-9);
    double meanX = 0.0;
    for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
      meanX += out->GetPoint(i)[0] / double(out->GetNumberOfPoints());
    if (t > 0.0)
      EXPECT_GT(meanX, previousMeanX) << "t = " << t; // carried along +x
    previousMeanX = meanX;
  }
  EXPECT_TRUE(tracerErrors.messages.empty()) << tracerErrors.all();
  EXPECT_TRUE(readerErrors.messages.empty()) << readerErrors.all();
  // Playing forward reads every step once, most of them from the read-ahead.
  EXPECT_LE(reader->GetNumberOfStepsRead(), 6);
  EXPECT_GE(reader->GetNumberOfReadAheadHits(), 4);
}

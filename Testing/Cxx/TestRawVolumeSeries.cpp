// SPDX-License-Identifier: BSD-3-Clause
#include "RawVolumeSeries.h"

#include <gtest/gtest.h>

#include <limits>

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

namespace fs = std::filesystem;

namespace
{
/// The test field: small integers, exact in every scalar type (int8 included).
float valueAt(int i, int j, int k, int c, int step)
{
  return float((i + 2 * j + 3 * k + 5 * c + 7 * step) % 50 - 10);
}

std::vector<float> expectedStep(const bp::RawVolumeSeries& s, int step)
{
  std::vector<float> v;
  for (int k = 0; k < s.dims[2]; ++k)
    for (int j = 0; j < s.dims[1]; ++j)
      for (int i = 0; i < s.dims[0]; ++i)
        for (int c = 0; c < 3; ++c)
          v.push_back(valueAt(i, j, k, c, step));
  return v;
}

template <typename T>
void append(std::vector<unsigned char>& bytes, double value, bool bigEndian)
{
  const T t = static_cast<T>(value);
  unsigned char b[sizeof(T)];
  std::memcpy(b, &t, sizeof(T));
  const std::uint16_t one = 1;
  const bool hostLittle = *reinterpret_cast<const unsigned char*>(&one) == 1;
  if (bigEndian == hostLittle)
    std::reverse(b, b + sizeof(T));
  bytes.insert(bytes.end(), b, b + sizeof(T));
}

void appendValue(std::vector<unsigned char>& bytes, bp::RawScalarType type, double value, bool big)
{
  switch (type)
  {
    case bp::RawScalarType::UInt8:
      append<std::uint8_t>(bytes, value, big);
      break;
    case bp::RawScalarType::Int8:
      append<std::int8_t>(bytes, value, big);
      break;
    case bp::RawScalarType::UInt16:
      append<std::uint16_t>(bytes, value, big);
      break;
    case bp::RawScalarType::Int16:
      append<std::int16_t>(bytes, value, big);
      break;
    case bp::RawScalarType::UInt32:
      append<std::uint32_t>(bytes, value, big);
      break;
    case bp::RawScalarType::Int32:
      append<std::int32_t>(bytes, value, big);
      break;
    case bp::RawScalarType::Float32:
      append<float>(bytes, value, big);
      break;
    case bp::RawScalarType::Float64:
      append<double>(bytes, value, big);
      break;
  }
}

bool isUnsigned(bp::RawScalarType t)
{
  return t == bp::RawScalarType::UInt8 || t == bp::RawScalarType::UInt16 ||
    t == bp::RawScalarType::UInt32;
}

void writeFile(const fs::path& path, const std::vector<unsigned char>& bytes)
{
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

class RawVolumeSeriesTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    static int counter = 0;
    this->dir = fs::temp_directory_path() /
      ("bp-raw-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
    fs::create_directories(this->dir);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(this->dir, ec);
  }

  /// Writes a series and returns its descriptor. Unsigned types get the field
  /// shifted by +10 so every value is representable.
  bp::RawVolumeSeries write(int steps, bool threeFiles, bp::RawScalarType type,
    bp::RawByteOrder order, std::uint64_t header = 0, std::array<int, 3> dims = { 5, 4, 3 })
  {
    bp::RawVolumeSeries s;
    s.dims = dims;
    s.scalarType = type;
    s.byteOrder = order;
    s.headerBytes = header;
    s.baseDirectory = this->dir.string();
    const bool big = order == bp::RawByteOrder::Big;
    const double shift = isUnsigned(type) ? 10.0 : 0.0;
    const std::string tag =
      std::string(bp::rawScalarTypeName(type)) + (big ? "be" : "le") + (threeFiles ? "3" : "1");
    for (int step = 0; step < steps; ++step)
    {
      s.times.push_back(0.5 * step);
      std::vector<std::vector<unsigned char>> bytes(
        threeFiles ? 3 : 1, std::vector<unsigned char>(std::size_t(header), 0xAB));
      for (int k = 0; k < dims[2]; ++k)
        for (int j = 0; j < dims[1]; ++j)
          for (int i = 0; i < dims[0]; ++i)
            for (int c = 0; c < 3; ++c)
              appendValue(bytes[threeFiles ? c : 0], type, valueAt(i, j, k, c, step) + shift, big);
      std::vector<std::string> names;
      for (std::size_t f = 0; f < bytes.size(); ++f)
      {
        const std::string name =
          tag + "_" + std::to_string(step) + "_" + std::to_string(f) + ".raw";
        writeFile(this->dir / name, bytes[f]);
        names.push_back(name);
      }
      s.files.push_back(names);
    }
    EXPECT_EQ(s.validate(), "");
    return s;
  }

  fs::path dir;
};

std::vector<float> shifted(std::vector<float> v, float by)
{
  for (float& x : v)
    x += by;
  return v;
}
} // namespace

TEST(RawVolumeSeriesNames, TypesAndByteOrdersRoundTrip)
{
  for (const char* name :
    { "uint8", "int8", "uint16", "int16", "uint32", "int32", "float32", "float64" })
  {
    bp::RawScalarType t = bp::RawScalarType::Float32;
    ASSERT_TRUE(bp::parseRawScalarType(name, t)) << name;
    EXPECT_STREQ(bp::rawScalarTypeName(t), name);
  }
  bp::RawScalarType t = bp::RawScalarType::UInt8;
  EXPECT_FALSE(bp::parseRawScalarType("float", t));
  EXPECT_FALSE(bp::parseRawScalarType("Float32", t));
  EXPECT_NE(bp::rawScalarTypeNames().find("float64"), std::string::npos);
  EXPECT_EQ(bp::rawScalarTypeSize(bp::RawScalarType::Float64), 8u);
  EXPECT_EQ(bp::rawScalarTypeSize(bp::RawScalarType::Int16), 2u);
  bp::RawByteOrder o = bp::RawByteOrder::Little;
  EXPECT_TRUE(bp::parseRawByteOrder("big", o));
  EXPECT_EQ(o, bp::RawByteOrder::Big);
  EXPECT_FALSE(bp::parseRawByteOrder("network", o));
}

TEST(RawVolumeSeriesDescriptor, ValidateNamesTheProblem)
{
  bp::RawVolumeSeries s;
  s.dims = { 4, 4, 3 };
  s.times = { 0.0, 1.0 };
  s.files = { { "a.raw" }, { "u.raw", "v.raw", "w.raw" } };
  EXPECT_EQ(s.validate(), "");

  auto broken = s;
  broken.dims = { 4, 0, 3 };
  EXPECT_NE(broken.validate().find("dimensions"), std::string::npos);
  broken = s;
  broken.dims = { 1 << 20, 1 << 20, 1 << 20 };
  EXPECT_NE(broken.validate().find("dimensions"), std::string::npos);
  // 2^21 x 2^21 x 2^22 = 2^64 points used to wrap to 0 (an empty file matched).
  broken.dims = { 1 << 21, 1 << 21, 1 << 22 };
  EXPECT_EQ(broken.numberOfPoints(), std::numeric_limits<std::uint64_t>::max());
  EXPECT_NE(broken.validate().find("dimensions"), std::string::npos);
  broken = s;
  broken.spacing = { 1.0, -1.0, 1.0 };
  EXPECT_NE(broken.validate().find("spacing"), std::string::npos);
  broken = s;
  broken.headerBytes = std::uint64_t(1) << 60;
  EXPECT_NE(broken.validate().find("header_bytes"), std::string::npos);
  broken = s;
  broken.times = { 0.0 };
  EXPECT_NE(broken.validate().find("one time per step"), std::string::npos);
  broken = s;
  broken.times = { 1.0, 1.0 };
  EXPECT_NE(broken.validate().find("strictly increasing"), std::string::npos);
  broken = s;
  broken.files[1].pop_back();
  EXPECT_NE(broken.validate().find("files entry 1 lists 2 files"), std::string::npos);
  broken = s;
  broken.files.clear();
  broken.times.clear();
  EXPECT_NE(broken.validate().find("no time step"), std::string::npos);
  broken = s;
  broken.zCoordinates = { 0.0, 1.0 };
  EXPECT_NE(broken.validate().find("z_coordinates has 2 values"), std::string::npos);
  broken.zCoordinates = { 0.0, 2.0, 1.0 };
  EXPECT_NE(broken.validate().find("z_coordinates must be strictly increasing"), std::string::npos);
  broken.zCoordinates = { 0.0, 1.0, 10.0 };
  broken.spacing[2] = 0.0; // unused with z coordinates
  EXPECT_EQ(broken.validate(), "");
}

TEST(RawVolumeSeriesDescriptor, StepAtOrBeforeSnapsDown)
{
  bp::RawVolumeSeries s;
  s.times = { 0.0, 0.1, 0.2, 0.5 };
  EXPECT_EQ(s.stepAtOrBefore(-3.0), 0);
  EXPECT_EQ(s.stepAtOrBefore(0.0), 0);
  EXPECT_EQ(s.stepAtOrBefore(0.15), 1);
  EXPECT_EQ(s.stepAtOrBefore(0.2), 2);
  EXPECT_EQ(s.stepAtOrBefore(0.2 - 1e-13), 2); // round-off absorbed
  EXPECT_EQ(s.stepAtOrBefore(0.49), 2);
  EXPECT_EQ(s.stepAtOrBefore(7.0), 3);
  s.times.clear();
  EXPECT_EQ(s.stepAtOrBefore(1.0), -1);
}

TEST(RawVolumeSeriesDescriptor, RelativePathsResolveAgainstTheDescriptorFolder)
{
  bp::RawVolumeSeries s;
  s.baseDirectory = "/data/bonnie";
  EXPECT_EQ(s.resolve("step1.raw"), "/data/bonnie/step1.raw");
  EXPECT_EQ(s.resolve("sub/step1.raw"), "/data/bonnie/sub/step1.raw");
  EXPECT_EQ(s.resolve("/abs/step1.raw"), "/abs/step1.raw");
}

TEST_F(RawVolumeSeriesTest, BothLayoutsBothByteOrdersEveryType)
{
  for (bp::RawScalarType type : { bp::RawScalarType::UInt8, bp::RawScalarType::Int8,
         bp::RawScalarType::UInt16, bp::RawScalarType::Int16, bp::RawScalarType::UInt32,
         bp::RawScalarType::Int32, bp::RawScalarType::Float32, bp::RawScalarType::Float64 })
    for (bp::RawByteOrder order : { bp::RawByteOrder::Little, bp::RawByteOrder::Big })
      for (bool threeFiles : { false, true })
      {
        SCOPED_TRACE(std::string(bp::rawScalarTypeName(type)) + " " +
          (order == bp::RawByteOrder::Big ? "big" : "little") +
          (threeFiles ? " three files" : " interleaved"));
        const auto s = this->write(2, threeFiles, type, order);
        const float shift = isUnsigned(type) ? 10.0f : 0.0f;
        for (int step = 0; step < 2; ++step)
        {
          std::vector<float> v;
          ASSERT_EQ(bp::readRawVolumeStep(s, std::size_t(step), v), "");
          EXPECT_EQ(v, shifted(expectedStep(s, step), shift));
        }
      }
}

TEST_F(RawVolumeSeriesTest, HeaderBytesAreSkipped)
{
  for (bool threeFiles : { false, true })
  {
    const auto s =
      this->write(1, threeFiles, bp::RawScalarType::Float32, bp::RawByteOrder::Big, 16);
    std::vector<float> v;
    ASSERT_EQ(bp::readRawVolumeStep(s, 0, v), "");
    EXPECT_EQ(v, expectedStep(s, 0));
    // Forgetting the header makes every file 16 bytes too long.
    auto noHeader = s;
    noHeader.headerBytes = 0;
    const std::string error = bp::readRawVolumeStep(noHeader, 0, v);
    EXPECT_NE(error.find("wrong size"), std::string::npos) << error;
    EXPECT_TRUE(v.empty());
  }
}

TEST_F(RawVolumeSeriesTest, LargerThanOneChunk)
{
  // 120 x 100 x 30 x 3 values: several conversion chunks, split across the three files.
  const auto s =
    this->write(1, true, bp::RawScalarType::Int16, bp::RawByteOrder::Big, 3, { 120, 100, 30 });
  std::vector<float> v;
  ASSERT_EQ(bp::readRawVolumeStep(s, 0, v), "");
  EXPECT_EQ(v, expectedStep(s, 0));
}

TEST_F(RawVolumeSeriesTest, MissingFileIsNamed)
{
  auto s = this->write(2, true, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  const std::string victim = s.resolve(s.files[1][1]);
  fs::remove(victim);
  std::vector<float> v = { 1.0f };
  const std::string error = bp::readRawVolumeStep(s, 1, v);
  EXPECT_NE(error.find(victim), std::string::npos) << error;
  EXPECT_NE(error.find("does not exist"), std::string::npos) << error;
  EXPECT_NE(error.find("step 1's v file"), std::string::npos) << error;
  EXPECT_TRUE(v.empty());
  EXPECT_EQ(bp::readRawVolumeStep(s, 0, v), "");
  // A directory where a file should be.
  fs::create_directory(victim);
  EXPECT_NE(bp::checkRawVolumeStep(s, 1).find("not a regular file"), std::string::npos);
  // A step that is not there.
  EXPECT_NE(bp::readRawVolumeStep(s, 7, v).find("does not exist"), std::string::npos);
}

TEST_F(RawVolumeSeriesTest, TruncatedFileIsNamed)
{
  auto s = this->write(1, false, bp::RawScalarType::Float64, bp::RawByteOrder::Little);
  const std::string victim = s.resolve(s.files[0][0]);
  const auto size = fs::file_size(victim);
  fs::resize_file(victim, size - 5);
  std::vector<float> v;
  const std::string error = bp::readRawVolumeStep(s, 0, v);
  EXPECT_NE(error.find(victim), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_NE(error.find(std::to_string(size - 5)), std::string::npos) << error;
  EXPECT_NE(error.find(std::to_string(size)), std::string::npos) << error;
  EXPECT_TRUE(v.empty());
  fs::resize_file(victim, 0);
  EXPECT_NE(bp::readRawVolumeStep(s, 0, v).find("truncated"), std::string::npos);
}

TEST_F(RawVolumeSeriesTest, OversizedFileGivesExpectedAndActualSize)
{
  auto s = this->write(1, true, bp::RawScalarType::UInt16, bp::RawByteOrder::Little);
  const std::string victim = s.resolve(s.files[0][2]);
  const auto size = fs::file_size(victim);
  fs::resize_file(victim, size + 2);
  std::vector<float> v;
  const std::string error = bp::readRawVolumeStep(s, 0, v);
  EXPECT_NE(error.find(victim), std::string::npos) << error;
  EXPECT_NE(error.find("step 0's w file"), std::string::npos) << error;
  EXPECT_NE(error.find("expected " + std::to_string(size) + " bytes"), std::string::npos) << error;
  EXPECT_NE(error.find("actual size " + std::to_string(size + 2)), std::string::npos) << error;
  EXPECT_TRUE(v.empty());
}

TEST_F(RawVolumeSeriesTest, WrongTypeIsCaughtBySize)
{
  auto s = this->write(1, false, bp::RawScalarType::Float64, bp::RawByteOrder::Little);
  s.scalarType = bp::RawScalarType::Float32;
  std::vector<float> v;
  EXPECT_NE(bp::readRawVolumeStep(s, 0, v).find("wrong size"), std::string::npos);
  s.scalarType = bp::RawScalarType::Float64;
  s.dims[0] += 1;
  EXPECT_NE(bp::readRawVolumeStep(s, 0, v).find("truncated"), std::string::npos);
}

TEST_F(RawVolumeSeriesTest, InvalidDescriptorIsNotRead)
{
  auto s = this->write(1, false, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  s.times.push_back(3.0);
  std::vector<float> v;
  EXPECT_NE(bp::readRawVolumeStep(s, 0, v).find("times"), std::string::npos);
  EXPECT_TRUE(v.empty());
}

TEST_F(RawVolumeSeriesTest, CancelStopsARead)
{
  const auto s = this->write(1, false, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  std::atomic<bool> cancel{ true };
  std::vector<float> v;
  EXPECT_EQ(bp::readRawVolumeStep(s, 0, v, &cancel), "cancelled");
  EXPECT_TRUE(v.empty());
}

TEST_F(RawVolumeSeriesTest, ReadAheadServesTheNextStep)
{
  const auto s = this->write(5, false, bp::RawScalarType::Int16, bp::RawByteOrder::Big);
  bp::RawVolumeReadAhead reader(s);
  std::vector<float> v;
  for (std::size_t k = 0; k < 5; ++k)
  {
    ASSERT_EQ(reader.read(k, v), "");
    EXPECT_EQ(v, expectedStep(s, int(k))) << "step " << k;
  }
  EXPECT_EQ(reader.readAheadHits(), 4u);
  EXPECT_EQ(reader.stepsRead(), 5u); // step 0 directly, 1..4 ahead, nothing past the end
}

TEST_F(RawVolumeSeriesTest, ReadAheadOutOfOrderStillReadsTheRightStep)
{
  const auto s = this->write(6, true, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  bp::RawVolumeReadAhead reader(s);
  std::vector<float> v;
  for (std::size_t k : { 3, 1, 2, 0, 5, 4, 4, 5 })
  {
    ASSERT_EQ(reader.read(k, v), "");
    EXPECT_EQ(v, expectedStep(s, int(k))) << "step " << k;
  }
  // 3 (+4 ahead, dropped), 1 (+2 ahead), 2 hit (+3 ahead, dropped), 0 (+1 ahead, dropped),
  // 5 (last: nothing ahead), 4 (+5 ahead, dropped), 4 (+5 ahead), 5 hit.
  EXPECT_EQ(reader.readAheadHits(), 2u);
  EXPECT_EQ(reader.stepsRead(), 12u);
}

TEST_F(RawVolumeSeriesTest, ReadAheadOffReadsOnlyWhatIsAsked)
{
  const auto s = this->write(4, false, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  bp::RawVolumeReadAhead reader(s, false);
  EXPECT_FALSE(reader.readAhead());
  std::vector<float> v;
  for (std::size_t k : { 0, 1, 2 })
    ASSERT_EQ(reader.read(k, v), "");
  EXPECT_EQ(v, expectedStep(s, 2));
  EXPECT_EQ(reader.stepsRead(), 3u);
  EXPECT_EQ(reader.readAheadHits(), 0u);
  reader.setReadAhead(true);
  ASSERT_EQ(reader.read(0, v), "");
  ASSERT_EQ(reader.read(1, v), "");
  EXPECT_EQ(reader.readAheadHits(), 1u);
  reader.setReadAhead(false); // drops step 2 read ahead
  ASSERT_EQ(reader.read(2, v), "");
  EXPECT_EQ(reader.readAheadHits(), 1u);
  EXPECT_EQ(v, expectedStep(s, 2));
  reader.setReadAhead(true);
  ASSERT_EQ(reader.read(1, v), "");
  reader.dropReadAhead(); // step 2 again
  ASSERT_EQ(reader.read(2, v), "");
  EXPECT_EQ(reader.readAheadHits(), 1u);
  EXPECT_EQ(v, expectedStep(s, 2));
}

TEST_F(RawVolumeSeriesTest, ReadAheadOfABrokenStepReportsItWhenAsked)
{
  const auto s = this->write(3, false, bp::RawScalarType::Float32, bp::RawByteOrder::Little);
  const std::string victim = s.resolve(s.files[1][0]);
  fs::resize_file(victim, 7);
  bp::RawVolumeReadAhead reader(s);
  std::vector<float> v;
  ASSERT_EQ(reader.read(0, v), "");
  const std::string error = reader.read(1, v);
  EXPECT_NE(error.find(victim), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_TRUE(v.empty());
  ASSERT_EQ(reader.read(2, v), "");
  EXPECT_EQ(v, expectedStep(s, 2));
}

TEST_F(RawVolumeSeriesTest, ReadAheadFromSeveralThreadsAndEarlyDestruction)
{
  const auto s =
    this->write(6, false, bp::RawScalarType::Float64, bp::RawByteOrder::Big, 0, { 60, 50, 40 });
  std::vector<std::vector<float>> expected;
  for (int k = 0; k < 6; ++k)
    expected.push_back(expectedStep(s, k));
  {
    bp::RawVolumeReadAhead reader(s);
    std::atomic<int> wrong{ 0 };
    std::vector<std::thread> threads;
    for (int t = 0; t < 4; ++t)
      threads.emplace_back(
        [&, t]()
        {
          std::vector<float> v;
          for (int i = 0; i < 6; ++i)
          {
            const std::size_t k = std::size_t((i + t) % 6);
            if (!reader.read(k, v).empty() || v != expected[k])
              ++wrong;
          }
        });
    for (auto& th : threads)
      th.join();
    EXPECT_EQ(wrong.load(), 0);
  }
  {
    // Destroyed while step 1 is being read ahead: the destructor cancels and waits.
    bp::RawVolumeReadAhead reader(s);
    std::vector<float> v;
    ASSERT_EQ(reader.read(0, v), "");
  }
}

// SPDX-License-Identifier: BSD-3-Clause
#include "RawVolumeSeries.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <new>
#include <sstream>
#include <system_error>
#include <utility>

namespace bp
{
namespace fs = std::filesystem;

namespace
{
constexpr RawScalarType AllTypes[] = { RawScalarType::UInt8, RawScalarType::Int8,
  RawScalarType::UInt16, RawScalarType::Int16, RawScalarType::UInt32, RawScalarType::Int32,
  RawScalarType::Float32, RawScalarType::Float64 };

/// Values converted per chunk: bounds the scratch buffer at 8 MiB.
constexpr std::size_t ChunkValues = std::size_t(1) << 20;

/// A grid this large is a typo, not a data set (12 TB of floats per step).
constexpr std::uint64_t MaxPoints = std::uint64_t(1) << 40;
/// Keeps header + data sizes far from overflow (1 PiB).
constexpr std::uint64_t MaxHeaderBytes = std::uint64_t(1) << 50;

bool hostIsLittleEndian()
{
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

template <typename T>
void convert(
  const unsigned char* bytes, std::size_t count, bool swap, float* out, std::size_t stride)
{
  unsigned char buffer[sizeof(T)];
  for (std::size_t i = 0; i < count; ++i, bytes += sizeof(T))
  {
    if (swap)
      std::reverse_copy(bytes, bytes + sizeof(T), buffer);
    else
      std::memcpy(buffer, bytes, sizeof(T));
    T value;
    std::memcpy(&value, buffer, sizeof(T));
    out[i * stride] = static_cast<float>(value);
  }
}

void convertValues(RawScalarType type, const unsigned char* bytes, std::size_t count, bool swap,
  float* out, std::size_t stride)
{
  switch (type)
  {
    case RawScalarType::UInt8:
      convert<std::uint8_t>(bytes, count, false, out, stride);
      break;
    case RawScalarType::Int8:
      convert<std::int8_t>(bytes, count, false, out, stride);
      break;
    case RawScalarType::UInt16:
      convert<std::uint16_t>(bytes, count, swap, out, stride);
      break;
    case RawScalarType::Int16:
      convert<std::int16_t>(bytes, count, swap, out, stride);
      break;
    case RawScalarType::UInt32:
      convert<std::uint32_t>(bytes, count, swap, out, stride);
      break;
    case RawScalarType::Int32:
      convert<std::int32_t>(bytes, count, swap, out, stride);
      break;
    case RawScalarType::Float32:
      convert<float>(bytes, count, swap, out, stride);
      break;
    case RawScalarType::Float64:
      convert<double>(bytes, count, swap, out, stride);
      break;
  }
}

/// "step 3's file 'a/b.raw'" or "step 3's v file 'a/v3.raw'".
std::string describeFile(
  std::size_t step, std::size_t component, std::size_t count, const std::string& path)
{
  static const char* const names[] = { "u", "v", "w" };
  std::ostringstream s;
  s << "step " << step << "'s ";
  if (count == 3)
    s << names[component] << " ";
  s << "file '" << path << "'";
  return s.str();
}

std::string dimsText(const RawVolumeSeries& series)
{
  std::ostringstream s;
  s << series.dims[0] << "x" << series.dims[1] << "x" << series.dims[2];
  return s.str();
}

bool allFinite(const std::array<double, 3>& v)
{
  return std::isfinite(v[0]) && std::isfinite(v[1]) && std::isfinite(v[2]);
}
} // namespace

const char* rawScalarTypeName(RawScalarType type)
{
  switch (type)
  {
    case RawScalarType::UInt8:
      return "uint8";
    case RawScalarType::Int8:
      return "int8";
    case RawScalarType::UInt16:
      return "uint16";
    case RawScalarType::Int16:
      return "int16";
    case RawScalarType::UInt32:
      return "uint32";
    case RawScalarType::Int32:
      return "int32";
    case RawScalarType::Float32:
      return "float32";
    case RawScalarType::Float64:
      return "float64";
  }
  return "unknown";
}

std::size_t rawScalarTypeSize(RawScalarType type)
{
  switch (type)
  {
    case RawScalarType::UInt8:
    case RawScalarType::Int8:
      return 1;
    case RawScalarType::UInt16:
    case RawScalarType::Int16:
      return 2;
    case RawScalarType::UInt32:
    case RawScalarType::Int32:
    case RawScalarType::Float32:
      return 4;
    case RawScalarType::Float64:
      return 8;
  }
  return 0;
}

bool parseRawScalarType(const std::string& name, RawScalarType& type)
{
  for (RawScalarType t : AllTypes)
    if (name == rawScalarTypeName(t))
    {
      type = t;
      return true;
    }
  return false;
}

std::string rawScalarTypeNames()
{
  std::string names;
  for (RawScalarType t : AllTypes)
    names += (names.empty() ? "" : ", ") + std::string(rawScalarTypeName(t));
  return names;
}

bool parseRawByteOrder(const std::string& name, RawByteOrder& order)
{
  if (name == "little")
    order = RawByteOrder::Little;
  else if (name == "big")
    order = RawByteOrder::Big;
  else
    return false;
  return true;
}

std::uint64_t RawVolumeSeries::numberOfPoints() const
{
  if (this->dims[0] < 1 || this->dims[1] < 1 || this->dims[2] < 1)
    return 0;
  // Three ints can multiply past 2^64 (2^21 x 2^21 x 2^22 wraps to 0, which
  // an empty file would match): the count saturates instead.
  std::uint64_t count = 1;
  for (int d : this->dims)
  {
    if (__builtin_mul_overflow(count, std::uint64_t(d), &count))
      return std::numeric_limits<std::uint64_t>::max();
  }
  return count;
}

std::uint64_t RawVolumeSeries::expectedFileSize(bool interleaved) const
{
  return this->headerBytes +
    (interleaved ? 3 : 1) * this->numberOfPoints() * rawScalarTypeSize(this->scalarType);
}

std::string RawVolumeSeries::resolve(const std::string& path) const
{
  const fs::path p(path);
  if (p.is_absolute() || this->baseDirectory.empty())
    return path;
  return (fs::path(this->baseDirectory) / p).string();
}

int RawVolumeSeries::stepAtOrBefore(double t) const
{
  if (this->times.empty())
    return -1;
  if (!std::isfinite(t))
    return 0;
  const double range = this->times.back() - this->times.front();
  const double tolerance = 1e-9 * std::max({ 1.0, std::abs(range), std::abs(t) });
  const auto after = std::upper_bound(this->times.begin(), this->times.end(), t + tolerance);
  return after == this->times.begin() ? 0 : int(after - this->times.begin()) - 1;
}

std::string RawVolumeSeries::validate() const
{
  std::ostringstream e;
  if (this->dims[0] < 1 || this->dims[1] < 1 || this->dims[2] < 1)
    e << "dimensions must be three positive point counts [nx, ny, nz], not [" << this->dims[0]
      << ", " << this->dims[1] << ", " << this->dims[2] << "]";
  else if (this->numberOfPoints() > MaxPoints)
    e << "dimensions " << dimsText(*this) << " give " << this->numberOfPoints()
      << " points, more than any volume this reader can hold; check dimensions";
  else if (!allFinite(this->origin))
    e << "origin must be three finite numbers";
  else if (!allFinite(this->spacing) || this->spacing[0] <= 0 || this->spacing[1] <= 0 ||
    (this->zCoordinates.empty() && this->spacing[2] <= 0))
    e << "spacing must be three positive numbers, not [" << this->spacing[0] << ", "
      << this->spacing[1] << ", " << this->spacing[2] << "]";
  else if (rawScalarTypeSize(this->scalarType) == 0)
    e << "unknown scalar type; use one of " << rawScalarTypeNames();
  else if (this->headerBytes > MaxHeaderBytes)
    e << "header_bytes " << this->headerBytes << " is larger than any file; check it";
  else if (this->arrayName.empty())
    e << "array_name must not be empty";
  else if (this->files.empty())
    e << "files lists no time step; give one entry per step";
  else if (this->times.size() != this->files.size())
    e << "times has " << this->times.size() << " values but files has " << this->files.size()
      << " steps; give one time per step";
  if (!e.str().empty())
    return e.str();

  for (std::size_t k = 0; k < this->files.size(); ++k)
  {
    const auto& step = this->files[k];
    if (step.size() != 1 && step.size() != 3)
      return "files entry " + std::to_string(k) + " lists " + std::to_string(step.size()) +
        " files; give one file of interleaved (u, v, w) values or three files [u, v, w]";
    for (const auto& f : step)
      if (f.empty())
        return "files entry " + std::to_string(k) + " has an empty file name";
  }
  for (std::size_t k = 0; k < this->times.size(); ++k)
  {
    if (!std::isfinite(this->times[k]))
      return "times[" + std::to_string(k) + "] is not a finite number";
    if (k > 0 && !(this->times[k] > this->times[k - 1]))
      return "times must be strictly increasing, but times[" + std::to_string(k) +
        "] does not exceed times[" + std::to_string(k - 1) + "]";
  }
  if (!this->zCoordinates.empty())
  {
    if (this->zCoordinates.size() != std::size_t(this->dims[2]))
      return "z_coordinates has " + std::to_string(this->zCoordinates.size()) +
        " values but the volume has " + std::to_string(this->dims[2]) +
        " layers (dimensions[2]); give one z per layer";
    for (std::size_t k = 0; k < this->zCoordinates.size(); ++k)
    {
      if (!std::isfinite(this->zCoordinates[k]))
        return "z_coordinates[" + std::to_string(k) + "] is not a finite number";
      if (k > 0 && !(this->zCoordinates[k] > this->zCoordinates[k - 1]))
        return "z_coordinates must be strictly increasing, but z_coordinates[" + std::to_string(k) +
          "] does not exceed z_coordinates[" + std::to_string(k - 1) + "]";
    }
  }
  return std::string();
}

std::string checkRawVolumeStep(const RawVolumeSeries& series, std::size_t step)
{
  if (step >= series.files.size())
    return "step " + std::to_string(step) + " does not exist: the series has " +
      std::to_string(series.files.size()) + " steps";
  const auto& names = series.files[step];
  const bool interleaved = names.size() == 1;
  const std::uint64_t expected = series.expectedFileSize(interleaved);
  for (std::size_t c = 0; c < names.size(); ++c)
  {
    const std::string path = series.resolve(names[c]);
    const std::string which = describeFile(step, c, names.size(), path);
    std::error_code ec;
    const fs::file_status status = fs::status(path, ec);
    if (!fs::exists(status))
      return which +
        " does not exist; check the name in files (relative names are relative to "
        "the descriptor's folder)";
    if (!fs::is_regular_file(status))
      return which + " is not a regular file";
    const std::uintmax_t actual = fs::file_size(path, ec);
    if (ec)
      return which + " cannot be read: " + ec.message();
    std::ostringstream layout;
    if (series.headerBytes > 0)
      layout << series.headerBytes << " header bytes + ";
    layout << (interleaved ? "3 x " : "") << dimsText(series) << " "
           << rawScalarTypeName(series.scalarType) << " values";
    if (actual < expected)
      return which + " is truncated: it has " + std::to_string(actual) + " bytes but " +
        layout.str() + " need " + std::to_string(expected) +
        " bytes; check dimensions, scalar_type and header_bytes, or replace the file";
    if (actual > expected)
      return which + " has the wrong size: expected " + std::to_string(expected) + " bytes (" +
        layout.str() + "), actual size " + std::to_string(actual) +
        " bytes; check dimensions, scalar_type and header_bytes";
    std::ifstream probe(path, std::ios::binary);
    if (!probe)
      return which + " cannot be opened for reading; check its permissions";
  }
  return std::string();
}

std::string readRawVolumeStep(const RawVolumeSeries& series, std::size_t step,
  std::vector<float>& values, const std::atomic<bool>* cancel)
{
  values.clear();
  std::string error = series.validate();
  if (!error.empty())
    return error;
  error = checkRawVolumeStep(series, step);
  if (!error.empty())
    return error;

  const std::uint64_t n = series.numberOfPoints();
  const auto& names = series.files[step];
  const bool interleaved = names.size() == 1;
  const std::size_t typeSize = rawScalarTypeSize(series.scalarType);
  const bool swap =
    typeSize > 1 && hostIsLittleEndian() != (series.byteOrder == RawByteOrder::Little);
  std::vector<unsigned char> chunk;
  try
  {
    values.resize(std::size_t(3 * n));
    chunk.resize(ChunkValues * typeSize);
  }
  catch (const std::bad_alloc&)
  {
    values.clear();
    values.shrink_to_fit();
    return "not enough memory for step " + std::to_string(step) + " (" + dimsText(series) +
      " points)";
  }

  for (std::size_t c = 0; c < names.size(); ++c)
  {
    const std::string path = series.resolve(names[c]);
    std::ifstream in(path, std::ios::binary);
    if (!in || !in.seekg(std::streamoff(series.headerBytes)))
    {
      values.clear();
      return describeFile(step, c, names.size(), path) + " cannot be opened for reading";
    }
    const std::uint64_t count = interleaved ? 3 * n : n;
    float* out = values.data() + (interleaved ? 0 : c);
    const std::size_t stride = interleaved ? 1 : 3;
    for (std::uint64_t done = 0; done < count;)
    {
      if (cancel && cancel->load())
      {
        values.clear();
        return "cancelled";
      }
      const std::size_t now = std::size_t(std::min<std::uint64_t>(ChunkValues, count - done));
      in.read(reinterpret_cast<char*>(chunk.data()), std::streamsize(now * typeSize));
      if (std::size_t(in.gcount()) != now * typeSize)
      {
        values.clear();
        return describeFile(step, c, names.size(), path) + " could not be read past byte " +
          std::to_string(series.headerBytes + done * typeSize + std::size_t(in.gcount())) +
          " (was it changed while being read?)";
      }
      convertValues(series.scalarType, chunk.data(), now, swap, out + done * stride, stride);
      done += now;
    }
  }
  return std::string();
}

RawVolumeReadAhead::RawVolumeReadAhead(RawVolumeSeries series, bool readAhead)
  : Series(std::make_shared<const RawVolumeSeries>(std::move(series)))
  , ReadAhead(readAhead)
{
}

RawVolumeReadAhead::~RawVolumeReadAhead()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->dropPending();
}

void RawVolumeReadAhead::setReadAhead(bool on)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->ReadAhead = on;
  if (!on)
    this->dropPending();
}

void RawVolumeReadAhead::dropReadAhead()
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  this->dropPending();
}

bool RawVolumeReadAhead::readAhead() const
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  return this->ReadAhead;
}

std::string RawVolumeReadAhead::read(std::size_t step, std::vector<float>& values)
{
  std::lock_guard<std::mutex> lock(this->Mutex);
  bool served = false;
  if (this->Ahead && this->Ahead->step == step)
  {
    std::pair<std::string, std::vector<float>> result;
    try
    {
      result = this->Ahead->result.get();
    }
    catch (...)
    {
      result.first = "read-ahead failed";
    }
    this->Ahead.reset();
    // A failed read-ahead is retried directly, so the error is current.
    if (result.first.empty())
    {
      values = std::move(result.second);
      served = true;
      ++this->Hits;
    }
  }
  else
    this->dropPending();

  if (!served)
  {
    ++this->StepsRead;
    const std::string error = readRawVolumeStep(*this->Series, step, values);
    if (!error.empty())
      return error;
  }
  if (this->ReadAhead && step + 1 < this->Series->numberOfSteps())
    this->startPending(step + 1);
  return std::string();
}

void RawVolumeReadAhead::dropPending()
{
  if (!this->Ahead)
    return;
  this->Ahead->cancel->store(true);
  if (this->Ahead->result.valid())
    this->Ahead->result.wait();
  this->Ahead.reset();
}

void RawVolumeReadAhead::startPending(std::size_t step)
{
  auto pending = std::make_unique<Pending>();
  pending->step = step;
  pending->cancel = std::make_shared<std::atomic<bool>>(false);
  std::shared_ptr<const RawVolumeSeries> series = this->Series;
  std::shared_ptr<std::atomic<bool>> cancel = pending->cancel;
  try
  {
    pending->result = std::async(std::launch::async,
      [series, step, cancel]()
      {
        std::pair<std::string, std::vector<float>> result;
        result.first = readRawVolumeStep(*series, step, result.second, cancel.get());
        return result;
      });
  }
  catch (const std::system_error&)
  {
    return; // no thread to spare: the next step is read when asked for
  }
  ++this->StepsRead;
  this->Ahead = std::move(pending);
}

} // namespace bp

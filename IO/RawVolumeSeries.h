// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RawVolumeSeries.h
 * @brief Time series of raw binary vector volumes: descriptor, reading, read-ahead.
 *
 * Real flows often come as one raw binary volume per time step (the hurricane
 * of the thesis: 121 steps of 19 MB), either one file of interleaved (u, v, w)
 * triplets or three files, one per component. A RawVolumeSeries describes such
 * a series (grid, scalar type, byte order, times, files); readRawVolumeStep()
 * turns one step into 3 N interleaved floats in VTK point order (x fastest);
 * RawVolumeReadAhead reads the next step on a background thread while the
 * current one is in use. Plain C++17: the VTK reader parses the JSON descriptor
 * and fills the struct.
 */
#ifndef BoundParticles_RawVolumeSeries_h
#define BoundParticles_RawVolumeSeries_h

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace bp
{

/// The type of every value in the files.
enum class RawScalarType
{
  UInt8,
  Int8,
  UInt16,
  Int16,
  UInt32,
  Int32,
  Float32,
  Float64
};

/// Byte order of the multi-byte values in the files.
enum class RawByteOrder
{
  Little,
  Big
};

/// "uint8", "int8", "uint16", "int16", "uint32", "int32", "float32", "float64".
const char* rawScalarTypeName(RawScalarType type);
/// Bytes per value.
std::size_t rawScalarTypeSize(RawScalarType type);
/// Parses a type name (as rawScalarTypeName() writes it); false if unknown.
bool parseRawScalarType(const std::string& name, RawScalarType& type);
/// The accepted type names, for messages: "uint8, int8, ..., float64".
std::string rawScalarTypeNames();

/// Parses "little" or "big"; false otherwise.
bool parseRawByteOrder(const std::string& name, RawByteOrder& order);

/// A series of raw vector volumes on one grid.
struct RawVolumeSeries
{
  std::array<int, 3> dims = { 0, 0, 0 };            ///< points along x, y, z
  std::array<double, 3> origin = { 0.0, 0.0, 0.0 }; ///< position of point (0, 0, 0)
  std::array<double, 3> spacing = { 1.0, 1.0,
    1.0 }; ///< uniform spacing (z unused with zCoordinates)
  RawScalarType scalarType = RawScalarType::Float32;
  RawByteOrder byteOrder = RawByteOrder::Little;
  std::uint64_t headerBytes = 0; ///< bytes skipped at the start of every file
  std::vector<double> times;     ///< one per step, strictly increasing
  /// One entry per step: one file of interleaved (u, v, w) triplets, or three
  /// files holding u, v and w. Relative paths are relative to baseDirectory.
  std::vector<std::vector<std::string>> files;
  /// Empty (uniform z), or dims[2] strictly increasing z values of the layers.
  std::vector<double> zCoordinates;
  std::string arrayName = "velocity"; ///< name of the output array
  std::string baseDirectory;          ///< folder of the descriptor

  /// Empty when the descriptor is usable, otherwise what is wrong and how to
  /// fix it. Checks the description only, not the files.
  std::string validate() const;

  std::size_t numberOfSteps() const { return this->files.size(); }
  /// dims[0] * dims[1] * dims[2] (0 for bad dims).
  std::uint64_t numberOfPoints() const;
  /// Bytes each file of a step must have: headerBytes + values * type size,
  /// where a file holds 3 N values when interleaved and N otherwise.
  std::uint64_t expectedFileSize(bool interleaved) const;
  /// The path of a file as listed, resolved against baseDirectory.
  std::string resolve(const std::string& path) const;
  /// The step at or before time t (the first step when t precedes it). A
  /// small tolerance absorbs round-off in t. -1 when there are no steps.
  int stepAtOrBefore(double t) const;
};

/// Checks that step's files exist, are readable regular files and have exactly
/// the expected size, without reading them. Empty when fine, otherwise an
/// error naming the file.
std::string checkRawVolumeStep(const RawVolumeSeries& series, std::size_t step);

/// Reads step into values (resized to 3 N, interleaved, x fastest), converting
/// the type to float and swapping bytes when needed. Returns an empty string,
/// or an error naming the offending file (values then cleared). The series
/// must validate(). When cancel becomes true the read stops early and returns
/// "cancelled".
std::string readRawVolumeStep(const RawVolumeSeries& series, std::size_t step,
  std::vector<float>& values, const std::atomic<bool>* cancel = nullptr);

/**
 * Reads steps of one series, reading step k + 1 on a background thread after
 * step k so that playing forward is served from memory. A request for any
 * other step drops the read-ahead and reads directly. At most one step is
 * held ahead. Thread-safe; the destructor cancels and waits for the
 * background read.
 */
class RawVolumeReadAhead
{
public:
  explicit RawVolumeReadAhead(RawVolumeSeries series, bool readAhead = true);
  ~RawVolumeReadAhead();
  RawVolumeReadAhead(const RawVolumeReadAhead&) = delete;
  RawVolumeReadAhead& operator=(const RawVolumeReadAhead&) = delete;

  const RawVolumeSeries& series() const { return *this->Series; }

  /// Turns read-ahead on or off; off drops any step read ahead.
  void setReadAhead(bool on);
  bool readAhead() const;

  /// Drops the step read ahead, if any (say, because the files changed on disk).
  void dropReadAhead();

  /// Reads step into values as readRawVolumeStep() does, from the read-ahead
  /// when it holds that step, and then starts reading step + 1 ahead.
  std::string read(std::size_t step, std::vector<float>& values);

  /// Steps read from disk, direct and ahead (a read-ahead counts when it starts).
  std::size_t stepsRead() const { return this->StepsRead.load(); }
  /// Requests served from the read-ahead.
  std::size_t readAheadHits() const { return this->Hits.load(); }

private:
  struct Pending
  {
    std::size_t step = 0;
    std::shared_ptr<std::atomic<bool>> cancel;
    std::future<std::pair<std::string, std::vector<float>>> result;
  };

  void dropPending();                  // with Mutex held
  void startPending(std::size_t step); // with Mutex held

  std::shared_ptr<const RawVolumeSeries> Series;
  mutable std::mutex Mutex;
  bool ReadAhead = true;
  std::unique_ptr<Pending> Ahead;
  std::atomic<std::size_t> StepsRead{ 0 };
  std::atomic<std::size_t> Hits{ 0 };
};

} // namespace bp

#endif

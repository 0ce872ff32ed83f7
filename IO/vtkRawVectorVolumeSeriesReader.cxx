// SPDX-License-Identifier: BSD-3-Clause
#include "vtkRawVectorVolumeSeriesReader.h"

#include "RawVolumeSeries.h"

#include "vtkDataObject.h"
#include "vtkDataSet.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkRectilinearGrid.h"
#include "vtkSmartPointer.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "vtk_jsoncpp.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

vtkStandardNewMacro(vtkRawVectorVolumeSeriesReader);

namespace
{
namespace fs = std::filesystem;

/// A descriptor is a few kilobytes; anything this large is a data file opened by mistake.
constexpr std::uintmax_t MaxDescriptorBytes = std::uintmax_t(16) << 20;

const char* const KnownKeys[] = { "dimensions", "origin", "spacing", "scalar_type", "byte_order",
  "header_bytes", "times", "files", "z_coordinates", "array_name", "description" };

std::string knownKeys()
{
  std::string s;
  for (const char* k : KnownKeys)
    s += (s.empty() ? "" : ", ") + std::string(k);
  return s;
}

/// Reads three numbers; empty on success, otherwise what is wrong.
template <typename T, typename Check>
std::string readTriple(const Json::Value& value, const char* key, T (&out)[3], Check valid)
{
  if (!value.isArray() || value.size() != 3)
    return std::string("'") + key + "' must be an array of three numbers [x, y, z]";
  for (Json::ArrayIndex i = 0; i < 3; ++i)
  {
    if (!valid(value[i]))
      return std::string("'") + key + "'[" + std::to_string(i) + "] is not a valid value";
    out[i] = static_cast<T>(value[i].asDouble());
  }
  return std::string();
}

std::string readNumbers(const Json::Value& value, const char* key, std::vector<double>& out)
{
  if (!value.isArray())
    return std::string("'") + key + "' must be an array of numbers";
  out.clear();
  for (Json::ArrayIndex i = 0; i < value.size(); ++i)
  {
    if (!value[i].isNumeric())
      return std::string("'") + key + "'[" + std::to_string(i) + "] is not a number";
    out.push_back(value[i].asDouble());
  }
  return std::string();
}

/// The descriptor's text parsed into `root`, a JSON object with only known keys.
std::string parseObject(const std::string& text, Json::Value& root)
{
  Json::CharReaderBuilder builder;
  builder["collectComments"] = false;
  builder["allowComments"] = true;
  builder["failIfExtra"] = true;
  builder["rejectDupKeys"] = true;
  std::unique_ptr<Json::CharReader> reader(builder.newCharReader());
  std::string errors;
  if (!reader->parse(text.data(), text.data() + text.size(), &root, &errors))
  {
    // jsoncpp lists "* Line L, Column C\n  message" entries; keep them on one line.
    std::replace(errors.begin(), errors.end(), '\n', ' ');
    return "is not valid JSON: " + errors;
  }
  if (!root.isObject())
    return "must hold one JSON object { \"dimensions\": ..., \"files\": ... }";

  for (const std::string& key : root.getMemberNames())
    if (std::find_if(std::begin(KnownKeys), std::end(KnownKeys),
          [&](const char* k) { return key == k; }) == std::end(KnownKeys))
      return "has the unknown key '" + key + "'; the known keys are " + knownKeys();
  return std::string();
}

/// The grid: "dimensions", "origin", "spacing".
std::string readGrid(const Json::Value& root, bp::RawVolumeSeries& series)
{
  const auto positiveInt = [](const Json::Value& v) { return v.isInt() && v.asInt() >= 1; };
  const auto number = [](const Json::Value& v) { return v.isNumeric(); };
  if (!root.isMember("dimensions"))
    return "lacks 'dimensions': add \"dimensions\": [nx, ny, nz], the points along x, y and z";
  int dims[3];
  std::string error = readTriple(root["dimensions"], "dimensions", dims, positiveInt);
  if (!error.empty())
    return error + " (points along x, y and z, each at least 1)";
  series.dims = { dims[0], dims[1], dims[2] };

  double triple[3];
  if (root.isMember("origin"))
  {
    error = readTriple(root["origin"], "origin", triple, number);
    if (!error.empty())
      return error;
    series.origin = { triple[0], triple[1], triple[2] };
  }
  if (root.isMember("spacing"))
  {
    error = readTriple(root["spacing"], "spacing", triple, number);
    if (!error.empty())
      return error;
    series.spacing = { triple[0], triple[1], triple[2] };
  }
  return std::string();
}

/// How the values are stored: "scalar_type", "byte_order", "header_bytes".
std::string readEncoding(const Json::Value& root, bp::RawVolumeSeries& series)
{
  if (!root.isMember("scalar_type"))
    return "lacks 'scalar_type': add e.g. \"scalar_type\": \"float32\" (one of " +
      bp::rawScalarTypeNames() + ")";
  const Json::Value& type = root["scalar_type"];
  if (!type.isString() || !bp::parseRawScalarType(type.asString(), series.scalarType))
    return "has the unknown 'scalar_type' " +
      (type.isString() ? "\"" + type.asString() + "\"" : std::string("(not a string)")) +
      "; use one of " + bp::rawScalarTypeNames();

  if (root.isMember("byte_order"))
  {
    const Json::Value& order = root["byte_order"];
    if (!order.isString() || !bp::parseRawByteOrder(order.asString(), series.byteOrder))
      return "has a 'byte_order' that is neither \"little\" nor \"big\"";
  }
  else if (bp::rawScalarTypeSize(series.scalarType) > 1)
    return "lacks 'byte_order': add \"byte_order\": \"little\" (most PCs) or \"big\"";

  if (root.isMember("header_bytes"))
  {
    const Json::Value& header = root["header_bytes"];
    if (!header.isIntegral() || (header.isInt64() && header.asInt64() < 0))
      return "has a 'header_bytes' that is not a non-negative whole number";
    series.headerBytes = header.asUInt64();
  }
  return std::string();
}

/// "files": per time step, one file of interleaved (u, v, w) or three.
std::string readFiles(const Json::Value& root, bp::RawVolumeSeries& series)
{
  if (!root.isMember("files"))
    return "lacks 'files': add one entry per time step, a file name of interleaved (u, v, w) "
           "values or an array of three file names [u, v, w]";
  const Json::Value& files = root["files"];
  if (!files.isArray() || files.empty())
    return "has 'files' that is not a non-empty array (one entry per time step)";
  series.files.clear();
  for (Json::ArrayIndex k = 0; k < files.size(); ++k)
  {
    const Json::Value& entry = files[k];
    std::vector<std::string> names;
    if (entry.isString())
      names.push_back(entry.asString());
    else if (entry.isArray())
      for (Json::ArrayIndex c = 0; c < entry.size(); ++c)
      {
        if (!entry[c].isString())
          return "has 'files'[" + std::to_string(k) + "][" + std::to_string(c) +
            "] that is not a file name";
        names.push_back(entry[c].asString());
      }
    else
      return "has 'files'[" + std::to_string(k) +
        "] that is neither a file name nor an array of three file names";
    series.files.push_back(std::move(names));
  }
  return std::string();
}

/// "times" (default 0, 1, ... per file) and "z_coordinates".
std::string readTimesAndLayers(const Json::Value& root, bp::RawVolumeSeries& series)
{
  if (root.isMember("times"))
  {
    const std::string error = readNumbers(root["times"], "times", series.times);
    if (!error.empty())
      return error;
  }
  else
  {
    series.times.clear();
    for (std::size_t k = 0; k < series.files.size(); ++k)
      series.times.push_back(double(k));
  }

  if (root.isMember("z_coordinates"))
  {
    const std::string error =
      readNumbers(root["z_coordinates"], "z_coordinates", series.zCoordinates);
    if (!error.empty())
      return error;
    // Given but empty is a mistake, not a request for uniform z (leave the key out for that).
    if (series.zCoordinates.empty())
      return "has an empty 'z_coordinates'; give one z per layer, or leave the key out for "
             "uniform spacing";
  }
  return std::string();
}

/// "array_name" and "description".
std::string readNames(const Json::Value& root, bp::RawVolumeSeries& series)
{
  if (root.isMember("array_name"))
  {
    if (!root["array_name"].isString())
      return "has an 'array_name' that is not a string";
    series.arrayName = root["array_name"].asString();
  }
  if (root.isMember("description") && !root["description"].isString())
    return "has a 'description' that is not a string";
  return std::string();
}

/// Fills series from the descriptor's JSON text. Empty on success, otherwise
/// what is wrong and how to fix it. The parts are read in the order the
/// messages assume: the first problem found is the one said.
std::string parseDescriptor(const std::string& text, bp::RawVolumeSeries& series)
{
  Json::Value root;
  std::string error = parseObject(text, root);
  using Part = std::string (*)(const Json::Value&, bp::RawVolumeSeries&);
  const Part parts[] = { readGrid, readEncoding, readFiles, readTimesAndLayers, readNames };
  for (Part part : parts)
  {
    if (!error.empty())
      return error;
    error = part(root, series);
  }
  if (!error.empty())
    return error;
  error = series.validate();
  return error.empty() ? error : "is not usable: " + error;
}
} // namespace

struct vtkRawVectorVolumeSeriesReader::vtkInternals
{
  // What the current reader was made from, to keep its read-ahead when the
  // pipeline asks again for the same descriptor.
  std::string File;
  std::string Text;
  bool Valid = false;
  std::unique_ptr<bp::RawVolumeReadAhead> Reader;
  // Counts of readers replaced since this reader was made.
  vtkIdType StepsReadBefore = 0;
  vtkIdType HitsBefore = 0;

  void Drop()
  {
    if (this->Reader)
    {
      this->StepsReadBefore += vtkIdType(this->Reader->stepsRead());
      this->HitsBefore += vtkIdType(this->Reader->readAheadHits());
    }
    this->Reader.reset();
    this->File.clear();
    this->Text.clear();
    this->Valid = false;
  }
};

//------------------------------------------------------------------------------
vtkRawVectorVolumeSeriesReader::vtkRawVectorVolumeSeriesReader()
  : Internals(new vtkInternals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkRawVectorVolumeSeriesReader::~vtkRawVectorVolumeSeriesReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
void vtkRawVectorVolumeSeriesReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ReadAhead: " << (this->ReadAhead ? "On" : "Off") << "\n";
  os << indent << "NumberOfTimeSteps: " << this->GetNumberOfTimeSteps() << "\n";
  os << indent << "NumberOfStepsRead: " << this->GetNumberOfStepsRead() << "\n";
  os << indent << "NumberOfReadAheadHits: " << this->GetNumberOfReadAheadHits() << "\n";
}

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::CanReadFile(const char* name)
{
  if (!name || !*name)
    return 0;
  std::ifstream in(name, std::ios::binary);
  if (!in)
    return 0;
  char c = 0;
  int skipped = 0;
  while (in.get(c) && skipped < 4096)
  {
    const unsigned char u = static_cast<unsigned char>(c);
    if (u == 0xEF || u == 0xBB || u == 0xBF || std::isspace(u)) // UTF-8 byte order mark, blanks
    {
      ++skipped;
      continue;
    }
    return c == '{' ? 1 : 0;
  }
  return 0;
}

//------------------------------------------------------------------------------
vtkIdType vtkRawVectorVolumeSeriesReader::GetNumberOfStepsRead() const
{
  const auto& I = *this->Internals;
  return I.StepsReadBefore + (I.Reader ? vtkIdType(I.Reader->stepsRead()) : 0);
}

//------------------------------------------------------------------------------
vtkIdType vtkRawVectorVolumeSeriesReader::GetNumberOfReadAheadHits() const
{
  const auto& I = *this->Internals;
  return I.HitsBefore + (I.Reader ? vtkIdType(I.Reader->readAheadHits()) : 0);
}

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::GetNumberOfTimeSteps() const
{
  const auto& I = *this->Internals;
  return I.Valid && I.Reader ? int(I.Reader->series().numberOfSteps()) : 0;
}

//------------------------------------------------------------------------------
bool vtkRawVectorVolumeSeriesReader::ReadDescriptor()
{
  auto& I = *this->Internals;
  if (!this->FileName || !*this->FileName)
  {
    I.Drop();
    vtkErrorMacro(<< "No FileName: set it to a Raw Vector Volume Series descriptor (.bpvol).");
    return false;
  }
  const std::string file = this->FileName;
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  std::string problem;
  std::string text;
  if (!fs::exists(status))
    problem = "does not exist; check the path";
  else if (!fs::is_regular_file(status))
    problem = "is not a regular file";
  else if (fs::file_size(file, ec) > MaxDescriptorBytes)
    problem = "is too large to be a descriptor (over 16 MiB); open the .bpvol JSON file that "
              "describes the raw files, not a raw file";
  else
  {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream buffer;
    if (!in || !(buffer << in.rdbuf()))
    {
      // An empty file makes operator<< fail too; say so plainly.
      problem = in ? "is empty; it must hold the JSON descriptor"
                   : "cannot be opened for reading; check its permissions";
    }
    text = buffer.str();
  }

  if (problem.empty() && I.Reader && I.Valid && file == I.File && text == I.Text)
  {
    // Same series: keep the reader, but not a step read ahead before this
    // change to the reader (the files may have changed too).
    I.Reader->dropReadAhead();
    return true;
  }

  I.Drop();
  bp::RawVolumeSeries series;
  if (problem.empty())
    problem = parseDescriptor(text, series);
  if (!problem.empty())
  {
    vtkErrorMacro(<< "Raw Vector Volume Series descriptor '" << file << "' " << problem);
    return false;
  }
  series.baseDirectory = fs::path(file).parent_path().string();
  I.Reader = std::make_unique<bp::RawVolumeReadAhead>(std::move(series), this->ReadAhead != 0);
  I.File = file;
  I.Text = std::move(text);
  I.Valid = true;
  return true;
}

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkDataSet");
  return 1;
}

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::RequestDataObject(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const bool valid = this->ReadDescriptor();
  const bool rectilinear = valid && !this->Internals->Reader->series().zCoordinates.empty();
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataObject* output = vtkDataObject::GetData(outInfo);
  const bool fits = rectilinear ? vtkRectilinearGrid::SafeDownCast(output) != nullptr
                                : vtkImageData::SafeDownCast(output) != nullptr;
  if (!fits)
  {
    vtkSmartPointer<vtkDataObject> made;
    if (rectilinear)
      made = vtkSmartPointer<vtkRectilinearGrid>::New();
    else
      made = vtkSmartPointer<vtkImageData>::New();
    outInfo->Set(vtkDataObject::DATA_OBJECT(), made);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
  outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  const auto& I = *this->Internals;
  if (!I.Valid || !I.Reader)
  {
    const int empty[6] = { 0, -1, 0, -1, 0, -1 };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), empty, 6);
    return 1; // the problem was reported when the descriptor was read
  }
  const bp::RawVolumeSeries& s = I.Reader->series();
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), s.times.data(),
    static_cast<int>(s.times.size()));
  const double range[2] = { s.times.front(), s.times.back() };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  const int extent[6] = { 0, s.dims[0] - 1, 0, s.dims[1] - 1, 0, s.dims[2] - 1 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  // Any block of the volume (a parallel run's pieces with their ghost layers).
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);
  if (s.zCoordinates.empty())
  {
    outInfo->Set(vtkDataObject::ORIGIN(), s.origin.data(), 3);
    outInfo->Set(vtkDataObject::SPACING(), s.spacing.data(), 3);
  }

  // Say now, not when the animation gets there, if some steps cannot be read
  // (existence and sizes only: nothing is read here).
  std::size_t broken = 0;
  std::string first;
  for (std::size_t k = 0; k < s.numberOfSteps(); ++k)
  {
    const std::string problem = bp::checkRawVolumeStep(s, k);
    if (!problem.empty() && broken++ == 0)
      first = problem;
  }
  if (broken > 0)
    vtkWarningMacro(<< "'" << I.File << "': " << broken << " of " << s.numberOfSteps()
                    << " time steps cannot be read and will give an empty output; the first: "
                    << first);
  return 1;
}

namespace
{
/// The time step at or before the requested time (the first without one).
int requestedStep(const bp::RawVolumeSeries& s, vtkInformation* outInfo)
{
  if (!outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
    return 0;
  return std::max(
    0, s.stepAtOrBefore(outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP())));
}

/// The block asked for (the whole volume unless a parallel run asks for its
/// piece with ghost layers), within the volume; false when none is left.
bool requestedBlock(const bp::RawVolumeSeries& s, vtkInformation* outInfo, int block[6])
{
  const int whole[6] = { 0, s.dims[0] - 1, 0, s.dims[1] - 1, 0, s.dims[2] - 1 };
  std::copy_n(whole, 6, block);
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT()))
  {
    int asked[6];
    outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), asked);
    for (int a = 0; a < 3; ++a)
    {
      block[2 * a] = std::max(block[2 * a], asked[2 * a]);
      block[2 * a + 1] = std::min(block[2 * a + 1], asked[2 * a + 1]);
    }
  }
  return !(block[0] > block[1] || block[2] > block[3] || block[4] > block[5]);
}

/// The output's geometry for `block`: an image, or a rectilinear grid along
/// the z coordinates. False for any other output type.
bool shapeOutput(vtkDataSet* output, const bp::RawVolumeSeries& s, int block[6])
{
  if (vtkImageData* image = vtkImageData::SafeDownCast(output))
  {
    image->SetExtent(block);
    image->SetOrigin(s.origin.data());
    image->SetSpacing(s.spacing.data());
    return true;
  }
  vtkRectilinearGrid* grid = vtkRectilinearGrid::SafeDownCast(output);
  if (!grid)
    return false;
  grid->SetExtent(block);
  vtkSmartPointer<vtkDoubleArray> axes[3];
  for (int a = 0; a < 3; ++a)
  {
    axes[a] = vtkSmartPointer<vtkDoubleArray>::New();
    axes[a]->SetNumberOfTuples(block[2 * a + 1] - block[2 * a] + 1);
    for (int i = block[2 * a]; i <= block[2 * a + 1]; ++i)
      axes[a]->SetValue(
        i - block[2 * a], a == 2 ? s.zCoordinates[std::size_t(i)] : s.origin[a] + i * s.spacing[a]);
  }
  grid->SetXCoordinates(axes[0]);
  grid->SetYCoordinates(axes[1]);
  grid->SetZCoordinates(axes[2]);
  return true;
}

/// The block's rows of the volume's `values` (x fastest, as the file and VTK
/// store them), as the output's vectors.
vtkSmartPointer<vtkFloatArray> blockVectors(
  const bp::RawVolumeSeries& s, const std::vector<float>& values, const int block[6])
{
  const vtkIdType nx = block[1] - block[0] + 1, ny = block[3] - block[2] + 1,
                  nz = block[5] - block[4] + 1;
  vtkNew<vtkFloatArray> vectors;
  vectors->SetName(s.arrayName.c_str());
  vectors->SetNumberOfComponents(3);
  vectors->SetNumberOfTuples(nx * ny * nz);
  float* out = vectors->GetPointer(0);
  for (vtkIdType k = 0; k < nz; ++k)
    for (vtkIdType j = 0; j < ny; ++j)
    {
      const std::size_t row =
        (std::size_t(block[4] + k) * std::size_t(s.dims[1]) + std::size_t(block[2] + j)) *
          std::size_t(s.dims[0]) +
        std::size_t(block[0]);
      out = std::copy_n(values.begin() + std::ptrdiff_t(3 * row), 3 * nx, out);
    }
  return vectors.GetPointer();
}
} // namespace

//------------------------------------------------------------------------------
int vtkRawVectorVolumeSeriesReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkDataSet* output = vtkDataSet::GetData(outInfo);
  if (!output)
  {
    vtkErrorMacro(<< "No output data object.");
    return 0;
  }
  output->Initialize();
  auto& I = *this->Internals;
  if (!I.Valid || !I.Reader)
    return 1; // empty output; the problem was reported when the descriptor was read

  const bp::RawVolumeSeries& s = I.Reader->series();
  const int step = requestedStep(s, outInfo);
  output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), s.times[std::size_t(step)]);
  int block[6];
  if (!requestedBlock(s, outInfo, block))
    return 1; // none of the volume: an empty output

  I.Reader->setReadAhead(this->ReadAhead != 0);
  std::vector<float> values;
  const std::string error = I.Reader->read(std::size_t(step), values);
  if (!error.empty())
  {
    vtkErrorMacro(<< "Raw Vector Volume Series '" << I.File << "': cannot read time step " << step
                  << " (time " << s.times[std::size_t(step)] << "): " << error);
    return 1;
  }
  if (!shapeOutput(output, s, block))
  {
    vtkErrorMacro(<< "Unexpected output type " << output->GetClassName() << ".");
    return 0;
  }
  output->GetPointData()->SetVectors(blockVectors(s, values, block));
  return 1;
}

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkRawVectorVolumeSeriesReader
 * @brief Reads a time series of raw binary vector volumes described by a JSON
 * descriptor (".bpvol", "Raw Vector Volume Series").
 *
 * The descriptor (FileName) gives the grid (dimensions, origin, spacing), the
 * scalar type and byte order of the values, optional header bytes to skip, the
 * time values, and per time step either one file of interleaved (u, v, w)
 * triplets or three files, one per component (docs/user-guide.md, "Raw
 * Vector Volume Series reader"). The output is a vtkImageData, or a vtkRectilinearGrid when the
 * descriptor lists z_coordinates (non-uniform layers), with one 3-component
 * float point array (array_name, default "velocity") set as the active vectors.
 *
 * Only the time step asked for (UPDATE_TIME_STEP, snapped to the step at or
 * before it; the first step when none is asked for) is read. With ReadAhead on
 * the next step is then read on a background thread, so playing forward is
 * served from memory; at most one step is held ahead.
 *
 * Every problem (unreadable or malformed descriptor, missing keys, bad type
 * names, missing, truncated or mis-sized data files) is reported with
 * vtkErrorMacro naming the file and what to fix, and gives an empty output.
 */
#ifndef vtkRawVectorVolumeSeriesReader_h
#define vtkRawVectorVolumeSeriesReader_h

#include "BoundParticlesIOModule.h" // for export macro
#include "vtkDataObjectAlgorithm.h"

#include <memory> // for std::unique_ptr

class BOUNDPARTICLESIO_EXPORT vtkRawVectorVolumeSeriesReader : public vtkDataObjectAlgorithm
{
public:
  static vtkRawVectorVolumeSeriesReader* New();
  vtkTypeMacro(vtkRawVectorVolumeSeriesReader, vtkDataObjectAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The JSON descriptor of the series.
  vtkSetFilePathMacro(FileName);
  vtkGetFilePathMacro(FileName);
  ///@}

  ///@{
  /// Read the next time step on a background thread after each step. Default on.
  vtkSetMacro(ReadAhead, vtkTypeBool);
  vtkGetMacro(ReadAhead, vtkTypeBool);
  vtkBooleanMacro(ReadAhead, vtkTypeBool);
  ///@}

  /// 1 when the file can be opened and looks like a JSON object (its first
  /// non-blank character is '{'). Errors in it are reported when it is read.
  virtual int CanReadFile(VTK_FILEPATH const char* name);

  /// Time steps read from disk since this reader was made, read-ahead included
  /// (a read-ahead counts when it starts). For tests.
  vtkIdType GetNumberOfStepsRead() const;

  /// Requests served from the read-ahead since this reader was made.
  vtkIdType GetNumberOfReadAheadHits() const;

  /// Time steps of the last descriptor read successfully (0 when none).
  int GetNumberOfTimeSteps() const;

protected:
  vtkRawVectorVolumeSeriesReader();
  ~vtkRawVectorVolumeSeriesReader() override;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestDataObject(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  vtkTypeBool ReadAhead = 1;

private:
  vtkRawVectorVolumeSeriesReader(const vtkRawVectorVolumeSeriesReader&) = delete;
  void operator=(const vtkRawVectorVolumeSeriesReader&) = delete;

  /// Reads and checks the descriptor; reports and returns false on a problem.
  bool ReadDescriptor();

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif

// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAnalyticFlowSource.h"

#include "AnalyticFlows.h"
#include "Memory.h"

#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <array>
#include <cstdint>
#include <sstream>

vtkStandardNewMacro(vtkAnalyticFlowSource);

vtkAnalyticFlowSource::vtkAnalyticFlowSource()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

std::string vtkAnalyticFlowSource::CheckSettings() const
{
  std::ostringstream err;
  for (int a = 0; a < 3; ++a)
  {
    if (this->Resolution[a] < 1 || this->Resolution[a] > 4096)
    {
      err << "Resolution along "
          << "XYZ"[a] << " is " << this->Resolution[a] << "; it must lie in [1, 4096].";
      return err.str();
    }
    if (!(this->Bounds[2 * a + 1] > this->Bounds[2 * a]) && this->Resolution[a] > 1)
    {
      err << "Bounds along "
          << "XYZ"[a] << " must have max > min.";
      return err.str();
    }
  }
  if (this->Resolution[0] * std::int64_t(this->Resolution[1]) * this->Resolution[2] < 2)
  {
    return "Resolution must give at least two points.";
  }
  if (bp::analyticFlowIsUnsteady(this->Flow) && this->NumberOfTimeSteps < 2)
  {
    return "NumberOfTimeSteps must be at least 2 for an unsteady flow.";
  }
  return std::string();
}

int vtkAnalyticFlowSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  const std::string error = this->CheckSettings();
  if (!error.empty())
  {
    vtkErrorMacro(<< error);
    return 0;
  }
  int extent[6];
  double origin[3], spacing[3];
  for (int a = 0; a < 3; ++a)
  {
    extent[2 * a] = 0;
    extent[2 * a + 1] = this->Resolution[a] - 1;
    origin[a] = this->Bounds[2 * a];
    spacing[a] = this->Resolution[a] > 1
      ? (this->Bounds[2 * a + 1] - this->Bounds[2 * a]) / (this->Resolution[a] - 1)
      : 1.0;
  }
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 3);
  outInfo->Set(CAN_PRODUCE_SUB_EXTENT(), 1);

  const auto steps = bp::analyticFlowTimeSteps(this->Flow, this->NumberOfTimeSteps);
  if (steps.empty())
  {
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_STEPS());
    outInfo->Remove(vtkStreamingDemandDrivenPipeline::TIME_RANGE());
  }
  else
  {
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_STEPS(), steps.data(), int(steps.size()));
    const double range[2] = { steps.front(), steps.back() };
    outInfo->Set(vtkStreamingDemandDrivenPipeline::TIME_RANGE(), range, 2);
  }
  return 1;
}

int vtkAnalyticFlowSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkImageData* output = vtkImageData::GetData(outInfo);
  const auto flow = this->Flow;

  double time = 0.0;
  if (bp::analyticFlowIsUnsteady(flow) &&
    outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP()))
  {
    time = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_TIME_STEP());
  }

  int extent[6];
  outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_EXTENT(), extent);
  double origin[3], spacing[3];
  outInfo->Get(vtkDataObject::ORIGIN(), origin);
  outInfo->Get(vtkDataObject::SPACING(), spacing);

  // The piece asked for, as a grid of its own laid over the whole box.
  bp::GridGeometry piece;
  for (int a = 0; a < 3; ++a)
  {
    piece.dims[a] = extent[2 * a + 1] - extent[2 * a] + 1;
    piece.origin[a] = origin[a] + extent[2 * a] * spacing[a];
    piece.spacing[a] = spacing[a];
  }
  const std::array<double, 6> box = { this->Bounds[0], this->Bounds[1], this->Bounds[2],
    this->Bounds[3], this->Bounds[4], this->Bounds[5] };
  // The volume and the copy a tracer takes of it: refused before allocating,
  // since a failed allocation inside VTK aborts.
  const std::string memoryError = bp::checkAllocatable(2.0 * 12.0 * double(piece.pointCount()),
    "An Analytic Flow of " + std::to_string(piece.dims[0]) + " x " + std::to_string(piece.dims[1]) +
      " x " + std::to_string(piece.dims[2]) + " points");
  if (!memoryError.empty())
  {
    vtkErrorMacro(<< memoryError << "; lower its Resolution.");
    return 1;
  }
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  velocity->SetNumberOfTuples(vtkIdType(piece.pointCount()));
  float* out = velocity->GetPointer(0);
  std::size_t n = 0;
  for (int k = 0; k < piece.dims[2]; ++k)
    for (int j = 0; j < piece.dims[1]; ++j)
      for (int i = 0; i < piece.dims[0]; ++i, ++n)
      {
        const double p[3] = { piece.origin[0] + i * spacing[0], piece.origin[1] + j * spacing[1],
          piece.origin[2] + k * spacing[2] };
        double v[3];
        bp::analyticVelocity(flow, p, time, box, v);
        out[3 * n] = float(v[0]);
        out[3 * n + 1] = float(v[1]);
        out[3 * n + 2] = float(v[2]);
      }

  output->SetExtent(extent);
  output->SetOrigin(origin);
  output->SetSpacing(spacing);
  output->GetPointData()->SetVectors(velocity);
  if (bp::analyticFlowIsUnsteady(flow))
  {
    output->GetInformation()->Set(vtkDataObject::DATA_TIME_STEP(), time);
  }
  return 1;
}

void vtkAnalyticFlowSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Flow: " << this->GetFlowAsString() << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " " << this->Resolution[1] << " "
     << this->Resolution[2] << "\n";
  os << indent << "NumberOfTimeSteps: " << this->NumberOfTimeSteps << "\n";
}

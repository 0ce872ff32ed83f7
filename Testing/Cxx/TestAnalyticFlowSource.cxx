// SPDX-License-Identifier: BSD-3-Clause
#include "vtkAnalyticFlowSource.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <gtest/gtest.h>

TEST(AnalyticFlowSource, MakesTheGridAndVectors)
{
  vtkNew<vtkAnalyticFlowSource> source;
  source->SetFlow(bp::AnalyticFlow::SolidBodyRotation);
  source->SetResolution(9, 5, 3);
  source->SetBounds(-2, 2, -1, 1, 0, 1);
  source->Update();
  vtkImageData* image = source->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 9);
  EXPECT_EQ(dims[1], 5);
  EXPECT_EQ(dims[2], 3);
  double b[6];
  image->GetBounds(b);
  EXPECT_DOUBLE_EQ(b[0], -2.0);
  EXPECT_DOUBLE_EQ(b[1], 2.0);
  vtkDataArray* v = image->GetPointData()->GetVectors();
  ASSERT_NE(v, nullptr);
  EXPECT_STREQ(v->GetName(), "velocity");
  EXPECT_EQ(v->GetNumberOfComponents(), 3);
  // v = (-y, x, 0) at the point (2, 1, 0).
  const vtkIdType id = image->ComputePointId(std::array<int, 3>{ 8, 4, 0 }.data());
  EXPECT_NEAR(v->GetComponent(id, 0), -1.0, 1e-6);
  EXPECT_NEAR(v->GetComponent(id, 1), 2.0, 1e-6);
}

TEST(AnalyticFlowSource, DoubleGyreHasTimeSteps)
{
  vtkNew<vtkAnalyticFlowSource> source;
  source->SetFlow(bp::AnalyticFlow::DoubleGyre);
  source->SetResolution(16, 8, 1);
  source->SetBounds(0, 2, 0, 1, 0, 0);
  source->SetNumberOfTimeSteps(5);
  source->UpdateInformation();
  vtkInformation* info = source->GetOutputInformation(0);
  ASSERT_TRUE(info->Has(vtkStreamingDemandDrivenPipeline::TIME_STEPS()));
  EXPECT_EQ(info->Length(vtkStreamingDemandDrivenPipeline::TIME_STEPS()), 5);
  source->UpdateTimeStep(1.0);
  const double a = source->GetOutput()->GetPointData()->GetVectors()->GetComponent(20, 0);
  source->UpdateTimeStep(2.0);
  const double b = source->GetOutput()->GetPointData()->GetVectors()->GetComponent(20, 0);
  EXPECT_NE(a, b);
}

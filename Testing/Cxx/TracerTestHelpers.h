// SPDX-License-Identifier: BSD-3-Clause
// What the tracer's C++ tests share: an error log, small inputs, a tracer on
// a source, and the check that an input is rejected with a message.
#ifndef BoundParticles_TracerTestHelpers_h
#define BoundParticles_TracerTestHelpers_h

#include "vtkAnalyticFlowSource.h"
#include "vtkBoundParticleTracer.h"
#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkTrivialProducer.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace
{
/// Collects the filter's error messages instead of printing them.
struct ErrorLog
{
  std::vector<std::string> messages;
  vtkNew<vtkCallbackCommand> callback;
  /// Collects the errors (or, with vtkCommand::WarningEvent, the warnings) said.
  explicit ErrorLog(vtkObject* watched, unsigned long event = vtkCommand::ErrorEvent)
  {
    this->callback->SetClientData(this);
    this->callback->SetCallback([](vtkObject*, unsigned long, void* self, void* text)
      { static_cast<ErrorLog*>(self)->messages.emplace_back(static_cast<const char*>(text)); });
    watched->AddObserver(event, this->callback);
  }
  bool mentions(const std::string& part) const
  {
    for (const auto& m : this->messages)
      if (m.find(part) != std::string::npos)
        return true;
    return false;
  }
};

std::vector<float> pointsOf(vtkPolyData* pd)
{
  vtkFloatArray* a = vtkFloatArray::SafeDownCast(pd->GetPoints()->GetData());
  return std::vector<float>(a->GetPointer(0), a->GetPointer(0) + 3 * pd->GetNumberOfPoints());
}

vtkSmartPointer<vtkAnalyticFlowSource> flow(bp::AnalyticFlow which, int resolution = 24)
{
  auto source = vtkSmartPointer<vtkAnalyticFlowSource>::New();
  source->SetFlow(which);
  source->SetResolution(resolution, resolution, resolution);
  return source;
}

vtkSmartPointer<vtkBoundParticleTracer> tracerOn(vtkAlgorithm* source, int elements = 200)
{
  auto tracer = vtkSmartPointer<vtkBoundParticleTracer>::New();
  tracer->SetInputConnection(source->GetOutputPort());
  tracer->SetNumberOfElements(elements);
  tracer->SetSeed(11);
  return tracer;
}

vtkPolyData* at(vtkBoundParticleTracer* tracer, double t)
{
  tracer->UpdateTimeStep(t);
  return tracer->GetOutput();
}

vtkSmartPointer<vtkImageData> image(int nx, int ny, int nz)
{
  auto img = vtkSmartPointer<vtkImageData>::New();
  img->SetDimensions(nx, ny, nz);
  img->SetSpacing(0.1, 0.1, 0.1);
  return img;
}

vtkSmartPointer<vtkFloatArray> array(const char* name, int components, vtkIdType tuples, float v)
{
  auto a = vtkSmartPointer<vtkFloatArray>::New();
  a->SetName(name);
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(tuples);
  a->Fill(v);
  return a;
}

/// Runs the tracer on `input` and expects an error naming `expected` and an empty output.
void expectRejected(vtkDataObject* input, const std::string& expected,
  void (*configure)(vtkBoundParticleTracer*) = nullptr)
{
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(input);
  auto tracer = tracerOn(producer, 10);
  if (configure)
    configure(tracer);
  ErrorLog log(tracer);
  tracer->UpdateTimeStep(0.5);
  EXPECT_TRUE(log.mentions(expected)) << "expected an error mentioning '" << expected << "', got "
                                      << (log.messages.empty() ? "none" : log.messages[0]);
  EXPECT_EQ(tracer->GetOutput()->GetNumberOfPoints(), 0);
}
} // namespace

#endif

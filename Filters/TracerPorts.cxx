// SPDX-License-Identifier: BSD-3-Clause
// How the tracer's requests reach its ports and inputs (TracerPorts.h).
#include "TracerPorts.h"
#include "TracerState.h"

#include "vtkBoundParticleTracer.h"

#include "vtkDataObject.h"
#include "vtkDemandDrivenPipeline.h"
#include "vtkExecutive.h"
#include "vtkInformation.h"
#include "vtkInformationExecutivePortVectorKey.h"
#include "vtkInformationIntegerKey.h"
#include "vtkInformationIntegerRequestKey.h"
#include "vtkInformationVector.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace bpvtk
{

int askedPort(vtkInformation* request)
{
  const int port = request->Has(vtkExecutive::FROM_OUTPUT_PORT())
    ? request->Get(vtkExecutive::FROM_OUTPUT_PORT())
    : 0;
  return port >= 0 && port < TracerPortCount ? port : ElementsPort;
}

void askAlike(vtkInformation* asked, vtkInformation* other)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (asked->Has(SDDP::UPDATE_TIME_STEP()))
  {
    other->Set(SDDP::UPDATE_TIME_STEP(), asked->Get(SDDP::UPDATE_TIME_STEP()));
  }
  else
  {
    other->Remove(SDDP::UPDATE_TIME_STEP());
  }
  for (vtkInformationIntegerKey* key : { SDDP::UPDATE_PIECE_NUMBER(),
         SDDP::UPDATE_NUMBER_OF_PIECES(), SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS() })
  {
    if (asked->Has(key))
    {
      other->Set(key, asked->Get(key));
    }
  }
}

void askOthersAlike(vtkInformationVector* outputs, int port)
{
  vtkInformation* asked = outputs->GetInformationObject(port);
  for (int other = 0; other < outputs->GetNumberOfInformationObjects(); ++other)
  {
    if (other != port)
    {
      askAlike(asked, outputs->GetInformationObject(other));
    }
  }
}

bool fillsInteractions(vtkInformation* request, vtkInformationVector* outputs)
{
  vtkInformation* info = outputs->GetInformationObject(InteractionsPort);
  return askedPort(request) == InteractionsPort ||
    (info && vtkExecutive::CONSUMERS()->Length(info) > 0);
}

void markNotGenerated(vtkInformation* request, vtkInformationVector* outputs, bool interactionsOnly)
{
  const bool state = askedPort(request) == StatePort;
  const bool interactions = fillsInteractions(request, outputs);
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    if ((port == StatePort) != state || (port == InteractionsPort && !interactions) ||
      (interactionsOnly && port != InteractionsPort))
    {
      outputs->GetInformationObject(port)->Set(vtkDemandDrivenPipeline::DATA_NOT_GENERATED(), 1);
    }
  }
}

void markFailedUpdate(
  vtkInformation* request, vtkInformationVector* outputs, const std::string& why)
{
  const bool state = askedPort(request) == StatePort;
  for (int port = 0; port < outputs->GetNumberOfInformationObjects(); ++port)
  {
    vtkInformation* info = outputs->GetInformationObject(port);
    if (state && port != StatePort)
    {
      continue; // a state pass leaves the others as they are
    }
    info->Remove(vtkDemandDrivenPipeline::DATA_NOT_GENERATED());
    if (vtkDataObject* data = vtkDataObject::GetData(info))
    {
      data->Initialize();
    }
    if (port == StatePort && vtkPolyData::GetData(info))
    {
      writeStateNote("the trace failed: " + why, vtkPolyData::GetData(info));
    }
  }
}

void requestWholeInputs(vtkInformationVector** inputs, bool hasTimes, double startTime)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  // The template, the seed points and the Surfaces are whole on every
  // process: each process places elements anywhere, and its elements may
  // pass any surface; a piece of them would differ.
  for (int port = 1; port < 4; ++port)
  {
    vtkInformation* whole = inputs[port]->GetInformationObject(0);
    if (!whole)
    {
      continue;
    }
    whole->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
    whole->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
    whole->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
    // An image's own whole extent (the field's would crop it).
    if (whole->Has(SDDP::WHOLE_EXTENT()))
    {
      whole->Set(SDDP::UPDATE_EXTENT(), whole->Get(SDDP::WHOLE_EXTENT()), 6);
    }
    whole->Remove(vtkBoundParticleTracer::GPU_WORK_QUEUE());
    if (!whole->Has(SDDP::TIME_STEPS()))
    {
      // The time copied from downstream means nothing to a source without
      // time steps, but a new one would run it again on every update.
      whole->Remove(SDDP::UPDATE_TIME_STEP());
    }
    else if (hasTimes)
    {
      // A time-varying template or seed source gives what it holds at the
      // trace's start: the same trace whatever time was shown before
      // (the time copied from downstream made a replay depend on it).
      whole->Set(SDDP::UPDATE_TIME_STEP(), startTime);
    }
  }
}

} // namespace bpvtk

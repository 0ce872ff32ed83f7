// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkAnalyticFlowSource
 * @brief Vector fields with known structure on a uniform grid ("Analytic Flow").
 *
 * Produces a vtkImageData with the 3-component point array "velocity" (the
 * active vectors) for one of the flows of Core/Field/AnalyticFlows.h, laid over
 * Bounds with Resolution points per axis: solid-body rotation, the shear layer
 * of thesis Fig. 4.2, the vertical shear of Fig. 4.4, ABC flow, a
 * hurricane-like vortex, and the unsteady double gyre, which reports
 * NumberOfTimeSteps time steps 0.5 apart.
 */
#ifndef vtkAnalyticFlowSource_h
#define vtkAnalyticFlowSource_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkBoundParticleSetGet.h"      // for vtkBPEnumMacro
#include "vtkImageAlgorithm.h"

#include <string> // for std::string

class BOUNDPARTICLESFILTERS_EXPORT vtkAnalyticFlowSource : public vtkImageAlgorithm
{
public:
  static vtkAnalyticFlowSource* New();
  vtkTypeMacro(vtkAnalyticFlowSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// Which flow (bp::AnalyticFlow): Solid Body Rotation, Shear Layer
  /// (default), Vertical Shear, ABC, Hurricane or Double Gyre. A number that
  /// names none is clamped with a warning.
  // Declares SetFlow, GetFlow and GetFlowAsString.
  vtkBPEnumMacro(Flow, bp::AnalyticFlow);
  ///@}

  ///@{
  /// Grid points along X, Y and Z (a 1 makes that axis a plane). Default 32^3.
  vtkSetVector3Macro(Resolution, int);
  vtkGetVector3Macro(Resolution, int);
  ///@}

  ///@{
  /// The box the flow is laid over: xmin, xmax, ymin, ymax, zmin, zmax.
  vtkSetVector6Macro(Bounds, double);
  vtkGetVector6Macro(Bounds, double);
  ///@}

  ///@{
  /// Time steps of an unsteady flow (0, 0.5, 1, ...). Default 21: one period.
  vtkSetMacro(NumberOfTimeSteps, int);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

protected:
  vtkAnalyticFlowSource();
  ~vtkAnalyticFlowSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  bp::AnalyticFlow Flow = bp::AnalyticFlow::ShearLayer;
  int Resolution[3] = { 32, 32, 32 };
  double Bounds[6] = { -1.0, 1.0, -1.0, 1.0, -1.0, 1.0 };
  int NumberOfTimeSteps = 21;

private:
  vtkAnalyticFlowSource(const vtkAnalyticFlowSource&) = delete;
  void operator=(const vtkAnalyticFlowSource&) = delete;

  /// Empty when Resolution and Bounds make a grid, otherwise why not.
  std::string CheckSettings() const;
};

#endif

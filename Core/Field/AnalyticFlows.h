// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file AnalyticFlows.h
 * @brief Vector fields with known structure, for the demo, the tests and the
 * benchmarks. Each flow is laid over a box (`bounds`) so its pattern is the
 * same for any box; the formulas are in docs/user-guide.md ("Analytic Flow").
 */
#ifndef BoundParticles_AnalyticFlows_h
#define BoundParticles_AnalyticFlows_h

#include "VectorField.h"

#include <array>
#include <vector>

namespace bp
{

enum class AnalyticFlow
{
  SolidBodyRotation = 0, ///< unit angular velocity about the box's vertical axis
  ShearLayer,            ///< thesis Fig. 4.2: flow along x whose speed peaks mid-depth in z
  VerticalShear,         ///< thesis Fig. 4.4: horizontal wind veering 90 degrees with height
  ABC,                   ///< Arnold-Beltrami-Childress flow, one period over the box
  Hurricane,             ///< tangential winds, inflow, eyewall updraft, decaying with height
  DoubleGyre,            ///< unsteady double gyre (Shadden et al. 2005), period 10
};
constexpr int AnalyticFlowCount = 6;

const char* analyticFlowName(AnalyticFlow flow);

/// Whether the flow changes with time (and so has time steps).
bool analyticFlowIsUnsteady(AnalyticFlow flow);

/// The flow's time step values: `count` steps of 0.5 for unsteady flows, none otherwise.
std::vector<double> analyticFlowTimeSteps(AnalyticFlow flow, int count);

/// Velocity at p and time t of the flow laid over `bounds` (xmin, xmax, ...).
void analyticVelocity(
  AnalyticFlow flow, const double p[3], double t, const std::array<double, 6>& bounds, double v[3]);

/// The flow sampled at every point of the grid, 3 floats per point.
std::vector<float> sampleAnalyticFlow(AnalyticFlow flow, const GridGeometry& grid, double t);

} // namespace bp

#endif

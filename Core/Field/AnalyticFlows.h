// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file AnalyticFlows.h
 * @brief Vector fields with known structure, for the demo, the tests and the
 * benchmarks. Each flow is laid over a box (`bounds`) so its pattern is the
 * same for any box; the formulas are in docs/user-guide.md ("Analytic Flow").
 */
#ifndef BoundParticles_AnalyticFlows_h
#define BoundParticles_AnalyticFlows_h

#include "BoundParticlesChoices.h"
#include "VectorField.h"

#include <array>
#include <vector>

namespace bp
{

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

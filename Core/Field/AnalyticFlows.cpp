// SPDX-License-Identifier: BSD-3-Clause
#include "AnalyticFlows.h"

#include <algorithm>
#include <cmath>

namespace bp
{
namespace
{
constexpr double Pi = 3.14159265358979323846;

/// Position as a fraction of the box along each axis (0 on a flat axis).
void normalizedPosition(const double p[3], const std::array<double, 6>& b, double xi[3])
{
  for (int a = 0; a < 3; ++a)
  {
    const double length = b[2 * a + 1] - b[2 * a];
    xi[a] = length > 0.0 ? (p[a] - b[2 * a]) / length : 0.0;
  }
}
} // namespace

bool analyticFlowIsUnsteady(AnalyticFlow flow)
{
  return flow == AnalyticFlow::DoubleGyre;
}

std::vector<double> analyticFlowTimeSteps(AnalyticFlow flow, int count)
{
  std::vector<double> steps;
  if (analyticFlowIsUnsteady(flow))
  {
    for (int k = 0; k < count; ++k)
    {
      steps.push_back(0.5 * k);
    }
  }
  return steps;
}

void analyticVelocity(
  AnalyticFlow flow, const double p[3], double t, const std::array<double, 6>& b, double v[3])
{
  double xi[3];
  normalizedPosition(p, b, xi);
  const double L[3] = { b[1] - b[0], b[3] - b[2], b[5] - b[4] };
  const double c[3] = { 0.5 * (b[0] + b[1]), 0.5 * (b[2] + b[3]), 0.5 * (b[4] + b[5]) };
  switch (flow)
  {
    case AnalyticFlow::SolidBodyRotation:
    {
      v[0] = -(p[1] - c[1]);
      v[1] = p[0] - c[0];
      v[2] = 0.0;
      return;
    }
    case AnalyticFlow::ShearLayer:
    {
      // u(z) = 0.25 + 1 - zeta^2, zeta in [-1, 1] over the depth: speed grows
      // with height below mid-depth and falls above it, so the vorticity
      // du/dz changes sign there (thesis Fig. 4.2).
      const double zeta = 2.0 * xi[2] - 1.0;
      v[0] = 0.25 + (1.0 - zeta * zeta);
      v[1] = 0.0;
      v[2] = 0.0;
      return;
    }
    case AnalyticFlow::VerticalShear:
    {
      const double angle = 0.5 * Pi * xi[2];
      const double speed = 0.5 + 0.5 * xi[2];
      v[0] = speed * std::cos(angle);
      v[1] = speed * std::sin(angle);
      v[2] = 0.0;
      return;
    }
    case AnalyticFlow::ABC:
    {
      const double A = std::sqrt(3.0), B = std::sqrt(2.0), C = 1.0;
      const double X = 2 * Pi * xi[0], Y = 2 * Pi * xi[1], Z = 2 * Pi * xi[2];
      v[0] = (A * std::sin(Z) + C * std::cos(Y)) * L[0] / (2 * Pi);
      v[1] = (B * std::sin(X) + A * std::cos(Z)) * L[1] / (2 * Pi);
      v[2] = (C * std::sin(Y) + B * std::cos(X)) * L[2] / (2 * Pi);
      return;
    }
    case AnalyticFlow::Hurricane:
    {
      // Modified Rankine vortex with its radius of maximum wind at 0.2 of the
      // box's half width, counter-clockwise seen from above; inflow near the
      // ground and outflow aloft; an updraft ring at the eyewall; all weaker
      // with height.
      const double dx = p[0] - c[0], dy = p[1] - c[1];
      const double r = std::sqrt(dx * dx + dy * dy);
      const double R = 0.5 * std::max(std::min(L[0], L[1]), 1e-300);
      const double rho = r / R, rhoMax = 0.2;
      const double height = xi[2];
      const double decay = std::exp(-1.2 * height);
      const double vt =
        (rho < rhoMax ? rho / rhoMax : std::pow(rhoMax / std::max(rho, 1e-300), 0.6)) * decay;
      const double vr = -0.3 * vt * (1.0 - 2.0 * height);
      const double ring = (rho - rhoMax) / 0.1;
      const double w = 0.3 * std::exp(-ring * ring) * std::sin(Pi * height) * decay;
      const double ex = r > 0.0 ? dx / r : 0.0, ey = r > 0.0 ? dy / r : 0.0;
      v[0] = vr * ex - vt * ey;
      v[1] = vr * ey + vt * ex;
      v[2] = w;
      return;
    }
    case AnalyticFlow::DoubleGyre:
    {
      const double A = 0.1, eps = 0.25, omega = 2 * Pi / 10.0;
      const double x = 2.0 * xi[0], y = xi[1];
      const double a = eps * std::sin(omega * t), bb = 1.0 - 2.0 * a;
      const double f = a * x * x + bb * x, dfdx = 2.0 * a * x + bb;
      v[0] = -Pi * A * std::sin(Pi * f) * std::cos(Pi * y) * L[0] / 2.0;
      v[1] = Pi * A * std::cos(Pi * f) * std::sin(Pi * y) * dfdx * L[1];
      v[2] = 0.0;
      return;
    }
  }
  v[0] = v[1] = v[2] = 0.0;
}

std::vector<float> sampleAnalyticFlow(AnalyticFlow flow, const GridGeometry& grid, double t)
{
  const auto bounds = grid.bounds();
  std::vector<float> out(3 * grid.pointCount());
  std::size_t n = 0;
  for (int k = 0; k < grid.dims[2]; ++k)
  {
    for (int j = 0; j < grid.dims[1]; ++j)
    {
      for (int i = 0; i < grid.dims[0]; ++i, ++n)
      {
        const double p[3] = { grid.coordinate(0, i), grid.coordinate(1, j), grid.coordinate(2, k) };
        double v[3];
        analyticVelocity(flow, p, t, bounds, v);
        out[3 * n] = float(v[0]);
        out[3 * n + 1] = float(v[1]);
        out[3 * n + 2] = float(v[2]);
      }
    }
  }
  return out;
}

} // namespace bp

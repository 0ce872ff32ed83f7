// SPDX-License-Identifier: BSD-3-Clause
#include "TestHelpers.h"

#include <gtest/gtest.h>

TEST(AnalyticFlows, EveryFlowIsFiniteAndNonZero)
{
  const bp::GridGeometry g = bptest::grid(12);
  for (int f = 0; f < bp::enumCount<bp::AnalyticFlow>(); ++f)
  {
    const auto flow = bp::AnalyticFlow(f);
    const std::vector<float> v = bp::sampleAnalyticFlow(flow, g, 1.0);
    double maxSpeed = 0.0;
    for (std::size_t i = 0; i < v.size(); i += 3)
    {
      ASSERT_TRUE(std::isfinite(v[i]) && std::isfinite(v[i + 1]) && std::isfinite(v[i + 2]))
        << bp::enumName(flow);
      maxSpeed = std::max(maxSpeed, double(std::hypot(v[i], v[i + 1], v[i + 2])));
    }
    EXPECT_GT(maxSpeed, 0.1) << bp::enumName(flow);
  }
}

TEST(AnalyticFlows, ShearLayerVorticityChangesSignAtMidDepth)
{
  const std::array<double, 6> b = { 0, 4, 0, 1, -1, 1 };
  double below[3], above[3], mid[3];
  const double pb[3] = { 1, 0.5, -0.5 }, pa[3] = { 1, 0.5, 0.5 }, pm[3] = { 1, 0.5, 0.0 };
  bp::analyticVelocity(bp::AnalyticFlow::ShearLayer, pb, 0, b, below);
  bp::analyticVelocity(bp::AnalyticFlow::ShearLayer, pa, 0, b, above);
  bp::analyticVelocity(bp::AnalyticFlow::ShearLayer, pm, 0, b, mid);
  EXPECT_GT(mid[0], below[0]);
  EXPECT_GT(mid[0], above[0]);
  EXPECT_NEAR(below[0], above[0], 1e-12);
}

TEST(AnalyticFlows, OnlyTheDoubleGyreIsUnsteady)
{
  for (int f = 0; f < bp::enumCount<bp::AnalyticFlow>(); ++f)
  {
    const auto flow = bp::AnalyticFlow(f);
    const auto steps = bp::analyticFlowTimeSteps(flow, 21);
    EXPECT_EQ(bp::analyticFlowIsUnsteady(flow), flow == bp::AnalyticFlow::DoubleGyre);
    EXPECT_EQ(steps.size(), bp::analyticFlowIsUnsteady(flow) ? 21u : 0u);
  }
  const std::array<double, 6> b = { 0, 2, 0, 1, 0, 0 };
  const double p[3] = { 0.7, 0.3, 0 };
  double v0[3], v1[3];
  bp::analyticVelocity(bp::AnalyticFlow::DoubleGyre, p, 0.0, b, v0);
  bp::analyticVelocity(bp::AnalyticFlow::DoubleGyre, p, 2.5, b, v1);
  EXPECT_GT(std::abs(v0[0] - v1[0]) + std::abs(v0[1] - v1[1]), 1e-3);
}

// SPDX-License-Identifier: BSD-3-Clause
// The Seed Types through the C++ API: the points each computes, and the
// tracer releasing from them and replaying when they change.
#include "TracerTestHelpers.h"

#include "SurfaceRelease.h"
#include "vtkBoundParticleLineSeeds.h"
#include "vtkBoundParticlePointCloudSeeds.h"
#include "vtkBoundParticleSurfaceSeeds.h"
#include "vtkImageData.h"
#include "vtkLineSource.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace
{
const bool NotFlat[3] = { false, false, false };

/// Each element's mean position at the tracer's start (time 0).
std::vector<std::array<double, 3>> centresAtStart(vtkBoundParticleTracer* tracer, int elements)
{
  vtkPolyData* out = at(tracer, 0.0);
  std::vector<std::array<double, 3>> sums(std::size_t(elements), { 0.0, 0.0, 0.0 });
  std::vector<int> counts(std::size_t(elements), 0);
  vtkDataArray* ids = out->GetPointData()->GetArray("ElementId");
  for (vtkIdType i = 0; ids && i < out->GetNumberOfPoints(); ++i)
  {
    const auto e = std::size_t(ids->GetTuple1(i));
    double x[3];
    out->GetPoint(i, x);
    for (int a = 0; a < 3; ++a)
    {
      sums[e][std::size_t(a)] += x[a];
    }
    ++counts[e];
  }
  for (std::size_t e = 0; e < sums.size(); ++e)
  {
    for (double& v : sums[e])
    {
      v /= counts[e] > 0 ? counts[e] : 1;
    }
  }
  return sums;
}
} // namespace

TEST(SeedTypes, LinePointsEvenlyFromPoint1ToPoint2)
{
  vtkNew<vtkBoundParticleLineSeeds> line;
  line->SetPoint1(-1.0, 0.0, 2.0);
  line->SetPoint2(1.0, 4.0, 2.0);
  line->SetResolution(4);
  std::vector<double> xyz;
  line->AppendPoints(0, NotFlat, 1000, xyz);
  ASSERT_EQ(xyz.size(), 15u);
  EXPECT_EQ(line->GetNumberOfSeedPoints(), 5);
  for (int i = 0; i < 5; ++i)
  {
    EXPECT_NEAR(xyz[3 * i + 0], -1.0 + 0.5 * i, 1e-12);
    EXPECT_NEAR(xyz[3 * i + 1], 1.0 * i, 1e-12);
    EXPECT_NEAR(xyz[3 * i + 2], 2.0, 1e-12);
  }
}

TEST(SeedTypes, HugeResolutionMakesOnlyWhatIsAskedFor)
{
  vtkNew<vtkBoundParticleLineSeeds> line;
  line->SetResolution(1000000000);
  std::vector<double> xyz;
  line->AppendPoints(0, NotFlat, 10, xyz);
  EXPECT_EQ(xyz.size(), 30u);
  EXPECT_EQ(line->GetNumberOfSeedPoints(), 1000000001);
}

TEST(SeedTypes, PointCloudInsideTheSphereAndTheSameForTheSameSeed)
{
  vtkNew<vtkBoundParticlePointCloudSeeds> cloud;
  cloud->SetCenter(1.0, 2.0, 3.0);
  cloud->SetRadius(0.5);
  cloud->SetNumberOfPoints(500);
  std::vector<double> a, b, c;
  cloud->AppendPoints(7, NotFlat, 100000, a);
  cloud->AppendPoints(7, NotFlat, 100000, b);
  cloud->AppendPoints(8, NotFlat, 100000, c);
  ASSERT_EQ(a.size(), 1500u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  double farthest = 0.0;
  int inner = 0; // within half the radius: 1/8 of a uniform ball
  for (std::size_t i = 0; i < 500; ++i)
  {
    const double r = std::hypot(a[3 * i] - 1.0, a[3 * i + 1] - 2.0, a[3 * i + 2] - 3.0);
    farthest = std::max(farthest, r);
    inner += r < 0.25 ? 1 : 0;
  }
  EXPECT_LE(farthest, 0.5);
  EXPECT_GT(farthest, 0.45);
  EXPECT_GT(inner, 30);
  EXPECT_LT(inner, 95);
}

TEST(SeedTypes, PointCloudOnAFlatAxisFillsTheDisc)
{
  vtkNew<vtkBoundParticlePointCloudSeeds> cloud;
  cloud->SetCenter(0.0, 0.0, 5.0);
  cloud->SetNumberOfPoints(400);
  const bool flatZ[3] = { false, false, true };
  std::vector<double> xyz;
  cloud->AppendPoints(1, flatZ, 100000, xyz);
  int inner = 0; // within R / sqrt(2): half of a uniform disc
  for (std::size_t i = 0; i < 400; ++i)
  {
    EXPECT_EQ(xyz[3 * i + 2], 5.0);
    const double r = std::hypot(xyz[3 * i], xyz[3 * i + 1]);
    EXPECT_LE(r, 1.0);
    inner += r < std::sqrt(0.5) ? 1 : 0;
  }
  EXPECT_GT(inner, 160);
  EXPECT_LT(inner, 240);
}

TEST(SeedTypes, TracerReleasesFromTheLineAndReplaysWhenItChanges)
{
  auto source = flow(bp::AnalyticFlow::ShearLayer);
  auto tracer = tracerOn(source, 11);
  tracer->SetElementShape(bp::BuiltinShape::Square);
  vtkNew<vtkBoundParticleLineSeeds> line;
  line->SetPoint1(-0.5, 0.0, 0.0);
  line->SetPoint2(0.5, 0.0, 0.0);
  line->SetResolution(10);
  tracer->SetSeedType(line);
  auto centres = centresAtStart(tracer, 11);
  for (int i = 0; i < 11; ++i)
  {
    EXPECT_NEAR(centres[std::size_t(i)][0], -0.5 + 0.1 * i, 1e-5);
    EXPECT_NEAR(centres[std::size_t(i)][1], 0.0, 1e-5);
  }
  // Set on the seeds alone: the tracer's MTime follows, and it replays.
  const vtkMTimeType before = tracer->GetMTime();
  line->SetPoint2(0.5, 0.5, 0.0);
  EXPECT_GT(tracer->GetMTime(), before);
  centres = centresAtStart(tracer, 11);
  EXPECT_NEAR(centres[10][1], 0.5, 1e-5);
  // Back to the emitter box.
  tracer->SetSeedType(nullptr);
  centres = centresAtStart(tracer, 11);
  double spread = 0.0;
  for (const auto& c : centres)
  {
    spread = std::max(spread, std::abs(c[2]));
  }
  EXPECT_GT(spread, 0.1);
}

TEST(SeedTypes, SurfaceTrianglesKeepTheSurfacesOrientation)
{
  std::vector<double> t;
  // A Plane: two triangles whose normal is (Point1 - Origin) x (Point2 - Origin).
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, 0, 0);
  plane->SetPoint1(2, 0, 0);
  plane->SetPoint2(0, 0, 1); // (2, 0, 0) x (0, 0, 1) points along -y
  plane->Update();
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(plane->GetOutput(), t);
  ASSERT_EQ(t.size(), 2u * 9u);
  double area = 0.0;
  for (std::size_t i = 0; i < 2; ++i)
  {
    EXPECT_EQ(bp::triangleNormal(t.data() + 9 * i), (std::array<double, 3>{ 0, -1, 0 }));
    area += bp::triangleArea(t.data() + 9 * i);
  }
  EXPECT_DOUBLE_EQ(area, 2.0);
  // A volume: its boundary, normals outward (a unit cube of voxels: 12
  // triangles, area 6, the normals summing to 0 face by face).
  vtkNew<vtkImageData> cube;
  cube->SetDimensions(2, 2, 2);
  t.clear();
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(cube, t);
  ASSERT_EQ(t.size(), 12u * 9u);
  area = 0.0;
  for (std::size_t i = 0; i < 12; ++i)
  {
    const double* tri = t.data() + 9 * i;
    const std::array<double, 3> n = bp::triangleNormal(tri), c = bp::triangleCentroid(tri);
    // Outward: from the cube's centre to the face's centroid.
    EXPECT_GT(n[0] * (c[0] - 0.5) + n[1] * (c[1] - 0.5) + n[2] * (c[2] - 0.5), 0.0) << i;
    area += bp::triangleArea(tri);
  }
  EXPECT_DOUBLE_EQ(area, 6.0);
  // Lines and vertices have no surface; nothing at all, none either.
  vtkNew<vtkLineSource> line;
  line->Update();
  t.clear();
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(line->GetOutput(), t);
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(nullptr, t);
  EXPECT_TRUE(t.empty());
}

TEST(SeedTypes, SurfaceHasNoPointsOfItsOwn)
{
  vtkNew<vtkBoundParticleSurfaceSeeds> surface;
  EXPECT_STREQ(surface->GetSeedTypeName(), "Surface");
  EXPECT_TRUE(surface->UsesSeedSource());
  EXPECT_EQ(surface->GetNumberOfSeedPoints(), 10000);
  std::vector<double> xyz;
  surface->AppendPoints(1u, NotFlat, 100, xyz);
  EXPECT_TRUE(xyz.empty()); // the tracer draws them over the Seed Source
  surface->SetNumberOfPoints(-2);
  EXPECT_EQ(surface->GetNumberOfSeedPoints(), 1);
  EXPECT_NE(surface->DescribeUnusableParameters().find("below 1"), std::string::npos);
  vtkNew<vtkBoundParticleLineSeeds> line;
  EXPECT_FALSE(line->UsesSeedSource());
}

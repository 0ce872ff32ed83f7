// SPDX-License-Identifier: BSD-3-Clause
// The Seed Types through the C++ API: the points each computes, and the
// tracer releasing from them and replaying when they change.
#include "TracerTestHelpers.h"

#include "SurfaceRelease.h"
#include "vtkBoundParticleLineSeeds.h"
#include "vtkBoundParticlePointCloudSeeds.h"
#include "vtkBoundParticleSurfaceSeeds.h"
#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkLineSource.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
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

TEST(SeedTypes, SurfaceReleasesFromItsNumberOfPointsOverTheSeedSource)
{
  // 3 points drawn over a plane across the shear layer's flow (along +x,
  // the plane's normal): 12 elements take them in order, cycling, so 3
  // release centres, 4 elements each, all on the plane.
  auto source = flow(bp::AnalyticFlow::ShearLayer);
  auto tracer = tracerOn(source, 12);
  tracer->SetElementShape(bp::BuiltinShape::Point);
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.0, -0.5, -0.5);
  plane->SetPoint1(0.0, 0.5, -0.5);
  plane->SetPoint2(0.0, -0.5, 0.5);
  plane->SetResolution(4, 4);
  tracer->SetSeedSourceConnection(plane->GetOutputPort());
  vtkNew<vtkBoundParticleSurfaceSeeds> surface;
  surface->SetNumberOfPoints(3);
  tracer->SetSeedType(surface);
  EXPECT_TRUE(surface->UsesSeedSource());
  const auto centres = centresAtStart(tracer, 12);
  std::vector<std::array<double, 3>> distinct;
  for (const auto& c : centres)
  {
    EXPECT_NEAR(c[0], 0.0, 1e-5);
    const bool seen = std::any_of(distinct.begin(), distinct.end(),
      [&c](const std::array<double, 3>& d)
      { return std::abs(d[1] - c[1]) < 1e-6 && std::abs(d[2] - c[2]) < 1e-6; });
    if (!seen)
    {
      distinct.push_back(c);
    }
  }
  EXPECT_EQ(distinct.size(), 3u);
  for (std::size_t e = 3; e < centres.size(); ++e)
  {
    EXPECT_NEAR(centres[e][1], centres[e % 3][1], 1e-6) << e;
  }
  surface->SetNumberOfPoints(-2);
  EXPECT_EQ(surface->GetNumberOfSeedPoints(), 1);
  EXPECT_NE(surface->DescribeUnusableParameters().find("below 1"), std::string::npos);
  vtkNew<vtkBoundParticleLineSeeds> line;
  EXPECT_FALSE(line->UsesSeedSource());
}

namespace
{
/// The triangles' total area, and whether every normal points away from `o`.
std::pair<double, bool> areaAndOutward(const std::vector<double>& t, const double o[3])
{
  double area = 0.0;
  bool outward = true;
  for (std::size_t i = 0; i + 9 <= t.size(); i += 9)
  {
    const std::array<double, 3> n = bp::triangleNormal(t.data() + i),
                                c = bp::triangleCentroid(t.data() + i);
    outward = outward && n[0] * (c[0] - o[0]) + n[1] * (c[1] - o[1]) + n[2] * (c[2] - o[2]) > 0;
    area += bp::triangleArea(t.data() + i);
  }
  return { area, outward };
}
} // namespace

TEST(SeedTypes, SurfaceOfBlocksLeavesOutTheFacesBetweenThem)
{
  // Two unit cubes of voxels side by side along x, as two blocks: their
  // boundary is the 2 x 1 x 1 box's (area 10), not the face they share.
  vtkNew<vtkMultiBlockDataSet> blocks;
  for (int b = 0; b < 2; ++b)
  {
    vtkNew<vtkImageData> cube;
    cube->SetDimensions(2, 2, 2);
    cube->SetOrigin(double(b), 0.0, 0.0);
    blocks->SetBlock(unsigned(b), cube);
  }
  std::vector<double> t;
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(blocks, t);
  EXPECT_EQ(t.size(), 20u * 9u);
  const double o[3] = { 1.0, 0.5, 0.5 };
  const auto [area, outward] = areaAndOutward(t, o);
  EXPECT_DOUBLE_EQ(area, 10.0);
  EXPECT_TRUE(outward);
  for (std::size_t i = 0; i + 9 <= t.size(); i += 9)
  {
    const std::array<double, 3> c = bp::triangleCentroid(t.data() + i);
    EXPECT_FALSE(std::abs(c[0] - 1.0) < 1e-9 && std::abs(bp::triangleNormal(t.data() + i)[0]) > 0.5)
      << "a triangle on the inner face x = 1";
  }
}

TEST(SeedTypes, LeftHandedGridsBoundaryPointsOutward)
{
  // A unit cube as a structured grid mirrored in x (x = −i): left-handed,
  // its cells' faces in VTK's order point inward. Alone and as one block
  // of two (the other right-handed), its boundary points outward.
  vtkNew<vtkStructuredGrid> mirrored;
  mirrored->SetDimensions(2, 2, 2);
  vtkNew<vtkPoints> points;
  for (int k = 0; k < 2; ++k)
  {
    for (int j = 0; j < 2; ++j)
    {
      for (int i = 0; i < 2; ++i)
      {
        points->InsertNextPoint(-double(i), double(j), double(k));
      }
    }
  }
  mirrored->SetPoints(points);
  std::vector<double> t;
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(mirrored, t);
  ASSERT_EQ(t.size(), 12u * 9u);
  const double o[3] = { -0.5, 0.5, 0.5 };
  auto [area, outward] = areaAndOutward(t, o);
  EXPECT_DOUBLE_EQ(area, 6.0);
  EXPECT_TRUE(outward);
  vtkNew<vtkImageData> cube; // x from 1 to 2, apart from the mirrored one
  cube->SetDimensions(2, 2, 2);
  cube->SetOrigin(1.0, 0.0, 0.0);
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, mirrored);
  blocks->SetBlock(1, cube);
  t.clear();
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(blocks, t);
  ASSERT_EQ(t.size(), 24u * 9u);
  std::size_t outwardCount = 0;
  for (std::size_t i = 0; i < 24; ++i)
  {
    const double* tri = t.data() + 9 * i;
    const std::array<double, 3> c = bp::triangleCentroid(tri), n = bp::triangleNormal(tri);
    const double centre[3] = { c[0] < 0.5 ? -0.5 : 1.5, 0.5, 0.5 };
    outwardCount +=
      n[0] * (c[0] - centre[0]) + n[1] * (c[1] - centre[1]) + n[2] * (c[2] - centre[2]) > 0.0;
  }
  EXPECT_EQ(outwardCount, 24u);
}

TEST(SeedTypes, SurfaceCellWithANonFiniteCornerIsLeftOutWhole)
{
  // Two quads: the second with a NaN corner. Its fan's first triangle is
  // finite, but the whole cell is left out and counted once.
  vtkNew<vtkPoints> points;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (const std::array<double, 3>& x : std::vector<std::array<double, 3>>{
         { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 2, 0, 0 }, { 2, 1, nan } })
  {
    points->InsertNextPoint(x.data());
  }
  vtkNew<vtkCellArray> quads;
  const vtkIdType a[4] = { 0, 1, 2, 3 }, b[4] = { 1, 4, 5, 2 };
  quads->InsertNextCell(4, a);
  quads->InsertNextCell(4, b);
  vtkNew<vtkPolyData> surface;
  surface->SetPoints(points);
  surface->SetPolys(quads);
  std::vector<double> t;
  vtkBoundParticleSurfaceSeeds::AppendSurfaceTriangles(surface, t);
  ASSERT_EQ(t.size(), 3u * 9u);
  std::vector<double> weights(3, 1.0);
  const bp::SurfaceSummary s = bp::summarizeSurface(t, weights);
  EXPECT_EQ(s.nonFinite, 1u);
  EXPECT_DOUBLE_EQ(s.area, 1.0);
}

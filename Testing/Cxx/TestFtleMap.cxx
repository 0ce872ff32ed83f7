// SPDX-License-Identifier: BSD-3-Clause
// The tracer's FTLE map (Filters/TracerFtleMap.h) from an engine released on
// a lattice: the image is the lattice (world coordinates), point e holds
// element e's ElementFTLE and ElementStretch as Core/Elements/ElementStretch computes
// them, hidden elements are masked, and any other release gives an empty image.
#include "TracerFtleMap.h"

#include "ElementStretch.h"
#include "Engine.h"
#include "ReleaseLattice.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace
{
/// u = (a x, -a y, 0) about the box's centre (1, 0.5): a linear strain.
bp::VectorField strain(double a)
{
  bp::GridGeometry g;
  g.dims = { 21, 11, 3 };
  g.origin = { 0, 0, -0.1 };
  g.spacing = { 0.1, 0.1, 0.1 };
  auto v = std::make_shared<std::vector<float>>();
  for (int k = 0; k < g.dims[2]; ++k)
    for (int j = 0; j < g.dims[1]; ++j)
      for (int i = 0; i < g.dims[0]; ++i)
        v->insert(v->end(), { float(a * (i * 0.1 - 1.0)), float(-a * (j * 0.1 - 0.5)), 0.0f });
  bp::FieldSlice s;
  s.velocity = v;
  return bp::VectorField(g, s);
}

/// A lattice release of spring-free crosses over [0.5, 1.5] x [0.25, 0.75]
/// at z = 0: the lattice's points as seed points place element e at point e
/// (whether or not the engine places Lattice releases itself).
bp::Parameters latticeRelease(bool hideLater)
{
  bp::Parameters p;
  p.emitterMin = { 0.5f, 0.25f, 0.0f };
  p.emitterMax = { 1.5f, 0.75f, 0.0f };
  p.releasePattern = bp::ReleasePattern::Lattice;
  p.lattice = bp::releaseLattice(p.emitterMin, p.emitterMax, 50, 0.0);
  p.numberOfElements = p.lattice.size();
  for (std::size_t e = 0; e < p.lattice.size(); ++e)
  {
    const std::array<float, 3> x = p.lattice.point(e);
    p.seedPoints.insert(p.seedPoints.end(), x.begin(), x.end());
  }
  p.elementSize = 0.02f;
  p.iterations = 0;
  p.orientation = bp::Orientation::Fixed;
  p.integrator = bp::Integrator::RK4;
  p.lifetimeMin = p.lifetimeMax = 10.0f;
  if (hideLater)
  {
    p.releaseStart = 100.0; // nothing released before: every element hidden
    p.releaseStop = 200.0;
  }
  return p;
}
} // namespace

TEST(FtleMap, IsTheLatticeWithEachElementsFtleAtItsPoint)
{
  const double a = 0.4;
  const bp::VectorField field = strain(a);
  const bp::Parameters p = latticeRelease(false);
  bp::Engine engine;
  ASSERT_EQ(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  engine.initialize(bp::serialRunner());
  for (int s = 0; s < 100; ++s)
    engine.step(field, s * 0.01, 0.01, bp::serialRunner());
  const std::array<double, 3> offset = { 10.0, -20.0, 5.0 };
  vtkNew<vtkImageData> image;
  bpvtk::fillFtleMap(image, engine, offset, nullptr);
  int dims[3];
  image->GetDimensions(dims);
  for (int k = 0; k < 3; ++k)
    EXPECT_EQ(dims[k], p.lattice.counts[std::size_t(k)]);
  EXPECT_EQ(dims[2], 1); // a flat box: a flat lattice
  double origin[3], spacing[3];
  image->GetOrigin(origin);
  image->GetSpacing(spacing);
  for (int k = 0; k < 2; ++k)
  {
    EXPECT_NEAR(origin[k], p.lattice.origin[std::size_t(k)] + offset[std::size_t(k)], 1e-6);
    EXPECT_NEAR(spacing[k], p.lattice.spacing[std::size_t(k)], 1e-7);
  }
  EXPECT_NEAR(origin[2], offset[2], 1e-6);
  vtkDataArray* ftle = image->GetPointData()->GetArray("FTLE");
  vtkDataArray* stretch = image->GetPointData()->GetArray("Stretch");
  vtkDataArray* valid = image->GetPointData()->GetArray("vtkValidPointMask");
  vtkDataArray* age = image->GetPointData()->GetArray("Age");
  ASSERT_TRUE(ftle && stretch && valid && age);
  ASSERT_EQ(ftle->GetNumberOfTuples(), vtkIdType(p.lattice.size()));
  const bp::StretchFit fit(engine.shape().rest, p.elementSize);
  const std::size_t n = engine.particlesPerElement();
  for (std::size_t e = 0; e < engine.elementCount(); ++e)
  {
    const vtkIdType id = vtkIdType(engine.elementIds()[e]);
    const std::array<float, 3> d =
      bp::elementDeformation(fit, engine.positions().data() + 3 * e * n, 1.0, false);
    EXPECT_EQ(valid->GetTuple1(id), 1.0);
    EXPECT_FLOAT_EQ(float(stretch->GetComponent(id, 0)), d[0]);
    EXPECT_FLOAT_EQ(float(stretch->GetComponent(id, 1)), d[1]);
    EXPECT_NEAR(ftle->GetTuple1(id), a, 0.01 * a) << "point " << id;
    EXPECT_NEAR(age->GetTuple1(id), 1.0, 1e-4) << "100 steps of 0.01"; // none released again
    // Element e was released at lattice point e.
    double x[3];
    image->GetPoint(id, x);
    const float* c = engine.initialCenters().data() + 3 * e;
    for (int k = 0; k < 3; ++k)
      EXPECT_NEAR(x[k], c[k] + offset[std::size_t(k)], 1e-5);
  }
}

TEST(FtleMap, HiddenElementsAreMaskedAndOtherReleasesGiveNothing)
{
  const bp::VectorField field = strain(0.4);
  bp::Engine hidden;
  ASSERT_EQ(
    hidden.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), latticeRelease(true)), "");
  hidden.initialize(bp::serialRunner());
  hidden.step(field, 0.0, 0.01, bp::serialRunner());
  vtkNew<vtkImageData> image;
  bpvtk::fillFtleMap(image, hidden, { 0, 0, 0 }, nullptr);
  ASSERT_GT(image->GetNumberOfPoints(), 0);
  vtkDataArray* valid = image->GetPointData()->GetArray("vtkValidPointMask");
  vtkDataArray* ftle = image->GetPointData()->GetArray("FTLE");
  vtkDataArray* stretch = image->GetPointData()->GetArray("Stretch");
  for (vtkIdType k = 0; k < image->GetNumberOfPoints(); ++k)
  {
    EXPECT_EQ(valid->GetTuple1(k), 0.0);
    EXPECT_EQ(ftle->GetTuple1(k), 0.0);
    EXPECT_EQ(stretch->GetComponent(k, 0), 1.0);
    EXPECT_EQ(stretch->GetComponent(k, 1), 1.0);
  }
  // Random releases: no lattice, no map.
  bp::Parameters p = latticeRelease(false);
  p.releasePattern = bp::ReleasePattern::Random;
  bp::Engine random;
  ASSERT_EQ(random.configure(bp::builtinTemplate(bp::BuiltinShape::Cross), p), "");
  random.initialize(bp::serialRunner());
  bpvtk::fillFtleMap(image, random, { 0, 0, 0 }, nullptr);
  EXPECT_EQ(image->GetNumberOfPoints(), 0);
}

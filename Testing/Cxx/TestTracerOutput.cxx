// SPDX-License-Identifier: BSD-3-Clause
// The tracer's output builder (Filters/TracerOutput.h) over frames of Play:
// whatever it keeps from one frame to the next (array memory, the arrays
// shown again as they are), every array of every frame has the bits of one
// built from nothing, while elements are released again and trails come and go.
#include "TracerOutput.h"

#include "AnalyticFlows.h"
#include "Engine.h"

#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstring>
#include <string>

namespace
{
/// Whether two arrays hold the same bits, and their ranges agree.
void expectSameBits(vtkDataArray* kept, vtkDataArray* fresh, const std::string& what)
{
  ASSERT_NE(kept, nullptr) << what;
  ASSERT_NE(fresh, nullptr) << what;
  ASSERT_EQ(kept->GetDataType(), fresh->GetDataType()) << what;
  ASSERT_EQ(kept->GetNumberOfValues(), fresh->GetNumberOfValues()) << what;
  const std::size_t bytes = std::size_t(kept->GetNumberOfValues()) * kept->GetDataTypeSize();
  EXPECT_EQ(std::memcmp(kept->GetVoidPointer(0), fresh->GetVoidPointer(0), bytes), 0) << what;
  for (int c = 0; c < kept->GetNumberOfComponents(); ++c)
  {
    double a[2], b[2];
    kept->GetRange(a, c);
    fresh->GetRange(b, c);
    EXPECT_EQ(a[0], b[0]) << what << " component " << c;
    EXPECT_EQ(a[1], b[1]) << what << " component " << c;
  }
}

/// Frames of Play, with or without trails.
void play(bool trails)
{
  bp::GridGeometry g;
  g.dims = { 24, 20, 12 };
  g.origin = { 0, 0, 0 };
  g.spacing = { 2.0 / 23, 1.0 / 19, 1.0 / 11 };
  bp::FieldSlice slice;
  slice.velocity = std::make_shared<std::vector<float>>(
    bp::sampleAnalyticFlow(bp::AnalyticFlow::ShearLayer, g, 0.0));
  const bp::VectorField field(g, slice);
  bp::Parameters p;
  p.numberOfElements = 300;
  p.elementSize = 0.1f;
  for (int a = 0; a < 3; ++a)
  {
    p.emitterMin[a] = 0.2f;
    p.emitterMax[a] = 0.8f;
  }
  // Short lives: elements are released again in most frames.
  p.lifetimeMin = 0.05f;
  p.lifetimeMax = 0.2f;
  p.trailLength = trails ? 3 : 0;
  p.trailInterval = 0.04;
  bp::Engine engine;
  ASSERT_TRUE(engine.configure(bp::builtinTemplate(bp::BuiltinShape::Strip16), p).empty());
  const bp::RangeRunner run = bp::poolRunner(3);
  engine.initialize(run);
  bpvtk::OutputFrame frame;
  frame.offset = { -1.0, 0.5, 2.0 };
  frame.domain = g.bounds();
  frame.reach = 3.0;
  frame.cellLength = g.cellLength();
  bpvtk::OutputStorage kept;
  vtkSmartPointer<vtkPolyData> held; // a display holding the last frame
  double t = 0.0;
  const double dt = 0.01;
  for (int k = 0; k < 24; ++k)
  {
    engine.step(field, t, dt, run);
    t += dt;
    frame.time = t;
    // Trails from the fifth frame on (a pose recorded before the time
    // shown), the Output Arrays changed in one.
    frame.wanted = bpvtk::OutputFrame::everyArray();
    frame.wanted[std::size_t(bp::OutputArrayId::ElementId)] = k != 9;
    const bp::Engine* shown = &engine;
    auto out = vtkSmartPointer<vtkPolyData>::New();
    bpvtk::fillParticleOutput(out, *shown, field, frame, kept, run);
    vtkNew<vtkPolyData> reference;
    bpvtk::OutputStorage nothing;
    bpvtk::fillParticleOutput(reference, *shown, field, frame, nothing, run);
    const std::string when = "frame " + std::to_string(k);
    expectSameBits(
      out->GetPoints()->GetData(), reference->GetPoints()->GetData(), when + " points");
    ASSERT_EQ(
      out->GetPointData()->GetNumberOfArrays(), reference->GetPointData()->GetNumberOfArrays());
    for (int i = 0; i < reference->GetPointData()->GetNumberOfArrays(); ++i)
    {
      vtkDataArray* fresh = reference->GetPointData()->GetArray(i);
      expectSameBits(
        out->GetPointData()->GetArray(fresh->GetName()), fresh, when + " " + fresh->GetName());
    }
    held = out;
  }
}

TEST(TracerOutput, EveryFrameHasTheBitsOfAnOutputBuiltFromNothing)
{
  play(false);
  play(true);
}
} // namespace

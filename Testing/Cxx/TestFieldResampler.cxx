// SPDX-License-Identifier: BSD-3-Clause
// The mesh resampler (Filters/TracerResample.h) alone: values at the grid
// points, the mask, kept weights, cell vectors, 2D meshes, blocks, refusals.
#include "TracerResample.h"

#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCharArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFloatArray.h"
#include "vtkGenericCell.h"
#include "vtkImageData.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkResampleToImage.h"
#include "vtkSmartPointer.h"
#include "vtkStaticCellLocator.h"
#include "vtkUnstructuredGrid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <functional>
#include <random>
#include <string>

namespace
{
using Vector = std::function<std::array<double, 3>(double x, double y, double z)>;

/// A lattice of n^3 points over [0, 1]^3 (shifted by `offset`) as hexahedra,
/// without the cells whose centre `skip` selects; point vectors "v" from `f`.
vtkSmartPointer<vtkUnstructuredGrid> hexMesh(int n, const Vector& f,
  const std::function<bool(double, double, double)>& skip = nullptr, double offset = 0.0)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  const double h = 1.0 / (n - 1);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const double x = offset + i * h, y = j * h, z = k * h;
        points->InsertNextPoint(x, y, z);
        const auto value = f(x, y, z);
        v->InsertNextTuple(value.data());
      }
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(v);
  auto id = [n](int i, int j, int k) { return vtkIdType(i + n * (j + n * k)); };
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
      {
        if (skip && skip(offset + (i + 0.5) * h, (j + 0.5) * h, (k + 0.5) * h))
          continue;
        const vtkIdType hex[8] = { id(i, j, k), id(i + 1, j, k), id(i + 1, j + 1, k),
          id(i, j + 1, k), id(i, j, k + 1), id(i + 1, j, k + 1), id(i + 1, j + 1, k + 1),
          id(i, j + 1, k + 1) };
        mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
      }
  return mesh;
}

std::array<double, 3> linear(double x, double y, double z)
{
  return { 1.0 + x, 2.0 * y, -z };
}

struct Resampled
{
  vtkNew<vtkImageData> image;
  std::string error, warning;

  vtkFloatArray* vectors()
  {
    return vtkFloatArray::SafeDownCast(image->GetPointData()->GetArray("v"));
  }
  vtkCharArray* mask()
  {
    return vtkCharArray::SafeDownCast(image->GetPointData()->GetArray("vtkValidPointMask"));
  }
};

void resample(bpvtk::FieldResampler& r, vtkDataObject* input, Resampled& out,
  std::array<int, 3> dims = { 0, 0, 0 }, bool cells = false)
{
  bpvtk::VectorsChoice choice;
  choice.name = "v";
  choice.association =
    cells ? vtkDataObject::FIELD_ASSOCIATION_CELLS : vtkDataObject::FIELD_ASSOCIATION_POINTS;
  out.error = r.resample(input, choice, dims, nullptr, bp::serialRunner(), out.image, out.warning);
}

TEST(FieldResampler, ALinearFieldIsExactAtEveryGridPoint)
{
  // Trilinear interpolation reproduces a linear field: at the mesh's own
  // points (the same lattice) and between them (twice as fine).
  auto mesh = hexMesh(9, linear);
  for (int n : { 9, 17 })
  {
    bpvtk::FieldResampler r;
    Resampled out;
    resample(r, mesh, out, { n, n, n });
    ASSERT_TRUE(out.error.empty()) << out.error;
    ASSERT_EQ(out.image->GetNumberOfPoints(), vtkIdType(n) * n * n);
    for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
    {
      double x[3];
      out.image->GetPoint(p, x);
      const auto expected = linear(x[0], x[1], x[2]);
      ASSERT_EQ(out.mask()->GetValue(p), 1) << "point " << p;
      for (int a = 0; a < 3; ++a)
      {
        ASSERT_NEAR(out.vectors()->GetComponent(p, a), expected[a], 2e-6) << "point " << p;
      }
    }
  }
}

TEST(FieldResampler, AStaticMeshKeepsItsWeightsAndNewVectorsGiveNewValues)
{
  auto mesh = hexMesh(6, linear);
  bpvtk::FieldResampler kept;
  Resampled first;
  resample(kept, mesh, first);
  ASSERT_TRUE(first.error.empty()) << first.error;
  EXPECT_FALSE(kept.keptWeights());

  // The next time step: the same points and cells (new objects, as a reader
  // gives), other vectors.
  auto next = hexMesh(6, [](double x, double y, double z) { return linear(2 * z, x, y); });
  Resampled second;
  resample(kept, next, second);
  ASSERT_TRUE(second.error.empty()) << second.error;
  EXPECT_TRUE(kept.keptWeights());
  bpvtk::FieldResampler fresh;
  Resampled reference;
  resample(fresh, next, reference);
  ASSERT_EQ(second.vectors()->GetNumberOfValues(), reference.vectors()->GetNumberOfValues());
  for (vtkIdType i = 0; i < reference.vectors()->GetNumberOfValues(); ++i)
  {
    ASSERT_EQ(second.vectors()->GetValue(i), reference.vectors()->GetValue(i)) << i;
  }

  // A moved point is a new mesh: located again.
  next->GetPoints()->SetPoint(7, 0.21, 0.02, 0.0);
  next->GetPoints()->Modified(); // as VTK asks after SetPoint
  Resampled moved;
  resample(kept, next, moved);
  EXPECT_FALSE(kept.keptWeights());
  // The same arrays again, unmodified (a reader that keeps a static mesh):
  // recognised without hashing them, and still the same mesh.
  resample(kept, next, moved);
  EXPECT_TRUE(kept.keptWeights());
  // Other connectivity with the same points: a new mesh.
  next->GetCells()->GetConnectivityArray()->SetComponent(0, 0, 1.0);
  next->GetCells()->GetConnectivityArray()->Modified();
  resample(kept, next, moved);
  EXPECT_FALSE(kept.keptWeights());
}

TEST(FieldResampler, AnAdaptingMeshKeepsTheGridOfItsFirstStepUntilToldToChooseAgain)
{
  // Issue 46: the automatic grid followed each step's cell count, so the
  // steps of an adapting mesh did not share one grid.
  bpvtk::FieldResampler r;
  Resampled first, finer, wider;
  resample(r, hexMesh(6, linear), first);
  ASSERT_TRUE(first.error.empty()) << first.error;
  const bp::ResampleGrid chosen = r.grid();
  resample(r, hexMesh(11, linear), finer); // 8 times the cells
  ASSERT_TRUE(finer.error.empty()) << finer.error;
  EXPECT_FALSE(r.keptWeights());
  EXPECT_EQ(r.grid().dims, chosen.dims);
  EXPECT_EQ(r.grid().spacing, chosen.spacing);
  EXPECT_TRUE(finer.warning.empty()) << finer.warning;
  // The finer mesh's own values on the kept grid.
  for (vtkIdType p = 0; p < finer.image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    finer.image->GetPoint(p, x);
    ASSERT_NEAR(finer.vectors()->GetComponent(p, 1), 2.0 * x[1], 2e-6) << p;
  }
  // A mesh that moved beyond the kept grid: cut to it, and said.
  resample(r, hexMesh(6, linear, nullptr, 0.5), wider);
  ASSERT_TRUE(wider.error.empty()) << wider.error;
  EXPECT_EQ(r.grid().origin, chosen.origin);
  EXPECT_NE(wider.warning.find("beyond the resampled grid along X"), std::string::npos)
    << wider.warning;
  // Told to choose again (the tracer holds no time step): the finer mesh's own grid.
  r.forgetGrid();
  resample(r, hexMesh(11, linear), finer);
  EXPECT_GT(r.grid().pointCount(), chosen.pointCount());
}

TEST(FieldResampler, CellVectorsGiveTheValueOfTheCellThatHoldsThePoint)
{
  auto mesh = hexMesh(5, linear);
  vtkNew<vtkFloatArray> c;
  c->SetName("v");
  c->SetNumberOfComponents(3);
  for (vtkIdType cell = 0; cell < mesh->GetNumberOfCells(); ++cell)
  {
    c->InsertNextTuple3(double(cell), 0.0, 1.0);
  }
  mesh->GetPointData()->RemoveArray("v");
  mesh->GetCellData()->AddArray(c);
  bpvtk::FieldResampler r;
  Resampled out;
  // 4 grid points along each axis over 4 cells: none on a face between cells.
  resample(r, mesh, out, { 4, 4, 4 }, true);
  ASSERT_TRUE(out.error.empty()) << out.error;
  EXPECT_EQ(out.vectors()->GetComponent(0, 0), 0.0f);
  // Asked as point data, the array is found on the cells.
  Resampled asPoints;
  resample(r, mesh, asPoints, { 4, 4, 4 }, false);
  ASSERT_TRUE(asPoints.error.empty()) << asPoints.error;
  for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out.image->GetPoint(p, x);
    // The hexahedron whose centre is nearest (the grid point is inside it).
    const int i = std::min(3, int(x[0] * 4)), j = std::min(3, int(x[1] * 4)),
              k = std::min(3, int(x[2] * 4));
    EXPECT_EQ(out.vectors()->GetComponent(p, 0), float(i + 4 * (j + 4 * k))) << p;
    EXPECT_EQ(asPoints.vectors()->GetComponent(p, 0), out.vectors()->GetComponent(p, 0));
  }
}

TEST(FieldResampler, PointsInAHoleAreOutsideTheFlow)
{
  const auto hole = [](double x, double y, double) { return std::hypot(x - 0.5, y - 0.5) < 0.25; };
  auto mesh = hexMesh(21, linear, hole);
  bpvtk::FieldResampler r;
  Resampled out;
  resample(r, mesh, out, { 41, 41, 5 });
  ASSERT_TRUE(out.error.empty()) << out.error;
  vtkIdType outside = 0;
  for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out.image->GetPoint(p, x);
    const double r2 = std::hypot(x[0] - 0.5, x[1] - 0.5);
    if (r2 < 0.15)
    {
      EXPECT_EQ(out.mask()->GetValue(p), 0) << "in the hole: " << x[0] << " " << x[1];
    }
    if (r2 > 0.35)
    {
      EXPECT_EQ(out.mask()->GetValue(p), 1) << "in the mesh: " << x[0] << " " << x[1];
    }
    outside += out.mask()->GetValue(p) == 0 ? 1 : 0;
    if (out.mask()->GetValue(p) == 0)
    {
      EXPECT_EQ(out.vectors()->GetComponent(p, 0), 0.0f);
    }
  }
  EXPECT_GT(outside, 0);
}

TEST(FieldResampler, AFlatMeshGivesAFlatGridWithEveryPointInside)
{
  // Triangles in the plane z = 2 (their points carry rounding-free z).
  vtkNew<vtkPolyData> plane;
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  const int n = 11;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
    {
      points->InsertNextPoint(i * 0.3, j * 0.1, 2.0);
      v->InsertNextTuple3(-j * 0.1, i * 0.3, 0.0);
    }
  plane->SetPoints(points);
  plane->GetPointData()->AddArray(v);
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i)
    {
      const vtkIdType a = i + n * j, b = a + 1, c = a + n, d = c + 1;
      const vtkIdType t1[3] = { a, b, d }, t2[3] = { a, d, c };
      triangles->InsertNextCell(3, t1);
      triangles->InsertNextCell(3, t2);
    }
  plane->SetPolys(triangles);
  bpvtk::FieldResampler r;
  Resampled out;
  resample(r, plane, out);
  ASSERT_TRUE(out.error.empty()) << out.error;
  EXPECT_EQ(r.grid().dims[2], 1);
  EXPECT_DOUBLE_EQ(r.grid().origin[2], 2.0);
  for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
  {
    ASSERT_EQ(out.mask()->GetValue(p), 1) << p;
    double x[3];
    out.image->GetPoint(p, x);
    EXPECT_NEAR(out.vectors()->GetComponent(p, 0), -x[1], 1e-5);
    EXPECT_NEAR(out.vectors()->GetComponent(p, 1), x[0], 1e-5);
  }
}

TEST(FieldResampler, BlocksOfTheVolumeAreSampledAndSurfacesAndBlocksWithoutVectorsLeftOut)
{
  // Two zones sharing the face x = 1, a surface patch with other vectors on
  // it, and a zone without the array.
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetBlock(0, hexMesh(5, linear));
  blocks->SetBlock(1, hexMesh(5, linear, nullptr, 1.0));
  vtkNew<vtkPolyData> patch;
  vtkNew<vtkPoints> corners;
  for (double y : { 0.0, 1.0 })
    for (double z : { 0.0, 1.0 })
      corners->InsertNextPoint(0.0, y, z);
  patch->SetPoints(corners);
  vtkNew<vtkCellArray> quad;
  const vtkIdType ids[4] = { 0, 1, 3, 2 };
  quad->InsertNextCell(4, ids);
  patch->SetPolys(quad);
  vtkNew<vtkFloatArray> wrong;
  wrong->SetName("v");
  wrong->SetNumberOfComponents(3);
  for (int i = 0; i < 4; ++i)
    wrong->InsertNextTuple3(99, 99, 99);
  patch->GetPointData()->AddArray(wrong);
  blocks->SetBlock(2, patch);
  auto bare = hexMesh(3, linear, nullptr, 3.0);
  bare->GetPointData()->RemoveArray("v");
  blocks->SetBlock(3, bare);

  bpvtk::FieldResampler r;
  Resampled out;
  resample(r, blocks, out, { 0, 5, 5 });
  ASSERT_TRUE(out.error.empty()) << out.error;
  EXPECT_NE(out.warning.find("1 block"), std::string::npos) << out.warning;
  // The grid spans both zones with the array (not the bare one at x = 3..4).
  EXPECT_NEAR(r.grid().origin[0] + (r.grid().dims[0] - 1) * r.grid().spacing[0], 2.0, 1e-12);
  for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
  {
    double x[3];
    out.image->GetPoint(p, x);
    ASSERT_EQ(out.mask()->GetValue(p), 1) << p;
    EXPECT_NEAR(out.vectors()->GetComponent(p, 0), 1.0 + x[0], 2e-6) << p;
  }
}

TEST(FieldResampler, SamplesAsVTKsResampleToImageDoes)
{
  // A curved field on a mesh with a hole, resampled by both onto the same
  // grid (the mesh's bounds): the same points inside, the same values.
  const auto curved = [](double x, double y, double z) -> std::array<double, 3> {
    return { std::sin(3 * y) + z * z, std::cos(2 * x) * z, x * y };
  };
  const auto hole = [](double x, double y, double) { return std::hypot(x - 0.5, y - 0.5) < 0.2; };
  auto mesh = hexMesh(13, curved, hole);
  // No grid point on a face between cells (spacings 1/29, 1/25, 1/19 against
  // the cells' 1/12), where the two grids' hair of difference would decide.
  const std::array<int, 3> dims = { 30, 26, 20 };
  bpvtk::FieldResampler r;
  Resampled ours;
  resample(r, mesh, ours, dims);
  ASSERT_TRUE(ours.error.empty()) << ours.error;

  vtkNew<vtkResampleToImage> vtk;
  vtk->SetInputDataObject(mesh);
  vtk->SetUseInputBounds(true);
  vtk->SetSamplingDimensions(dims[0], dims[1], dims[2]);
  vtk->Update();
  vtkImageData* theirs = vtk->GetOutput();
  ASSERT_EQ(theirs->GetNumberOfPoints(), ours.image->GetNumberOfPoints());
  vtkDataArray* theirMask = theirs->GetPointData()->GetArray("vtkValidPointMask");
  vtkDataArray* theirValues = theirs->GetPointData()->GetArray("v");
  ASSERT_TRUE(theirMask && theirValues);
  vtkIdType differentMask = 0, inside = 0;
  double largest = 0.0;
  for (vtkIdType p = 0; p < theirs->GetNumberOfPoints(); ++p)
  {
    double a[3], b[3];
    ours.image->GetPoint(p, a);
    theirs->GetPoint(p, b);
    // vtkResampleToImage pulls its grid in from the bounds by a hair (5e-7 here).
    for (int c = 0; c < 3; ++c)
    {
      ASSERT_NEAR(a[c], b[c], 1e-6);
    }
    const bool in = ours.mask()->GetValue(p) != 0;
    differentMask += in != (theirMask->GetComponent(p, 0) != 0) ? 1 : 0;
    if (in && theirMask->GetComponent(p, 0) != 0)
    {
      ++inside;
      for (int c = 0; c < 3; ++c)
      {
        largest = std::max(largest,
          std::abs(double(ours.vectors()->GetComponent(p, c)) - theirValues->GetComponent(p, c)));
      }
    }
  }
  EXPECT_EQ(differentMask, 0);
  EXPECT_GT(inside, theirs->GetNumberOfPoints() / 2);
  EXPECT_LT(largest, 1e-5);
}

/**
 * A lattice of n^3 points over [0, 1]^3, interior points jittered by up to a
 * tenth of a cell, as hexahedra or cut into six tetrahedra each (Kuhn: no
 * face of a hexahedron's cut lines up with the grid), float or double
 * points, point vectors "v" of a curved field (so two cells sharing a face
 * interpolate differently off it).
 */
vtkSmartPointer<vtkUnstructuredGrid> jitteredMesh(int n, bool tetrahedra, bool doubles)
{
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  vtkNew<vtkPoints> points;
  points->SetDataType(doubles ? VTK_DOUBLE : VTK_FLOAT);
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  std::mt19937 random(7);
  std::uniform_real_distribution<double> jitter(-0.1, 0.1);
  const double h = 1.0 / (n - 1);
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i)
      {
        const int index[3] = { i, j, k };
        double x[3];
        for (int a = 0; a < 3; ++a)
          x[a] = (index[a] + (index[a] > 0 && index[a] < n - 1 ? jitter(random) : 0.0)) * h;
        points->InsertNextPoint(x);
        v->InsertNextTuple3(
          std::sin(3 * x[1]) + x[2] * x[2], std::cos(2 * x[0]) * x[2], x[0] * x[1]);
      }
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(v);
  auto id = [n](int i, int j, int k) { return vtkIdType(i + n * (j + n * k)); };
  const int kuhn[6][4] = { { 0, 1, 3, 7 }, { 0, 1, 5, 7 }, { 0, 2, 3, 7 }, { 0, 2, 6, 7 },
    { 0, 4, 5, 7 }, { 0, 4, 6, 7 } };
  for (int k = 0; k + 1 < n; ++k)
    for (int j = 0; j + 1 < n; ++j)
      for (int i = 0; i + 1 < n; ++i)
      {
        vtkIdType c[8];
        for (int b = 0; b < 8; ++b)
          c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        if (!tetrahedra)
        {
          const vtkIdType hex[8] = { c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6] };
          mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
          continue;
        }
        for (const auto& t : kuhn)
        {
          vtkIdType tet[4] = { c[t[0]], c[t[1]], c[t[2]], c[t[3]] };
          // Positive volume, VTK's orientation.
          double p[4][3];
          for (int q = 0; q < 4; ++q)
            points->GetPoint(tet[q], p[q]);
          double e[3][3];
          for (int q = 0; q < 3; ++q)
            for (int a = 0; a < 3; ++a)
              e[q][a] = p[q + 1][a] - p[0][a];
          const double volume = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
            e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
            e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
          if (volume < 0)
            std::swap(tet[1], tet[2]);
          mesh->InsertNextCell(VTK_TETRA, 4, tet);
        }
      }
  return mesh;
}

/// What the search promises, found by brute force: of the cells whose bounds
/// hold a grid point and whose EvaluatePosition (VTK's) says inside, the
/// lowest-numbered, its weights as floats summed in double as the resampler
/// sums them. `mask` 1 where a cell holds the point.
void lowestCellReference(vtkUnstructuredGrid* mesh, const bp::ResampleGrid& g,
  std::vector<float>& values, std::vector<char>& mask)
{
  values.assign(3 * g.pointCount(), 0.0f);
  mask.assign(g.pointCount(), 0);
  vtkFloatArray* v = vtkFloatArray::SafeDownCast(mesh->GetPointData()->GetArray("v"));
  vtkNew<vtkGenericCell> cell;
  std::vector<double> w(8);
  for (vtkIdType c = 0; c < mesh->GetNumberOfCells(); ++c)
  {
    double b[6];
    mesh->GetCellBounds(c, b);
    mesh->GetCell(c, cell);
    for (int k = 0; k < g.dims[2]; ++k)
      for (int j = 0; j < g.dims[1]; ++j)
        for (int i = 0; i < g.dims[0]; ++i)
        {
          const double x[3] = { g.origin[0] + i * g.spacing[0], g.origin[1] + j * g.spacing[1],
            g.origin[2] + k * g.spacing[2] };
          const std::size_t p = g.index(i, j, k);
          if (mask[p] || x[0] < b[0] || x[0] > b[1] || x[1] < b[2] || x[1] > b[3] || x[2] < b[4] ||
            x[2] > b[5])
            continue;
          int subId;
          double pcoords[3], dist2;
          if (cell->EvaluatePosition(x, nullptr, subId, pcoords, dist2, w.data()) != 1)
            continue;
          mask[p] = 1;
          for (int a = 0; a < 3; ++a)
          {
            double sum = 0.0;
            for (vtkIdType q = 0; q < cell->GetNumberOfPoints(); ++q)
              sum += double(float(w[q])) * double(v->GetComponent(cell->GetPointId(q), a));
            values[3 * p + a] = float(sum);
          }
        }
  }
}

TEST(FieldResampler, EachGridPointTakesTheLowestNumberedCellThatHoldsIt)
{
  // Tetrahedra with float and double points (read straight from the
  // arrays), hexahedra (through vtkGenericCell), serial and on threads: the
  // same bits as VTK's own cells give, and the same mask as a search with
  // vtkStaticCellLocator, one FindCell per grid point.
  for (const bool tetrahedra : { true, false })
    for (const bool doubles : { false, true })
    {
      auto mesh = jitteredMesh(7, tetrahedra, doubles);
      for (const bp::RangeRunner& run : { bp::serialRunner(), bp::poolRunner(3) })
      {
        bpvtk::FieldResampler r;
        Resampled out;
        bpvtk::VectorsChoice choice;
        choice.name = "v";
        out.error = r.resample(mesh, choice, { 23, 19, 17 }, nullptr, run, out.image, out.warning);
        ASSERT_TRUE(out.error.empty()) << out.error;
        std::vector<float> values;
        std::vector<char> mask;
        lowestCellReference(mesh, r.grid(), values, mask);
        vtkNew<vtkStaticCellLocator> locator;
        locator->SetDataSet(mesh);
        locator->BuildLocator();
        vtkNew<vtkGenericCell> cell;
        double w[8], pcoords[3];
        int subId;
        vtkIdType inside = 0;
        for (vtkIdType p = 0; p < out.image->GetNumberOfPoints(); ++p)
        {
          double x[3];
          out.image->GetPoint(p, x);
          const char found = locator->FindCell(x, 0.0, cell, subId, pcoords, w) >= 0 ? 1 : 0;
          ASSERT_EQ(out.mask()->GetValue(p), found) << "point " << p;
          ASSERT_EQ(mask[std::size_t(p)], found) << "point " << p;
          inside += found;
          for (int a = 0; a < 3; ++a)
          {
            const float ours = out.vectors()->GetValue(3 * p + a);
            ASSERT_EQ(std::memcmp(&ours, &values[std::size_t(3 * p + a)], sizeof(float)), 0)
              << "point " << p << " (" << ours << " against " << values[std::size_t(3 * p + a)]
              << ")";
          }
        }
        EXPECT_GT(inside, out.image->GetNumberOfPoints() / 2);
      }
    }
}

TEST(FieldResampler, AMeshThatChangesEveryStepIsSearchedAgainAsANewOne)
{
  // Issue 38: a script whose mesh changed topology between time steps
  // (point count, cells) ended with a SIGSEGV once. One resampler on threads
  // through meshes of every kind in turn, some arrays changed in place as a
  // reader may change them; each step's values are a fresh resampler's on the
  // same grid (run under AddressSanitizer: BOUNDPARTICLES_SANITIZE_RESAMPLER).
  auto hexes = hexMesh(6, linear);
  auto hole = hexMesh(9, linear, [](double x, double y, double) { return x + y < 0.6; });
  vtkNew<vtkMultiBlockDataSet> zones;
  zones->SetBlock(0, hexMesh(5, linear));
  zones->SetBlock(1, hexMesh(7, linear, nullptr, 0.3));
  zones->SetBlock(2, vtkNew<vtkUnstructuredGrid>()); // an empty block
  const std::vector<vtkSmartPointer<vtkDataObject>> steps = { hexes, jitteredMesh(7, true, false),
    zones.Get(), hole, jitteredMesh(5, false, true), hexes };
  bpvtk::FieldResampler kept;
  kept.setReleaseWeights("v", vtkDataObject::FIELD_ASSOCIATION_POINTS);
  int compared = 0;
  for (std::size_t s = 0; s < steps.size(); ++s)
  {
    if (s == 5)
    {
      // The first mesh again, its points moved and fewer of them in place.
      hexes->GetPoints()->SetNumberOfPoints(150);
      hexes->GetPointData()->GetArray("v")->SetNumberOfTuples(150);
      vtkNew<vtkCellArray> fewer;
      for (vtkIdType c = 0; c < hexes->GetNumberOfCells(); ++c)
      {
        vtkIdType n;
        const vtkIdType* ids;
        hexes->GetCellPoints(c, n, ids);
        if (*std::max_element(ids, ids + n) < 150)
          fewer->InsertNextCell(n, ids);
      }
      hexes->SetCells(VTK_HEXAHEDRON, fewer);
      hexes->GetPoints()->Modified();
    }
    Resampled out, reference;
    bpvtk::VectorsChoice choice;
    choice.name = "v";
    out.error = kept.resample(
      steps[s], choice, { 0, 0, 0 }, nullptr, bp::poolRunner(3), out.image, out.warning);
    ASSERT_TRUE(out.error.empty()) << "step " << s << ": " << out.error;
    EXPECT_FALSE(kept.keptWeights()) << "step " << s;
    bpvtk::FieldResampler fresh;
    fresh.setReleaseWeights("v", vtkDataObject::FIELD_ASSOCIATION_POINTS);
    const bp::ResampleGrid g = kept.grid();
    reference.error = fresh.resample(steps[s], choice, { g.dims[0], g.dims[1], g.dims[2] }, nullptr,
      bp::serialRunner(), reference.image, reference.warning);
    ASSERT_TRUE(reference.error.empty()) << reference.error;
    if (fresh.grid().spacing != g.spacing || fresh.grid().origin != g.origin)
    {
      continue; // the mesh lies elsewhere than the kept grid: nothing to compare
    }
    for (vtkIdType i = 0; i < out.vectors()->GetNumberOfValues(); ++i)
    {
      ASSERT_EQ(out.vectors()->GetValue(i), reference.vectors()->GetValue(i)) << "step " << s;
    }
    ++compared;
  }
  EXPECT_GE(compared, 4);
}

TEST(FieldResampler, InputsWithoutAMeshOrTheArrayAreRefusedWithAReason)
{
  bpvtk::FieldResampler r;
  Resampled out;
  vtkNew<vtkUnstructuredGrid> empty;
  resample(r, empty, out);
  EXPECT_NE(out.error.find("no cells"), std::string::npos) << out.error;

  // Vertices only (a point cloud): no surface or volume to interpolate in.
  vtkNew<vtkPolyData> cloud;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> vertices;
  vtkNew<vtkFloatArray> v;
  v->SetName("v");
  v->SetNumberOfComponents(3);
  for (vtkIdType i = 0; i < 10; ++i)
  {
    points->InsertNextPoint(double(i), double(i % 3), 0.5 * double(i % 2));
    vertices->InsertNextCell(1, &i);
    v->InsertNextTuple3(1, 0, 0);
  }
  cloud->SetPoints(points);
  cloud->SetVerts(vertices);
  cloud->GetPointData()->AddArray(v);
  resample(r, cloud, out);
  EXPECT_NE(out.error.find("points or lines"), std::string::npos) << out.error;

  auto mesh = hexMesh(4, linear);
  bpvtk::VectorsChoice missing;
  missing.name = "nothing";
  out.error =
    r.resample(mesh, missing, { 0, 0, 0 }, nullptr, bp::serialRunner(), out.image, out.warning);
  EXPECT_NE(out.error.find("'nothing'"), std::string::npos) << out.error;
  resample(r, mesh, out, { 100000, 100000, 100000 });
  EXPECT_NE(out.error.find("more than"), std::string::npos) << out.error;
}
} // namespace

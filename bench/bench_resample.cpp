// SPDX-License-Identifier: BSD-3-Clause
// What the mesh resampler costs on its own (issue 40): the first resample of
// a mesh (the cell search, which the first frame pays) and the next one with
// the mesh unchanged (the kept weights: one weighted sum per grid point), on
// the meshes bench/unstructured.py makes (hexahedra cut into five or six
// tetrahedra, jittered or not, or left as hexahedra) or on a .vtu given.
// Medians of --repeats, wall clock and the process's CPU time.
//
// --dump PREFIX writes each mesh's resampled vectors and mask (raw float32,
// then int8) to PREFIX<mesh>.raw, to compare two builds.
//
//   BoundParticlesResampleBench [--cells N] [--threads T] [--repeats R] [--vtu FILE] [--dump P]
#include "TracerResample.h"

#include "vtkCellArray.h"
#include "vtkCellType.h"
#include "vtkFloatArray.h"
#include "vtkIdTypeArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkSmartPointer.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLUnstructuredGridReader.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <random>
#include <string>
#include <thread>
#include <vector>

namespace
{
double cpuSeconds()
{
  timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

/// How a hexahedron of the lattice is cut.
enum class Cut
{
  Hexahedra,
  Five,
  Six
};

/**
 * The box [0,2] x [0,1] x [0,1] as 2n x n x n hexahedra (n from `cells`),
 * cut as asked, interior points jittered by up to `jitter` of a cell, with
 * point vectors "velocity" (a swirl): bench/unstructured.py's mesh.
 */
vtkSmartPointer<vtkUnstructuredGrid> boxMesh(double cells, Cut cut, double jitter)
{
  const double perHex = cut == Cut::Six ? 6.0 : cut == Cut::Five ? 5.0 : 1.0;
  const int n = std::max(2, int(std::lround(std::cbrt(cells / (2.0 * perHex)))));
  const int dims[3] = { 2 * n + 1, n + 1, n + 1 };
  const double h[3] = { 2.0 / (dims[0] - 1), 1.0 / (dims[1] - 1), 1.0 / (dims[2] - 1) };
  std::mt19937 random(1);
  std::uniform_real_distribution<double> shift(-jitter, jitter);
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> velocity;
  velocity->SetName("velocity");
  velocity->SetNumberOfComponents(3);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
      {
        const int index[3] = { i, j, k };
        double x[3];
        for (int a = 0; a < 3; ++a)
        {
          const bool interior = index[a] > 0 && index[a] < dims[a] - 1;
          x[a] = (index[a] + (interior ? shift(random) : 0.0)) * h[a];
        }
        points->InsertNextPoint(x);
        velocity->InsertNextTuple3(-std::sin(3.1 * x[1]), std::sin(1.6 * x[0]), 0.1 * x[2]);
      }
  auto mesh = vtkSmartPointer<vtkUnstructuredGrid>::New();
  mesh->SetPoints(points);
  mesh->GetPointData()->AddArray(velocity);
  auto id = [&](int i, int j, int k) { return vtkIdType(i + dims[0] * (j + dims[1] * k)); };
  // Corner c of a hexahedron: bit 0 along x, bit 1 along y, bit 2 along z.
  const int kuhn[6][4] = { { 0, 1, 3, 7 }, { 0, 1, 5, 7 }, { 0, 2, 3, 7 }, { 0, 2, 6, 7 },
    { 0, 4, 5, 7 }, { 0, 4, 6, 7 } };
  const int five[2][5][4] = { { { 0, 1, 2, 4 }, { 1, 3, 2, 7 }, { 1, 4, 5, 7 }, { 2, 7, 6, 4 },
                                { 1, 2, 4, 7 } },
    { { 1, 3, 0, 5 }, { 0, 2, 3, 6 }, { 0, 5, 4, 6 }, { 3, 6, 7, 5 }, { 0, 3, 5, 6 } } };
  for (int k = 0; k + 1 < dims[2]; ++k)
    for (int j = 0; j + 1 < dims[1]; ++j)
      for (int i = 0; i + 1 < dims[0]; ++i)
      {
        vtkIdType c[8];
        for (int b = 0; b < 8; ++b)
          c[b] = id(i + (b & 1), j + ((b >> 1) & 1), k + ((b >> 2) & 1));
        if (cut == Cut::Hexahedra)
        {
          const vtkIdType hex[8] = { c[0], c[1], c[3], c[2], c[4], c[5], c[7], c[6] };
          mesh->InsertNextCell(VTK_HEXAHEDRON, 8, hex);
          continue;
        }
        // Five: alternate the two mirror cuts so that faces match.
        const int(*tets)[4] = cut == Cut::Six ? kuhn : five[(i + j + k) % 2];
        for (int t = 0; t < (cut == Cut::Six ? 6 : 5); ++t)
        {
          vtkIdType tet[4] = { c[tets[t][0]], c[tets[t][1]], c[tets[t][2]], c[tets[t][3]] };
          double p[4][3];
          for (int q = 0; q < 4; ++q)
            points->GetPoint(tet[q], p[q]);
          double u[3], v[3], w[3];
          for (int a = 0; a < 3; ++a)
          {
            u[a] = p[1][a] - p[0][a];
            v[a] = p[2][a] - p[0][a];
            w[a] = p[3][a] - p[0][a];
          }
          const double volume = u[0] * (v[1] * w[2] - v[2] * w[1]) -
            u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
          if (volume < 0)
            std::swap(tet[1], tet[2]); // VTK's orientation
          mesh->InsertNextCell(VTK_TETRA, 4, tet);
        }
      }
  return mesh;
}

struct Timing
{
  std::vector<double> wall, cpu;
  void add(double w, double c)
  {
    wall.push_back(w);
    cpu.push_back(c);
  }
};

/// One resample of `mesh` by `r`, timed into `into`; the grid's inside share.
/// --dump: where each first resample's vectors and mask go (raw floats, chars), if anywhere.
std::string dumpPrefix;

double resampleOnce(bpvtk::FieldResampler& r, vtkUnstructuredGrid* mesh, const bp::RangeRunner& run,
  Timing& into, const std::string& dump = std::string())
{
  bpvtk::VectorsChoice choice;
  choice.name = "velocity";
  vtkNew<vtkImageData> image;
  std::string warning;
  const auto wall = std::chrono::steady_clock::now();
  const double cpu = cpuSeconds();
  const std::string error = r.resample(mesh, choice, { 0, 0, 0 }, nullptr, run, image, warning);
  into.add(std::chrono::duration<double>(std::chrono::steady_clock::now() - wall).count(),
    cpuSeconds() - cpu);
  if (!error.empty())
  {
    std::fprintf(stderr, "%s\n", error.c_str());
    std::exit(1);
  }
  vtkDataArray* mask = image->GetPointData()->GetArray("vtkValidPointMask");
  if (!dump.empty())
  {
    vtkDataArray* values = image->GetPointData()->GetArray("velocity");
    std::FILE* out = std::fopen(dump.c_str(), "wb");
    std::fwrite(values->GetVoidPointer(0), 4, std::size_t(values->GetNumberOfValues()), out);
    std::fwrite(mask->GetVoidPointer(0), 1, std::size_t(mask->GetNumberOfValues()), out);
    std::fclose(out);
  }
  double inside = 0.0;
  for (vtkIdType p = 0; p < mask->GetNumberOfTuples(); ++p)
    inside += mask->GetComponent(p, 0);
  return inside / double(mask->GetNumberOfTuples());
}

void measure(const char* name, vtkUnstructuredGrid* mesh, unsigned threads, int repeats)
{
  const bp::RangeRunner run = bp::poolRunner(threads);
  Timing first, kept;
  double inside = 0.0;
  std::array<int, 3> dims{};
  for (int r = 0; r < repeats; ++r)
  {
    bpvtk::FieldResampler resampler;
    std::string dump = dumpPrefix.empty() || r > 0 ? std::string() : dumpPrefix + name + ".raw";
    std::replace(dump.begin(), dump.end(), ' ', '_');
    inside = resampleOnce(resampler, mesh, run, first, dump);
    dims = resampler.grid().dims;
    // The same mesh again: new vectors only (the cells and weights kept).
    mesh->GetPointData()->GetArray("velocity")->Modified();
    resampleOnce(resampler, mesh, run, kept);
  }
  std::printf("%-26s %9lld %5d x %3d x %3d %7.1f%% %9.3f %9.3f %9.1f %9.1f\n", name,
    (long long)mesh->GetNumberOfCells(), dims[0], dims[1], dims[2], 100.0 * inside,
    median(first.wall), median(first.cpu), 1e3 * median(kept.wall), 1e3 * median(kept.cpu));
  std::fflush(stdout);
}
} // namespace

int main(int argc, char** argv)
{
  double cells = 1e6;
  unsigned threads = std::max(1u, std::thread::hardware_concurrency());
  int repeats = 3;
  std::string vtu;
  for (int i = 1; i < argc; ++i)
  {
    if (!std::strcmp(argv[i], "--cells") && i + 1 < argc)
      cells = std::atof(argv[++i]);
    else if (!std::strcmp(argv[i], "--threads") && i + 1 < argc)
      threads = unsigned(std::atoi(argv[++i]));
    else if (!std::strcmp(argv[i], "--repeats") && i + 1 < argc)
      repeats = std::atoi(argv[++i]);
    else if (!std::strcmp(argv[i], "--vtu") && i + 1 < argc)
      vtu = argv[++i];
    else if (!std::strcmp(argv[i], "--dump") && i + 1 < argc)
      dumpPrefix = argv[++i];
    else
    {
      std::fprintf(stderr,
        "usage: %s [--cells N] [--threads T] [--repeats R] [--vtu FILE] [--dump PREFIX]\n",
        argv[0]);
      return 2;
    }
  }
  std::printf("The mesh resampler alone, %u threads, medians of %d: the first resample (cell "
              "search) and the next with the mesh kept (weights kept)\n",
    threads, repeats);
  std::printf("%-26s %9s %15s %8s %9s %9s %9s %9s\n", "mesh", "cells", "grid", "inside", "first s",
    "first cpu", "kept ms", "kept cpu");
  if (!vtu.empty())
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(vtu.c_str());
    reader->Update();
    measure(vtu.substr(vtu.find_last_of('/') + 1).c_str(), reader->GetOutput(), threads, repeats);
    return 0;
  }
  const struct
  {
    const char* name;
    Cut cut;
    double jitter;
  } meshes[] = { { "tetrahedra, 6, jittered", Cut::Six, 0.1 }, { "tetrahedra, 6", Cut::Six, 0.0 },
    { "tetrahedra, 5, jittered", Cut::Five, 0.1 }, { "tetrahedra, 5", Cut::Five, 0.0 },
    { "hexahedra, jittered", Cut::Hexahedra, 0.1 } };
  for (const auto& m : meshes)
  {
    auto mesh = boxMesh(cells, m.cut, m.jitter);
    measure(m.name, mesh, threads, repeats);
  }
  return 0;
}

// SPDX-License-Identifier: BSD-3-Clause
// Writes every built-in element shape as a .vtp file: points at the rest
// positions, triangles as polygons, springs as lines (cell array Stiffness),
// which is exactly what the tracer's Element Template input reads back. Users
// start from these files to make their own elements.
//
//   BoundParticlesWriteElements OUTPUT_FOLDER    writes them
//   BoundParticlesWriteElements --check FOLDER   checks the committed ones
//
// The check compares values, not text: VTK 9.3 and later write the same
// floats with fewer digits than VTK 9.2.
#include "ElementTemplate.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdio>
#include <cstring>
#include <string>

namespace
{
/// The element as the tracer's Element Template input reads it.
vtkSmartPointer<vtkPolyData> elementMesh(const bp::ElementTemplate& shape)
{
  vtkNew<vtkPolyData> mesh;
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  for (const auto& r : shape.rest)
    points->InsertNextPoint(r[0], r[1], r[2]);
  mesh->SetPoints(points);
  vtkNew<vtkCellArray> lines, polys;
  vtkNew<vtkFloatArray> stiffness;
  stiffness->SetName("Stiffness");
  for (const bp::Spring& spring : shape.springs)
  {
    const vtkIdType ids[2] = { spring.a, spring.b };
    lines->InsertNextCell(2, ids);
    stiffness->InsertNextValue(spring.stiffness);
  }
  for (const auto& t : shape.triangles)
  {
    const vtkIdType ids[3] = { t[0], t[1], t[2] };
    polys->InsertNextCell(3, ids);
  }
  mesh->SetLines(lines);
  mesh->SetPolys(polys);
  // Cell data runs over lines, then polygons: springs have their stiffness,
  // triangles a 1 that the tracer does not read.
  for (std::size_t k = 0; k < shape.triangles.size(); ++k)
    stiffness->InsertNextValue(1.0f);
  mesh->GetCellData()->AddArray(stiffness);
  return mesh;
}

bool sameCells(vtkCellArray* a, vtkCellArray* b)
{
  if (a->GetNumberOfCells() != b->GetNumberOfCells() ||
    a->GetNumberOfConnectivityIds() != b->GetNumberOfConnectivityIds())
  {
    return false;
  }
  for (vtkIdType i = 0; i < a->GetNumberOfConnectivityIds(); ++i)
  {
    if (a->GetConnectivityArray()->GetComponent(i, 0) !=
      b->GetConnectivityArray()->GetComponent(i, 0))
    {
      return false;
    }
  }
  return true;
}

/// Empty when `committed` holds exactly `made`'s points, cells and stiffness.
std::string difference(vtkPolyData* made, vtkPolyData* committed)
{
  vtkDataArray* p = made->GetPoints()->GetData();
  vtkDataArray* q = committed->GetPoints() ? committed->GetPoints()->GetData() : nullptr;
  if (!q || p->GetNumberOfTuples() != q->GetNumberOfTuples())
  {
    return "a different number of points";
  }
  for (vtkIdType i = 0; i < p->GetNumberOfValues(); ++i)
  {
    if (float(p->GetComponent(i / 3, i % 3)) != float(q->GetComponent(i / 3, i % 3)))
    {
      return "point " + std::to_string(i / 3) + " moved";
    }
  }
  if (!sameCells(made->GetLines(), committed->GetLines()))
  {
    return "other springs";
  }
  if (!sameCells(made->GetPolys(), committed->GetPolys()))
  {
    return "other triangles";
  }
  vtkDataArray* a = made->GetCellData()->GetArray("Stiffness");
  vtkDataArray* b = committed->GetCellData()->GetArray("Stiffness");
  if (!b || a->GetNumberOfTuples() != b->GetNumberOfTuples())
  {
    return "no or another Stiffness array";
  }
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
  {
    if (float(a->GetTuple1(i)) != float(b->GetTuple1(i)))
    {
      return "the stiffness of cell " + std::to_string(i) + " changed";
    }
  }
  return std::string();
}
} // namespace

int main(int argc, char** argv)
{
  const bool check = argc == 3 && std::strcmp(argv[1], "--check") == 0;
  if (argc != 2 && !check)
  {
    std::fprintf(stderr, "usage: %s OUTPUT_FOLDER | --check COMMITTED_FOLDER\n", argv[0]);
    return 2;
  }
  const std::string folder = argv[argc - 1];
  int failures = 0;
  for (int s = 0; s < bp::enumCount<bp::BuiltinShape>(); ++s)
  {
    const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape(s));
    const vtkSmartPointer<vtkPolyData> mesh = elementMesh(shape);
    const std::string file = folder + "/" + shape.name + ".vtp";
    if (check)
    {
      vtkNew<vtkXMLPolyDataReader> reader;
      reader->SetFileName(file.c_str());
      reader->Update();
      const std::string why = difference(mesh, reader->GetOutput());
      if (!why.empty())
      {
        std::fprintf(stderr,
          "Elements/%s.vtp is out of date (%s): run BoundParticlesWriteElements on the "
          "Elements folder and commit the result\n",
          shape.name.c_str(), why.c_str());
        ++failures;
      }
      continue;
    }
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetFileName(file.c_str());
    writer->SetInputData(mesh);
    writer->SetDataModeToAscii();
    if (!writer->Write())
    {
      std::fprintf(stderr, "could not write %s\n", file.c_str());
      return 1;
    }
  }
  if (check && failures == 0)
  {
    std::printf("all %d built-in elements are current\n", bp::enumCount<bp::BuiltinShape>());
  }
  return failures == 0 ? 0 : 1;
}

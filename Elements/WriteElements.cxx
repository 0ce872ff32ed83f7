// SPDX-License-Identifier: BSD-3-Clause
// Writes every built-in element shape as a .vtp file: points at the rest
// positions, triangles as polygons, springs as lines (cell array Stiffness),
// which is exactly what the tracer's Element Template input reads back. Users
// start from these files to make their own elements.
//
//   BoundParticlesWriteElements OUTPUT_FOLDER
#include "ElementTemplate.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkFloatArray.h"
#include "vtkNew.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkXMLPolyDataWriter.h"

#include <cstdio>
#include <string>

int main(int argc, char** argv)
{
  if (argc != 2)
  {
    std::fprintf(stderr, "usage: %s OUTPUT_FOLDER\n", argv[0]);
    return 2;
  }
  for (int s = 0; s < bp::BuiltinShapeCount; ++s)
  {
    const bp::ElementTemplate shape = bp::builtinTemplate(bp::BuiltinShape(s));
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
    const std::string file = std::string(argv[1]) + "/" + shape.name + ".vtp";
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
  return 0;
}

// SPDX-License-Identifier: BSD-3-Clause
// The draw's per-configuration tables and their integer textures (DrawTables.h).
#include "DrawTables.h"

#include "ElementTemplate.h"
#include "Engine.h"
#include "SuperSet.h"
#include "SuperSetLinks.h"

#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTextureObject.h"
// VTK 9.4 replaced GLEW by glad as its OpenGL loader.
#if __has_include("vtk_glad.h")
#include "vtk_glad.h"
#else
#include "vtk_glew.h"
#endif

#include <algorithm>
#include <array>
#include <cstdint>
#include <utility>

namespace bpvtk
{

vtkSmartPointer<vtkPolyData> templatePolyData(
  const bp::ElementTemplate& shape, float size, bool links)
{
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  vtkNew<vtkPoints> points;
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  for (const auto& r : shape.rest)
  {
    points->InsertNextPoint(size * r[0], size * r[1], size * r[2]);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
  }
  mesh->SetPoints(points);
  mesh->GetPointData()->SetNormals(normals);
  vtkNew<vtkCellArray> cells;
  if (!shape.triangles.empty())
  {
    for (const auto& t : shape.triangles)
    {
      const vtkIdType ids[3] = { vtkIdType(t[0]), vtkIdType(t[1]), vtkIdType(t[2]) };
      cells->InsertNextCell(3, ids);
    }
    mesh->SetPolys(cells);
  }
  else if (!shape.springs.empty())
  {
    for (const auto& s : shape.springs)
    {
      const vtkIdType ids[2] = { vtkIdType(s.a), vtkIdType(s.b) };
      cells->InsertNextCell(2, ids);
    }
    mesh->SetLines(cells);
  }
  else
  {
    for (vtkIdType i = 0; i < vtkIdType(shape.rest.size()); ++i)
    {
      cells->InsertNextCell(1, &i);
    }
    mesh->SetVerts(cells);
  }
  if (links && mesh->GetNumberOfLines() == 0)
  {
    vtkNew<vtkCellArray> standIn;
    const vtkIdType ids[2] = { 0, 0 };
    standIn->InsertNextCell(2, ids);
    mesh->SetLines(standIn);
  }
  return mesh;
}

std::vector<int> linkPairs(const bp::Parameters& p)
{
  const bp::LinkTable table =
    bp::makeLinkTable(p.linking, p.numberOfElements, p.latticeWidth, p.emitterMin, p.emitterMax);
  std::vector<int> pairs;
  pairs.reserve(2 * table.linkCount());
  bp::forEachLink(table,
    [&pairs](std::size_t e, std::size_t f)
    {
      pairs.push_back(int(e));
      pairs.push_back(int(f));
    });
  return pairs;
}

std::vector<int> cornerTable(const bp::ElementTemplate& shape, int& width)
{
  const std::size_t n = shape.rest.size();
  std::vector<std::vector<std::array<int, 3>>> rows(n);
  for (const auto& t : shape.triangles)
  {
    const std::array<int, 3> corners = { int(t[0]), int(t[1]), int(t[2]) };
    for (std::uint32_t i : t)
    {
      rows[i].push_back(corners);
    }
  }
  width = 1;
  for (const auto& row : rows)
  {
    width = std::max(width, int(row.size()));
  }
  std::vector<int> texels(std::size_t(4) * width * n, -1);
  for (std::size_t i = 0; i < n; ++i)
  {
    for (std::size_t k = 0; k < rows[i].size(); ++k)
    {
      std::copy(rows[i][k].begin(), rows[i][k].end(), texels.begin() + 4 * (i * width + k));
    }
  }
  return texels;
}

IntegerTable::IntegerTable(int components)
  : Components(components)
{
}

IntegerTable::~IntegerTable() = default;

void IntegerTable::set(std::vector<int> texels, int width)
{
  this->Texels = std::move(texels);
  this->RowWidth = width;
  this->UploadedWidth = 0;
  this->Uploaded = false;
}

std::size_t IntegerTable::texelCount() const
{
  return this->Texels.size() / std::size_t(this->Components);
}

int IntegerTable::rowWidth(int maxSize) const
{
  return this->RowWidth > 0 ? this->RowWidth
                            : int(std::min(this->texelCount(), std::size_t(maxSize)));
}

std::size_t IntegerTable::rows(int maxSize) const
{
  const std::size_t width = std::size_t(this->rowWidth(maxSize));
  return width > 0 ? (this->texelCount() + width - 1) / width : 0;
}

bool IntegerTable::upload(vtkOpenGLRenderWindow* window, int maxSize)
{
  if (this->Texels.empty() || (this->Uploaded && this->Texture->GetHandle()))
  {
    return true;
  }
  this->Uploaded = true;
  const int width = this->rowWidth(maxSize);
  const std::size_t rows = this->rows(maxSize);
  if (rows > std::size_t(maxSize) || width > maxSize)
  {
    this->Texels.clear();
    this->UploadedWidth = 0;
    return false;
  }
  // The last row padded with zeros where the rows wrap at the texture size.
  std::vector<int> texels(std::size_t(this->Components) * std::size_t(width) * rows, 0);
  std::copy(this->Texels.begin(), this->Texels.end(), texels.begin());
  const bool pairs = this->Components == 2;
  this->Texture->SetContext(window);
  this->Texture->SetInternalFormat(pairs ? GL_RG32I : GL_RGBA32I);
  this->Texture->SetFormat(pairs ? GL_RG_INTEGER : GL_RGBA_INTEGER);
  this->Texture->Create2DFromRaw(
    unsigned(width), unsigned(rows), this->Components, VTK_INT, texels.data());
  this->UploadedWidth = width;
  return true;
}

int IntegerTable::width() const
{
  return this->Texels.empty() ? 0 : this->UploadedWidth;
}

unsigned IntegerTable::handle() const
{
  return this->Texels.empty() || this->UploadedWidth == 0 ? 0u : this->Texture->GetHandle();
}

void IntegerTable::release(vtkWindow* window)
{
  this->Texture->ReleaseGraphicsResources(window);
  this->Uploaded = false;
}

} // namespace bpvtk

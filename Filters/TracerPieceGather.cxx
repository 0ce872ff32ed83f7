// SPDX-License-Identifier: BSD-3-Clause
// In situ under MPI: each process holds the piece its simulation gave it,
// not the block with ghost layers the tracer asked for. PieceLayout::gatherPiece
// gathers each process's block from the pieces (docs/design.md, "In situ").
#include "TracerParallel.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkMultiProcessController.h"
#include "vtkPointData.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using Extent = std::array<int, 6>;

bool isEmpty(const Extent& e)
{
  return e[0] > e[1] || e[2] > e[3] || e[4] > e[5];
}

Extent intersection(const Extent& a, const Extent& b)
{
  Extent c;
  for (int axis = 0; axis < 3; ++axis)
  {
    c[2 * axis] = std::max(a[2 * axis], b[2 * axis]);
    c[2 * axis + 1] = std::min(a[2 * axis + 1], b[2 * axis + 1]);
  }
  return c;
}

bool contains(const Extent& outer, const Extent& inner)
{
  return isEmpty(inner) || intersection(outer, inner) == inner;
}

vtkIdType pointsIn(const Extent& e)
{
  return isEmpty(e) ? 0 : vtkIdType(e[1] - e[0] + 1) * (e[3] - e[2] + 1) * (e[5] - e[4] + 1);
}

std::string describe(const Extent& e)
{
  std::ostringstream text;
  text << "[" << e[0] << " " << e[1] << " " << e[2] << " " << e[3] << " " << e[4] << " " << e[5]
       << "]";
  return text.str();
}

/// The point arrays that travel: all but VTK's ghost marks, which describe
/// the held piece, not the gathered one.
std::vector<vtkDataArray*> travelling(vtkImageData* image)
{
  std::vector<vtkDataArray*> arrays;
  vtkPointData* pd = image->GetPointData();
  for (int i = 0; i < pd->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = pd->GetArray(i);
    if (array && array->GetName() && std::string(array->GetName()) != "vtkGhostType")
    {
      arrays.push_back(array);
    }
  }
  std::sort(arrays.begin(), arrays.end(),
    [](vtkDataArray* a, vtkDataArray* b) { return std::string(a->GetName()) < b->GetName(); });
  return arrays;
}

/// One point array's layout: what every process's piece must hold alike.
struct ArraySpec
{
  std::string name;
  int components = 1;
  int type = VTK_DOUBLE;
  bool operator==(const ArraySpec& o) const
  {
    return name == o.name && components == o.components && type == o.type;
  }
};

/// What every process's piece must share: the grid it lies on and its point
/// arrays. A piece with no points sends nothing and takes the others'.
struct PieceGrid
{
  double origin[3] = { 0.0, 0.0, 0.0 };
  double spacing[3] = { 1.0, 1.0, 1.0 };
  std::vector<ArraySpec> arrays;
};

/// `image`'s grid and arrays as text (names length-prefixed, numbers to full
/// precision), to be compared and shared between processes; empty for a
/// piece with no points.
std::string describeGrid(vtkImageData* image)
{
  if (image->GetNumberOfPoints() == 0)
  {
    return std::string();
  }
  std::ostringstream text;
  text << std::setprecision(17);
  for (int a = 0; a < 3; ++a)
  {
    text << image->GetOrigin()[a] << " " << image->GetSpacing()[a] << " ";
  }
  for (vtkDataArray* array : travelling(image))
  {
    const std::string name = array->GetName();
    text << name.size() << " " << name << " " << array->GetNumberOfComponents() << " "
         << array->GetDataType() << " ";
  }
  return text.str();
}

PieceGrid readGrid(const std::string& described)
{
  PieceGrid grid;
  std::istringstream text(described);
  for (int a = 0; a < 3; ++a)
  {
    text >> grid.origin[a] >> grid.spacing[a];
  }
  std::size_t length = 0;
  while (text >> length)
  {
    ArraySpec spec;
    text.get(); // the space before the name
    spec.name.resize(length);
    text.read(&spec.name[0], std::streamsize(length));
    text >> spec.components >> spec.type;
    grid.arrays.push_back(spec);
  }
  return grid;
}

/// Why `mine` (a piece's described grid) cannot be gathered with `first`
/// (the first piece's), or empty.
std::string mismatch(const std::string& mine, const std::string& first)
{
  if (mine.empty() || mine == first)
  {
    return std::string();
  }
  const PieceGrid a = readGrid(mine), b = readGrid(first);
  if (!(a.arrays == b.arrays))
  {
    return "The processes' pieces of the input hold different point arrays; every piece must "
           "hold the same ones.";
  }
  for (int axis = 0; axis < 3; ++axis)
  {
    const double tolerance = 1e-6 * std::abs(b.spacing[axis]);
    if (std::abs(a.origin[axis] - b.origin[axis]) > tolerance ||
      std::abs(a.spacing[axis] - b.spacing[axis]) > tolerance)
    {
      return "The processes' pieces of the input lie on different grids (origin or spacing); "
             "every piece must be a part of one grid.";
    }
  }
  return std::string();
}

/// An image with no points on `described`'s grid, with its arrays: what a
/// process whose piece is empty gathers into.
vtkSmartPointer<vtkImageData> emptyPieceOn(const std::string& described)
{
  const PieceGrid grid = readGrid(described);
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(grid.origin);
  image->SetSpacing(grid.spacing);
  for (const ArraySpec& spec : grid.arrays)
  {
    auto array = vtk::TakeSmartPointer(vtkDataArray::CreateDataArray(spec.type));
    array->SetName(spec.name.c_str());
    array->SetNumberOfComponents(spec.components);
    image->GetPointData()->AddArray(array);
  }
  return image;
}

int totalComponents(const std::vector<vtkDataArray*>& arrays)
{
  int total = 0;
  for (vtkDataArray* array : arrays)
  {
    total += array->GetNumberOfComponents();
  }
  return total;
}

/// Calls visit(id in `image`, index in `box`) for each point of `box`, x fastest.
template <typename Visit>
void forEachPoint(vtkImageData* image, const Extent& box, Visit visit)
{
  vtkIdType index = 0;
  for (int k = box[4]; k <= box[5]; ++k)
    for (int j = box[2]; j <= box[3]; ++j)
      for (int i = box[0]; i <= box[1]; ++i)
      {
        int ijk[3] = { i, j, k };
        visit(image->ComputePointId(ijk), index++);
      }
}

/// The values of `box` in `image`'s arrays: point after point, each point's
/// arrays in order.
std::vector<double> pack(vtkImageData* image, const Extent& box)
{
  const std::vector<vtkDataArray*> arrays = travelling(image);
  const int width = totalComponents(arrays);
  std::vector<double> values(std::size_t(pointsIn(box)) * width);
  forEachPoint(image, box,
    [&](vtkIdType id, vtkIdType index)
    {
      double* to = values.data() + std::size_t(index) * width;
      for (vtkDataArray* array : arrays)
      {
        array->GetTuple(id, to);
        to += array->GetNumberOfComponents();
      }
    });
  return values;
}

void unpack(const std::vector<double>& values, const Extent& box, vtkImageData* image,
  std::vector<char>& covered)
{
  const std::vector<vtkDataArray*> arrays = travelling(image);
  const int width = totalComponents(arrays);
  forEachPoint(image, box,
    [&](vtkIdType id, vtkIdType index)
    {
      const double* from = values.data() + std::size_t(index) * width;
      for (vtkDataArray* array : arrays)
      {
        array->SetTuple(id, from);
        from += array->GetNumberOfComponents();
      }
      covered[std::size_t(id)] = 1;
    });
}

/// An image over `extent` with `like`'s geometry and empty copies of its arrays.
vtkSmartPointer<vtkImageData> emptyLike(vtkImageData* like, const Extent& extent)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetOrigin(like->GetOrigin());
  image->SetSpacing(like->GetSpacing());
  image->SetExtent(const_cast<int*>(extent.data()));
  for (vtkDataArray* array : travelling(like))
  {
    auto copy = vtk::TakeSmartPointer(array->NewInstance());
    copy->SetName(array->GetName());
    copy->SetNumberOfComponents(array->GetNumberOfComponents());
    copy->SetNumberOfTuples(image->GetNumberOfPoints());
    image->GetPointData()->AddArray(copy);
  }
  return image;
}
} // namespace

namespace bpvtk
{

bool PieceLayout::blockWithGhosts(int piece, int extent[6]) const
{
  int owned[6];
  if (!pieceBlock(piece, this->Pieces, this->WholeExtent, this->Periodic, owned))
  {
    return false; // more processes than blocks: this one owns nothing
  }
  for (int a = 0; a < 3; ++a)
  {
    // Along a periodic axis the whole axis: the field across the seam.
    const bool whole = this->Periodic[std::size_t(a)];
    extent[2 * a] = whole ? this->WholeExtent[2 * a]
                          : std::max(owned[2 * a] - this->GhostCells, this->WholeExtent[2 * a]);
    extent[2 * a + 1] = whole
      ? this->WholeExtent[2 * a + 1]
      : std::min(owned[2 * a + 1] + this->GhostCells, this->WholeExtent[2 * a + 1]);
  }
  return true;
}

vtkSmartPointer<vtkImageData> PieceLayout::gatherPiece(vtkImageData* held, std::string& error)
{
  const int P = this->Pieces, me = this->Piece;
  Extent mine;
  held->GetExtent(mine.data());
  std::vector<int> all(std::size_t(6) * P);
  this->Controller->AllGather(mine.data(), all.data(), 6);
  std::vector<Extent> holds(static_cast<std::size_t>(P)), needs(static_cast<std::size_t>(P));
  bool everyoneHolds = true;
  for (int q = 0; q < P; ++q)
  {
    std::copy(all.begin() + 6 * q, all.begin() + 6 * (q + 1), holds[std::size_t(q)].begin());
    Extent& need = needs[std::size_t(q)];
    if (!this->blockWithGhosts(q, need.data()))
    {
      need = { 0, -1, 0, -1, 0, -1 };
    }
    everyoneHolds = everyoneHolds && contains(holds[std::size_t(q)], need);
  }
  if (everyoneHolds)
  {
    return held; // nothing needs to travel (every piece has its block and ghosts)
  }
  // Every process must send what it holds in one layout. A process whose
  // piece is empty has no grid or arrays of its own (a bare image's origin
  // and spacing are VTK's defaults): it gathers on the first piece's.
  const std::string mineDescribed = describeGrid(held);
  const std::string first = firstNonEmpty(this->Controller, mineDescribed);
  error = this->agree(mismatch(mineDescribed, first));
  if (!error.empty())
  {
    return nullptr;
  }
  vtkSmartPointer<vtkImageData> onFirstGrid;
  if (mineDescribed.empty())
  {
    onFirstGrid = emptyPieceOn(first);
    held = onFirstGrid;
  }
  const Extent& want = needs[std::size_t(me)];
  vtkSmartPointer<vtkImageData> piece = emptyLike(held, want);
  std::vector<char> covered(std::size_t(pointsIn(want)), 0);
  const Extent own = intersection(mine, want);
  if (!isEmpty(own))
  {
    unpack(pack(held, own), own, piece, covered);
  }
  // Pairwise, in one global order of pairs (blocking sends never wait on
  // each other in a cycle); only pairs with something to send talk.
  constexpr int tag = 8732;
  const int width = totalComponents(travelling(held));
  for (int q = 0; q < P; ++q)
  {
    if (q == me)
    {
      continue;
    }
    const Extent out = intersection(mine, needs[std::size_t(q)]);
    const Extent in = intersection(holds[std::size_t(q)], want);
    auto send = [&]
    {
      if (!isEmpty(out))
      {
        std::vector<double> values = pack(held, out);
        this->Controller->Send(values.data(), vtkIdType(values.size()), q, tag);
      }
    };
    auto receive = [&]
    {
      if (!isEmpty(in))
      {
        std::vector<double> values(std::size_t(pointsIn(in)) * width);
        this->Controller->Receive(values.data(), vtkIdType(values.size()), q, tag);
        unpack(values, in, piece, covered);
      }
    };
    exchangeInOrder(me, q, send, receive);
  }
  const bool whole = std::find(covered.begin(), covered.end(), 0) == covered.end();
  error = this->agree(whole ? std::string()
                            : "The processes' pieces of the input do not cover the extent " +
        describe(want) + " that process " + std::to_string(me) +
        " traces in; together they must cover the whole extent.");
  return error.empty() ? piece : nullptr;
}

} // namespace bpvtk

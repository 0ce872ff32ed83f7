// SPDX-License-Identifier: BSD-3-Clause
#include "TracerParallel.h"

#include "TracerReleaseWeights.h"

#include "vtkCommunicator.h"
#include "vtkDataArray.h"
#include "vtkExtentTranslator.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkRectilinearGrid.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace
{
/// The global controller when the pipeline asks for one of as many pieces as
/// it has processes (pvbatch, pvserver under MPI), else null.
vtkMultiProcessController* pieceController(int pieces)
{
  vtkMultiProcessController* c = vtkMultiProcessController::GetGlobalController();
  return pieces > 1 && c && c->GetNumberOfProcesses() == pieces ? c : nullptr;
}

/// Whether the block split of `whole` gives each of `pieces` a block with
/// cells along every axis that has them.
bool splitsIntoBlocks(const int whole[6], int pieces)
{
  vtkNew<vtkExtentTranslator> translator;
  for (int piece = 0; piece < pieces; ++piece)
  {
    int block[6];
    if (!translator->PieceToExtentThreadSafe(
          piece, pieces, 0, const_cast<int*>(whole), block, vtkExtentTranslator::BLOCK_MODE, 0))
    {
      return false;
    }
    for (int a = 0; a < 3; ++a)
    {
      // A block needs cells along every axis that has them.
      if (block[2 * a + 1] < block[2 * a] ||
        (whole[2 * a + 1] > whole[2 * a] && block[2 * a + 1] == block[2 * a]))
      {
        return false;
      }
    }
  }
  return true;
}

/// Sends each process its records, pairwise in one global order of pairs (so
/// blocking sends never wait on each other in a cycle); only pairs with
/// something to send talk.
bp::ExchangeFunction controllerExchange(vtkMultiProcessController* controller)
{
  return [controller](const std::vector<std::vector<std::uint32_t>>& outgoing)
  {
    const int P = controller->GetNumberOfProcesses(), me = controller->GetLocalProcessId();
    const std::size_t processes = std::size_t(P);
    std::vector<long long> counts(processes), all(processes * processes);
    for (int q = 0; q < P; ++q)
    {
      counts[std::size_t(q)] = q == me ? 0 : (long long)outgoing[std::size_t(q)].size();
    }
    controller->AllGather(counts.data(), all.data(), P);
    constexpr int tag = 8731;
    std::vector<std::uint32_t> incoming, buffer;
    for (int q = 0; q < P; ++q)
    {
      if (q == me)
      {
        continue;
      }
      const long long sending = all[std::size_t(me) * P + q];
      const long long receiving = all[std::size_t(q) * P + me];
      auto send = [&]
      {
        if (sending > 0)
          controller->Send(outgoing[std::size_t(q)].data(), vtkIdType(sending), q, tag);
      };
      auto receive = [&]
      {
        if (receiving > 0)
        {
          buffer.resize(std::size_t(receiving));
          controller->Receive(buffer.data(), vtkIdType(receiving), q, tag);
          incoming.insert(incoming.end(), buffer.begin(), buffer.end());
        }
      };
      bpvtk::exchangeInOrder(me, q, send, receive);
    }
    return incoming;
  };
}
} // namespace

namespace bpvtk
{

bool pieceBlock(
  int piece, int pieces, const int whole[6], const std::array<bool, 3>& periodic, int block[6])
{
  // The extent split: `whole` collapsed along the periodic axes, where that
  // gives every piece cells; every process decides alike from the same values.
  int split[6];
  std::copy(whole, whole + 6, split);
  bool collapsed = false;
  for (int a = 0; a < 3; ++a)
  {
    if (periodic[std::size_t(a)] && whole[2 * a + 1] > whole[2 * a])
    {
      split[2 * a + 1] = split[2 * a];
      collapsed = true;
    }
  }
  if (collapsed && !splitsIntoBlocks(split, pieces))
  {
    std::copy(whole, whole + 6, split);
    collapsed = false;
  }
  vtkNew<vtkExtentTranslator> translator;
  if (!translator->PieceToExtentThreadSafe(
        piece, pieces, 0, split, block, vtkExtentTranslator::BLOCK_MODE, 0))
  {
    return false;
  }
  for (int a = 0; collapsed && a < 3; ++a)
  {
    if (periodic[std::size_t(a)])
    {
      block[2 * a] = whole[2 * a];
      block[2 * a + 1] = whole[2 * a + 1];
    }
  }
  return true;
}

std::string agreeOnError(vtkMultiProcessController* controller, const std::string& error)
{
  return firstNonEmpty(controller, error);
}

std::string firstNonEmpty(vtkMultiProcessController* controller, const std::string& text)
{
  if (!controller)
  {
    return text;
  }
  const int processes = controller->GetNumberOfProcesses();
  std::vector<long long> lengths(std::size_t(processes), 0);
  const long long mine = (long long)text.size();
  controller->AllGather(&mine, lengths.data(), 1);
  for (int q = 0; q < processes; ++q)
  {
    const long long length = lengths[std::size_t(q)];
    if (length > 0)
    {
      std::string first(
        q == controller->GetLocalProcessId() ? text : std::string(std::size_t(length), ' '));
      controller->Broadcast(&first[0], vtkIdType(length), q);
      return first;
    }
  }
  return std::string();
}

bool PieceLayout::takeRequest(vtkInformation* outInfo, vtkInformation* inInfo)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  const int pieces = outInfo->Has(SDDP::UPDATE_NUMBER_OF_PIECES())
    ? outInfo->Get(SDDP::UPDATE_NUMBER_OF_PIECES())
    : 1;
  this->RequestedPiece =
    outInfo->Has(SDDP::UPDATE_PIECE_NUMBER()) ? outInfo->Get(SDDP::UPDATE_PIECE_NUMBER()) : 0;
  vtkMultiProcessController* controller = pieceController(pieces);
  // Every process decides alike, from the whole extent.
  this->TooSmall = controller && inInfo->Has(SDDP::WHOLE_EXTENT()) &&
    !splitsIntoBlocks(inInfo->Get(SDDP::WHOLE_EXTENT()), pieces);
  controller = this->TooSmall ? nullptr : controller;
  const bool changed =
    controller != this->Controller || (controller && this->Piece != this->RequestedPiece);
  this->Controller = controller;
  this->Pieces = controller ? pieces : 1;
  this->Piece = controller ? this->RequestedPiece : 0;
  return changed;
}

void PieceLayout::requestInput(vtkInformation* inInfo, bool mesh)
{
  using SDDP = vtkStreamingDemandDrivenPipeline;
  if (inInfo->Has(SDDP::WHOLE_EXTENT()))
  {
    // The whole extent: in parallel, the executive of a source that can
    // produce sub-extents splits it by piece (blocks, as below) and adds the
    // ghost layers.
    int* whole = inInfo->Get(SDDP::WHOLE_EXTENT());
    inInfo->Set(SDDP::UPDATE_EXTENT(), whole, 6);
    if (!mesh)
    {
      this->setWholeExtent(whole);
    }
  }
  // Without a process per piece, piece 0 traces the whole field: ask for all
  // of it. A mesh (resampled by the tracer, whatever its type) needs no
  // ghosts: the whole grid is known once every piece is read, and
  // cutPiece() adds the layers.
  inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), this->Piece);
  inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), this->Pieces);
  inInfo->Set(
    SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), this->distributed() && !mesh ? this->GhostCells : 0);
  int extent[6];
  const bool periodic = this->Periodic[0] || this->Periodic[1] || this->Periodic[2];
  if (periodic && !mesh && inInfo->Has(SDDP::WHOLE_EXTENT()) && this->distributed() &&
    this->blockWithGhosts(this->Piece, extent))
  {
    // The executive splits the update extent into blocks with ghost layers
    // alike along every axis; along a periodic one each process needs the
    // whole axis (the field across the seam), and the blocks split the other
    // axes only (pieceBlock()). So the extent is asked for as it is, one
    // piece: a source that produces sub-extents gives just it, another the
    // whole, which cropToPiece() cuts to it.
    inInfo->Set(SDDP::UPDATE_EXTENT(), extent, 6);
    inInfo->Set(SDDP::UPDATE_PIECE_NUMBER(), 0);
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_PIECES(), 1);
    inInfo->Set(SDDP::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
}

bool PieceLayout::setPeriodic(const std::array<bool, 3>& periodic)
{
  const bool changed = periodic != this->Periodic;
  this->Periodic = periodic;
  return changed && this->distributed();
}

void PieceLayout::setWholeExtent(const int whole[6])
{
  std::copy(whole, whole + 6, this->WholeExtent);
  if (!this->distributed())
  {
    return;
  }
  if (!pieceBlock(this->Piece, this->Pieces, this->WholeExtent, this->Periodic, this->OwnedExtent))
  {
    // More processes than blocks: this one owns nothing.
    for (int a = 0; a < 3; ++a)
    {
      this->OwnedExtent[2 * a] = whole[2 * a] + 1;
      this->OwnedExtent[2 * a + 1] = whole[2 * a];
    }
  }
}

vtkSmartPointer<vtkDataSet> PieceLayout::cropToPiece(vtkDataSet* held) const
{
  int have[6];
  if (vtkImageData* image = vtkImageData::SafeDownCast(held))
  {
    image->GetExtent(have);
  }
  else if (vtkRectilinearGrid* grid = vtkRectilinearGrid::SafeDownCast(held))
  {
    grid->GetExtent(have);
  }
  else
  {
    return nullptr;
  }
  int want[6];
  if (!this->distributed() || !this->blockWithGhosts(this->Piece, want))
  {
    return nullptr;
  }
  bool more = false;
  for (int a = 0; a < 3; ++a)
  {
    if (have[2 * a] > want[2 * a] || have[2 * a + 1] < want[2 * a + 1])
    {
      return nullptr; // not the piece asked for: share() and the grid checks say so
    }
    more = more || have[2 * a] < want[2 * a] || have[2 * a + 1] > want[2 * a + 1];
  }
  if (!more)
  {
    return nullptr;
  }
  auto cut = vtk::TakeSmartPointer(held->NewInstance());
  cut->ShallowCopy(held);
  cut->Crop(want); // new arrays: the producer's output stays as its other consumers hold it
  return cut;
}

vtkSmartPointer<vtkImageData> PieceLayout::cutPiece(vtkImageData* whole)
{
  this->setWholeExtent(whole->GetExtent());
  if (!this->distributed())
  {
    return whole;
  }
  // This process's block with GhostCells layers, as an image source gives
  // it; the whole axis along a periodic one.
  int piece[6];
  for (int a = 0; a < 3; ++a)
  {
    piece[2 * a] = std::max(this->OwnedExtent[2 * a] - this->GhostCells, this->WholeExtent[2 * a]);
    piece[2 * a + 1] =
      std::min(this->OwnedExtent[2 * a + 1] + this->GhostCells, this->WholeExtent[2 * a + 1]);
    if (this->Periodic[std::size_t(a)])
    {
      piece[2 * a] = this->WholeExtent[2 * a];
      piece[2 * a + 1] = this->WholeExtent[2 * a + 1];
    }
  }
  auto cut = vtkSmartPointer<vtkImageData>::New();
  cut->SetOrigin(whole->GetOrigin());
  cut->SetSpacing(whole->GetSpacing());
  cut->SetExtent(piece);
  vtkPointData* from = whole->GetPointData();
  for (int i = 0; i < from->GetNumberOfArrays(); ++i)
  {
    vtkDataArray* array = from->GetArray(i);
    auto part = vtk::TakeSmartPointer(array->NewInstance());
    part->SetName(array->GetName());
    part->SetNumberOfComponents(array->GetNumberOfComponents());
    part->SetNumberOfTuples(cut->GetNumberOfPoints());
    vtkIdType to = 0;
    for (int k = piece[4]; k <= piece[5]; ++k)
    {
      for (int j = piece[2]; j <= piece[3]; ++j)
      {
        const int first[3] = { piece[0], j, k };
        const vtkIdType row = whole->ComputePointId(const_cast<int*>(first));
        const vtkIdType n = piece[1] - piece[0] + 1;
        for (vtkIdType t = 0; t < n; ++t)
        {
          part->SetTuple(to++, row + t, array);
        }
      }
    }
    cut->GetPointData()->AddArray(part);
  }
  return cut;
}

namespace
{
/// What each process tells the others in share(): its block's box, whether
/// it read its piece, its smallest cell width, and its grid's spacing along
/// each uniform axis (NaN along a rectilinear one, or without a block).
constexpr int ShareValues = 11;

/// This process's values for share() (`mine`), or the error when the input
/// delivered an extent that lacks the block this process owns.
std::string localShare(
  const bp::GridGeometry& grid, const int extent[6], const int owned[6], double mine[ShareValues])
{
  const bool owns = owned[0] <= owned[1] && owned[2] <= owned[3] && owned[4] <= owned[5];
  double smallest = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a)
  {
    if (owns && (owned[2 * a] < extent[2 * a] || owned[2 * a + 1] > extent[2 * a + 1]))
    {
      std::ostringstream err;
      err << "The input delivered extent [" << extent[0] << " " << extent[1] << " " << extent[2]
          << " " << extent[3] << " " << extent[4] << " " << extent[5]
          << "], which lacks this process's block [" << owned[0] << " " << owned[1] << " "
          << owned[2] << " " << owned[3] << " " << owned[4] << " " << owned[5]
          << "]; the source must produce the extent it is asked for.";
      mine[7] = smallest;
      return err.str();
    }
    if (owns)
    {
      mine[2 * a] = grid.coordinate(a, owned[2 * a] - extent[2 * a]);
      mine[2 * a + 1] = grid.coordinate(a, owned[2 * a + 1] - extent[2 * a]);
      if (!grid.isRectilinear(a))
      {
        mine[8 + a] = std::abs(grid.spacing[a]);
      }
    }
    for (int i = 0; i + 1 < grid.dims[a]; ++i)
    {
      smallest = std::min(smallest, std::abs(grid.coordinate(a, i + 1) - grid.coordinate(a, i)));
      if (!grid.isRectilinear(a))
        break;
    }
  }
  mine[7] = smallest;
  return std::string();
}

/// Empty where `extent` spans the whole extent along every periodic axis,
/// otherwise the error: sampling across the seam reads the other side from
/// this piece (PieceLayout::setPeriodic).
std::string periodicGap(
  const int extent[6], const int whole[6], const std::array<bool, 3>& periodic)
{
  for (int a = 0; a < 3; ++a)
  {
    if (periodic[std::size_t(a)] &&
      (extent[2 * a] > whole[2 * a] || extent[2 * a + 1] < whole[2 * a + 1]))
    {
      std::ostringstream err;
      err << "The input delivered extent [" << extent[2 * a] << " " << extent[2 * a + 1]
          << "] along "
          << "xyz"[a] << ", which is periodic, where every process needs the whole "
          << "axis [" << whole[2 * a] << " " << whole[2 * a + 1]
          << "]; the source must produce the extent it is asked for.";
      return err.str();
    }
  }
  return std::string();
}
} // namespace

std::string PieceLayout::share(std::string error, const bp::GridGeometry& grid, const int extent[6],
  std::array<double, 3>& offset)
{
  std::copy(extent, extent + 6, this->PieceExtent);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  double mine[ShareValues] = { 1, 0, 1, 0, 1, 0, 1, 0, nan, nan, nan };
  if (error.empty())
  {
    error = localShare(grid, extent, this->OwnedExtent, mine);
    error = error.empty() ? periodicGap(extent, this->WholeExtent, this->Periodic) : error;
  }
  else
  {
    mine[7] = std::numeric_limits<double>::infinity();
  }
  mine[6] = error.empty() ? 1.0 : 0.0;
  std::vector<double> all(std::size_t(ShareValues) * this->Pieces);
  this->Controller->AllGather(mine, all.data(), ShareValues);
  std::vector<bp::Box> boxes(std::size_t(this->Pieces));
  this->DomainSmallestCell = std::numeric_limits<double>::infinity();
  std::array<double, 3> spacing = { nan, nan, nan };
  bool spaced = false;
  for (int q = 0; q < this->Pieces; ++q)
  {
    const double* v = all.data() + std::size_t(q) * ShareValues;
    if (v[6] == 0.0 && error.empty())
    {
      error = "Process " + std::to_string(q) +
        " could not read its piece of the input; see its error message.";
    }
    std::copy(v, v + 6, boxes[std::size_t(q)].begin());
    this->DomainSmallestCell = std::min(this->DomainSmallestCell, v[7]);
    if (!spaced && !bp::isEmptyBox(boxes[std::size_t(q)]))
    {
      std::copy(v + 8, v + 11, spacing.begin()); // the first block's, alike on every process
      spaced = true;
    }
  }
  if (error.empty())
  {
    error = bp::Partition::validate(boxes);
    error = error.empty() ? error : "The processes' pieces of the input do not fit: " + error + ".";
  }
  if (!error.empty())
  {
    return error;
  }
  this->placeDomain(boxes, spacing, offset);
  return std::string();
}

void PieceLayout::placeDomain(
  std::vector<bp::Box> boxes, const std::array<double, 3>& spacing, std::array<double, 3>& offset)
{
  const bp::Box world = bp::Partition(boxes).domain();
  offset = { world[0], world[2], world[4] };
  for (bp::Box& b : boxes)
  {
    // Whether a box is empty is decided before it moves: tested during the
    // move, a box whose lower bound had moved past its unmoved upper bound
    // passed for empty and stayed half moved (every field not at the origin).
    if (bp::isEmptyBox(b))
    {
      continue;
    }
    for (int k = 0; k < 6; ++k)
    {
      b[k] -= offset[std::size_t(k / 2)];
    }
  }
  this->Partition.reset(new bp::Partition(boxes));
  const bp::Box& local = this->Partition->domain();
  double sum = 0.0;
  int axes = 0;
  for (int a = 0; a < 3; ++a)
  {
    const int cells = this->WholeExtent[2 * a + 1] - this->WholeExtent[2 * a];
    this->Domain.lower[a] = float(local[2 * a]);
    this->Domain.upper[a] = float(local[2 * a + 1]);
    this->Domain.degenerate[a] = cells < 1;
    // No sides along a periodic axis: the engine moves an element whose
    // centre leaves there by a period (Engine::wrapPeriodic, on the whole
    // field's bounds), before the next step hands it to its new owner.
    this->Domain.periodic[a] = this->Periodic[std::size_t(a)] && cells >= 1;
    if (cells >= 1)
    {
      // A uniform axis's spacing, as one process's grid gives it: the
      // domain's far corner rounds differently with each split (each piece
      // places its points from its own first one), and the steps and sizes
      // that follow from this length must not depend on the process count
      // (a saved state resumes on another, its step compared by bits).
      sum += std::isnan(spacing[a]) ? (local[2 * a + 1] - local[2 * a]) / cells : spacing[a];
      ++axes;
    }
  }
  this->DomainCellLength = axes > 0 ? sum / axes : 1.0;
}

double PieceLayout::globalMax(double value) const
{
  double global = value;
  this->Controller->AllReduce(&value, &global, 1, vtkCommunicator::MAX_OP);
  return global;
}

void PieceLayout::globalMax(std::vector<double>& values) const
{
  std::vector<double> global(values.size());
  this->Controller->AllReduce(
    values.data(), global.data(), vtkIdType(values.size()), vtkCommunicator::MAX_OP);
  values.swap(global);
}

std::vector<long long> PieceLayout::gather(long long count) const
{
  std::vector<long long> all(std::size_t(this->Pieces), 0);
  this->Controller->AllGather(&count, all.data(), 1);
  return all;
}

std::string PieceLayout::agree(const std::string& error) const
{
  return agreeOnError(this->Controller, error);
}

int PieceLayout::shareFirst(std::vector<double>& values) const
{
  const std::vector<long long> counts = this->gather((long long)values.size());
  const auto first = std::find_if(counts.begin(), counts.end(), [](long long n) { return n > 0; });
  if (first == counts.end())
  {
    return 0;
  }
  const int root = int(first - counts.begin());
  int others = 0;
  for (int q = root + 1; q < this->Pieces; ++q)
  {
    others += counts[std::size_t(q)] > 0 && counts[std::size_t(q)] != *first ? 1 : 0;
  }
  values.resize(std::size_t(*first));
  this->Controller->Broadcast(values.data(), vtkIdType(*first), root);
  return others;
}

bp::ExchangeFunction PieceLayout::exchange() const
{
  return controllerExchange(this->Controller);
}

std::array<double, 6> PieceLayout::domainBounds(const bp::GridGeometry& local) const
{
  return this->distributed() && this->Partition ? this->Partition->domain() : local.bounds();
}

bp::ReleaseMaskFunction PieceLayout::releaseMask() const
{
  return [this](const bp::VectorField& piece, float minSpeed)
  {
    const bp::GridGeometry& local = piece.grid();
    bp::GridGeometry whole;
    int shift[3], cells[3][2]; // piece-to-whole index shift; this block's cells
    for (int a = 0; a < 3; ++a)
    {
      whole.dims[a] = this->WholeExtent[2 * a + 1] - this->WholeExtent[2 * a] + 1;
      whole.spacing[a] = local.spacing[a];
      shift[a] = this->PieceExtent[2 * a] - this->WholeExtent[2 * a];
      const int lastCell = std::max(whole.dims[a] - 2, 0);
      cells[a][0] = this->OwnedExtent[2 * a] - this->WholeExtent[2 * a];
      cells[a][1] = std::min(this->OwnedExtent[2 * a + 1] - this->WholeExtent[2 * a], lastCell);
    }
    // Engine coordinates start at the whole grid's first point (share()).
    for (int a = 0; a < 3; ++a)
    {
      if (!local.isRectilinear(a))
      {
        continue;
      }
      // Each piece gives its points; the others -inf, so the largest is the one.
      std::vector<double> mine(std::size_t(whole.dims[a]), -std::numeric_limits<double>::max());
      for (int i = 0; i < local.dims[a]; ++i)
      {
        mine[std::size_t(i + shift[a])] = local.coordinate(a, i);
      }
      std::vector<double> all(mine.size());
      this->Controller->AllReduce(
        mine.data(), all.data(), vtkIdType(mine.size()), vtkCommunicator::MAX_OP);
      whole.setCoordinates(a, std::move(all));
    }
    const auto localUnfit = bp::releaseUnfitCells(piece, minSpeed);
    std::vector<std::uint8_t> mine(whole.pointCount(), 0);
    const int nx = local.dims[0], ny = local.dims[1];
    for (int k = cells[2][0]; localUnfit && k <= cells[2][1]; ++k)
      for (int j = cells[1][0]; j <= cells[1][1]; ++j)
        for (int i = cells[0][0]; i <= cells[0][1]; ++i)
        {
          const std::size_t at = std::size_t(i - shift[0]) +
            std::size_t(nx) * (std::size_t(j - shift[1]) + std::size_t(ny) * (k - shift[2]));
          mine[std::size_t(i) +
            std::size_t(whole.dims[0]) * (std::size_t(j) + std::size_t(whole.dims[1]) * k)] =
            (*localUnfit)[at];
        }
    auto unfit = std::make_shared<std::vector<std::uint8_t>>(mine.size());
    this->Controller->AllReduce(
      mine.data(), unfit->data(), vtkIdType(mine.size()), vtkCommunicator::MAX_OP);
    const bool any = std::find(unfit->begin(), unfit->end(), 1) != unfit->end();
    // Release Weights over the whole field, as the mask (TracerReleaseWeights.h).
    const auto weights = gatherReleaseWeights(this->Controller, whole, local, shift,
      piece.firstSlice().releaseWeights, any ? unfit.get() : nullptr);
    return bp::ReleaseMask{ whole, any ? unfit : nullptr, weights };
  };
}

double PieceLayout::cellLength(const bp::GridGeometry& local) const
{
  return this->distributed() ? this->DomainCellLength : local.cellLength();
}

std::array<int, 3> PieceLayout::wholeDims(const bp::GridGeometry& local) const
{
  std::array<int, 3> dims = local.dims;
  for (int a = 0; a < 3 && this->distributed(); ++a)
  {
    dims[a] = this->WholeExtent[2 * a + 1] - this->WholeExtent[2 * a] + 1;
  }
  return dims;
}

} // namespace bpvtk

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerParallel.h
 * @brief The tracer's part of a distributed run (pvbatch, pvserver under MPI).
 *
 * When the pipeline asks for one of as many pieces as there are processes,
 * each process asks its input for one block of the image extent (the
 * vtkExtentTranslator's block split) with ghost layers, owns the elements
 * whose centres lie in its block, and in each step (after resets, before
 * advection) hands elements to the
 * process that owns their new centre (bp::DistributedStepper, through the
 * global vtkMultiProcessController). Along a periodic axis each process
 * reads the whole axis instead of its block's share (the field across the
 * seam), the blocks then split the other axes only where they can
 * (pieceBlock()), and an element the last step moved across the seam is
 * handed over with the others. Otherwise piece 0 traces the whole field and other
 * pieces are empty.
 */
#ifndef BoundParticles_TracerParallel_h
#define BoundParticles_TracerParallel_h

#include "DomainMask.h"
#include "Partition.h"
#include "VectorField.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "vtkSmartPointer.h"

class vtkDataSet;
class vtkImageData;
class vtkInformation;
class vtkMultiProcessController;

namespace bpvtk
{

/// One pairwise exchange of this process `me` with process `q` over blocking
/// sends: the lower of the two sends first, so neither waits on the other.
template <typename Send, typename Receive>
void exchangeInOrder(int me, int q, const Send& send, const Receive& receive)
{
  if (me < q)
  {
    send();
    receive();
  }
  else
  {
    receive();
    send();
  }
}

/**
 * Where one process failed and the others did not, every process must fail
 * before the next collective call, or the others would wait in it forever:
 * the first failing process's `error` (collective over `controller`; empty
 * when none failed). Without a controller, `error` itself.
 */
std::string agreeOnError(vtkMultiProcessController* controller, const std::string& error);

/**
 * The lowest process's non-empty `text`, on every process (collective over
 * `controller`; empty when every process's is empty): a choice that one
 * process makes from data the others may lack. Without a controller, `text`.
 */
std::string firstNonEmpty(vtkMultiProcessController* controller, const std::string& text);

/**
 * Piece `piece` of `pieces`' block of the extent `whole` (the block this
 * process owns), the same on every process. With `periodic` axes the split
 * runs along the others only: vtkExtentTranslator's block split of `whole`
 * collapsed to its first point along each periodic axis, the block then
 * widened to the whole axis there, so that a process holds whole periodic
 * axes over its own part of the others. Where that split cannot give every
 * piece cells (every axis periodic, or too few cells along the others), and
 * without periodic axes, the block split of `whole` itself (the executive's).
 * False where the piece owns nothing (more pieces than blocks).
 */
bool pieceBlock(
  int piece, int pieces, const int whole[6], const std::array<bool, 3>& periodic, int block[6]);

class PieceLayout
{
public:
  /**
   * Takes the pieces the output request asks for (UPDATE_PIECE_NUMBER,
   * UPDATE_NUMBER_OF_PIECES). Returns true when they differ from the last
   * request's: a change of pieces is a change of input, so the trace replays.
   * A field too small to give every process a block of cells (`inInfo`'s
   * whole extent) is traced whole by piece 0, as without a process per piece.
   */
  bool takeRequest(vtkInformation* outInfo, vtkInformation* inInfo);
  /// Whether piece 0 traces alone because the field has too few cells to split.
  bool tooSmallToSplit() const { return this->TooSmall; }

  /// Asks the input for the whole extent (one process) or this process's
  /// block with GhostCells layers (the executive splits it); a `mesh` (an
  /// input the tracer resamples) for this process's piece, without ghosts.
  /// With a periodic axis (setPeriodic) an image or grid is asked for
  /// blockWithGhosts() as one piece: the whole axis on every process.
  void requestInput(vtkInformation* inInfo, bool mesh);

  /**
   * The periodic axes (the tracer's Periodic). Along one, a process's piece
   * of the field spans the whole axis, so that sampling across the seam
   * reads the field on the other side without an exchange of field data,
   * while the process still owns only the elements of its block (an element
   * moved across the seam migrates in the next step, as any other). Returns
   * whether they changed in a distributed run: the pieces read change.
   */
  bool setPeriodic(const std::array<bool, 3>& periodic);

  /// Takes the whole grid's extent and this process's block of it
  /// (pieceBlock(), along the axes that are not periodic where it can).
  void setWholeExtent(const int whole[6]);

  /**
   * The piece of `whole` (the whole grid, resampled from a mesh) that this
   * process would have read from an image: its block with GhostCells layers
   * (the whole axis along a periodic one). `whole` itself outside a
   * distributed run.
   */
  vtkSmartPointer<vtkImageData> cutPiece(vtkImageData* whole);

  /**
   * In situ each process holds the piece its simulation gave it (any extent
   * of the announced whole extent), not the block with ghost layers it asked
   * for: `held` itself where every process holds its block and GhostCells
   * layers, else this process's block with its layers, the point arrays
   * gathered from every process's piece (collective; TracerPieceGather.cxx).
   * A process whose piece has no points gathers on the first non-empty
   * piece's grid and arrays. Null with `error` set on every process where the
   * pieces do not cover a block, hold different arrays or lie on different
   * grids.
   */
  vtkSmartPointer<vtkImageData> gatherPiece(vtkImageData* held, std::string& error);

  /**
   * Where `held` (an image or a rectilinear grid, as delivered) has more
   * ghost layers than asked for, this process's block with GhostCells layers
   * cut from it (a copy; `held` is left as it is); null where it has just
   * those, or does not hold them all. The executive gives a piece with more
   * layers without running its producer again when the producer holds one
   * (asked for by another consumer: a second tracer on the same source),
   * while the next time step comes with the layers asked for: every time
   * step must be read on one extent.
   */
  vtkSmartPointer<vtkDataSet> cropToPiece(vtkDataSet* held) const;

  /// Piece `piece`'s block of the whole extent (pieceBlock()) with
  /// GhostCells layers, and the whole extent along a periodic axis; false
  /// where it owns nothing (more processes than blocks).
  bool blockWithGhosts(int piece, int extent[6]) const;

  /**
   * Gathers every process's block of the field (its owned extent's bounds)
   * into the partition and the whole field's domain, and sets `offset` to the
   * whole grid's first point. Collective; a process that could not read its
   * piece (`error` not empty) makes every process fail. Returns the error, if any.
   */
  std::string share(std::string error, const bp::GridGeometry& grid, const int extent[6],
    std::array<double, 3>& offset);

  /// The largest of every process's `value` (collective).
  double globalMax(double value) const;
  /// Each value the largest over the processes (every process gives as many).
  void globalMax(std::vector<double>& values) const;

  /// Every process's `count`, in process order (collective).
  std::vector<long long> gather(long long count) const;

  /// agreeOnError() among this layout's processes.
  std::string agree(const std::string& error) const;

  /**
   * Gives every process the same values: those of the first process whose
   * `values` are not empty (collective). A source filled on one process only
   * (a trivial producer) then serves all. Returns how many later processes
   * had a different, non-zero number of values (values of the same count are
   * not compared).
   */
  int shareFirst(std::vector<double>& values) const;

  /// The element exchange through the controller (DistributedStepper).
  bp::ExchangeFunction exchange() const;

  /**
   * The whole field's release mask (bp::releaseUnfitCells) from this
   * process's piece: each process marks the cells of its block, and all
   * combine them (collective; one byte per grid point travels). The whole
   * grid's rectilinear axes are gathered the same way.
   */
  bp::ReleaseMaskFunction releaseMask() const;

  bool distributed() const { return this->Controller != nullptr; }
  /// Whether this process outputs nothing: a piece other than 0 of several
  /// asked for without a process per piece.
  bool idle() const { return !this->distributed() && this->RequestedPiece != 0; }

  /// The whole field's bounds, grid-local (`local` is this process's grid).
  std::array<double, 6> domainBounds(const bp::GridGeometry& local) const;
  /// The whole field's mean cell length (`local` is this process's grid).
  double cellLength(const bp::GridGeometry& local) const;
  /// The whole field's points per axis (`local` is this process's grid):
  /// 1 along a flat axis, where a process's block may be thin but the field is not.
  std::array<int, 3> wholeDims(const bp::GridGeometry& local) const;

  vtkMultiProcessController* Controller = nullptr;
  int Piece = 0;
  int Pieces = 1;
  int RequestedPiece = 0; ///< the output piece asked for (without a controller)
  bool TooSmall = false;  ///< processes to split among, but too few cells
  int GhostCells = 2;     ///< around the owned block; grown at a replay if too few
  /// Periodic axes: a piece holds the whole axis (setPeriodic).
  std::array<bool, 3> Periodic = { false, false, false };
  int WholeExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int OwnedExtent[6] = { 0, -1, 0, -1, 0, -1 };
  int PieceExtent[6] = { 0, -1, 0, -1, 0, -1 }; ///< the extent this process read (with ghosts)
  std::unique_ptr<bp::Partition> Partition;     ///< every piece's block, grid-local
  bp::Domain Domain;                            ///< the whole field's, grid-local
  double DomainCellLength = 1.0, DomainSmallestCell = 1.0;

private:
  /// After share(): the whole grid's first point as `offset`, the pieces'
  /// `boxes` moved by it into the partition, and the whole field's domain
  /// and cell length (from `spacing` along uniform axes, NaN elsewhere).
  void placeDomain(std::vector<bp::Box> boxes, const std::array<double, 3>& spacing,
    std::array<double, 3>& offset);
};

} // namespace bpvtk

#endif

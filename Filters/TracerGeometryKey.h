// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerGeometryKey.h
 * @brief What the resampler's located cells and weights depend on, as one
 * 64-bit key: the sampled blocks' points and cells, hashed (FieldResampler
 * keeps its weights while the key stays).
 */
#ifndef BoundParticles_TracerGeometryKey_h
#define BoundParticles_TracerGeometryKey_h

#include "Parallel.h"

#include "vtkDataArray.h"
#include "vtkType.h"
#include "vtkWeakPointer.h"

#include <array>
#include <cstdint>
#include <vector>

class vtkDataSet;
class vtkMultiProcessController;

namespace bpvtk
{

/// An array whose content was hashed: while it lives unmodified (a reader
/// that keeps a static mesh hands the same arrays again), its hash stands.
struct HashedArray
{
  vtkWeakPointer<vtkDataArray> array;
  vtkMTimeType time = 0;
  std::uint64_t hash = 0;
};

/// The key of the sampled `blocks`' geometry, the dimensions `requested` and
/// the number of processes. `hashed`: the arrays hashed last time, whose
/// hashes stand while they are unmodified; on return, those of this key.
std::uint64_t geometryKey(const std::vector<vtkDataSet*>& blocks,
  const std::array<int, 3>& requested, vtkMultiProcessController* controller,
  const bp::RangeRunner& run, std::vector<HashedArray>& hashed);

} // namespace bpvtk

#endif

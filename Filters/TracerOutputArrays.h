// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TracerOutputArrays.h
 * @brief How each row of bp::outputArrays() is written into the tracer's
 * output: a block of whole elements at a time, inside the one pass that
 * writes every array (TracerOutput.cxx), and the trails' tuples after them;
 * and the frame the output is shown in (OutputFrame).
 */
#ifndef BoundParticles_TracerOutputArrays_h
#define BoundParticles_TracerOutputArrays_h

#include "Engine.h"
#include "OutputArrays.h"
#include "Parallel.h"
#include "VectorField.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

class vtkDataArray;

namespace bpvtk
{

/// Where the particles are shown: what turns engine state into output.
struct OutputFrame
{
  double time = 0.0;                                   ///< the simulation time shown
  /// A backward trace (TimeDirection.h): `time` and the field are the trace's,
  /// whose flow is the data's reversed; Velocity and ElementSpin are written
  /// per time of the data (negated), SpinVorticityRatio is the same either way.
  bool backward = false;
  std::array<double, 3> offset = { 0, 0, 0 };          ///< world position of the grid-local origin
  std::array<double, 6> domain = { 0, 1, 0, 1, 0, 1 }; ///< the whole field, grid-local
  double reach = 0.0;      ///< the largest world |coordinate| in the field
  double cellLength = 1.0; ///< of the local grid (for the points' precision)
  int coloringAxis = 2;    ///< for Layer and Radius
  /// Per row of the table, by id: whether the output carries it (the
  /// tracer's Output Arrays and Compute Vorticity).
  std::array<bool, std::size_t(bp::OutputArrayId::Count)> wanted = everyArray();

  bool wants(const bp::OutputArray& row) const { return this->wanted[std::size_t(row.id)]; }
  static std::array<bool, std::size_t(bp::OutputArrayId::Count)> everyArray()
  {
    std::array<bool, std::size_t(bp::OutputArrayId::Count)> all;
    all.fill(true);
    return all;
  }
};

/// A pose of an element's trail that the output shows.
struct TrailPose
{
  std::size_t slot;    ///< in the engine's trail ring
  std::size_t element; ///< whose pose it is
  float age;           ///< how long before the time shown
};

/**
 * The trail poses to show at `time`, newest first: those of each shown
 * element's own generation (a released element starts a new trail), strictly
 * older than the time shown (a step taken back leaves none ahead of it), and
 * not across a periodic seam of `field` from the element
 * (Engine::trailAcrossSeam: the trail breaks where the element moved by a period).
 */
std::vector<TrailPose> trailPoses(
  const bp::Engine& engine, const bp::VectorField& field, double time);

/// What filling an array may read: the engine, the field, the frame, and the
/// output's arrays by id (null where the frame does not want one); those of
/// earlier rows are filled.
struct FillContext
{
  const bp::Engine& engine;
  const bp::VectorField& field;
  const OutputFrame& frame;
  const bp::RangeRunner& run;
  const std::vector<TrailPose>& trail;
  std::array<vtkDataArray*, std::size_t(bp::OutputArrayId::Count)> arrays;
  const bp::RangeRunner serial = bp::serialRunner(); ///< inside a block

  vtkDataArray* array(bp::OutputArrayId id) const { return this->arrays[std::size_t(id)]; }
};

/**
 * For a row whose values do not change while its inputs stay (ElementId,
 * ParticleIndex, Layer, Radius), a key of those inputs (the elements' ids,
 * the template's size, the release centres and the frame they are measured
 * in): the last output's array is shown again while the key stays. 0 for the
 * other rows, and for every row when trails add tuples.
 */
std::uint64_t unchangedKey(const bp::OutputArray& row, const FillContext& c);

/// Writes particles [begin, end) of `out` as its row's source says (the
/// block's ends are whole elements).
void writeParticles(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c,
  std::size_t begin, std::size_t end);

/**
 * The values of a trail pose's points: its element's (the pose is drawn
 * coloured as its element is now), but Age (each pose's own) and Normals
 * (of the pose).
 */
void extendToTrail(const bp::OutputArray& row, vtkDataArray* out, const FillContext& c);

} // namespace bpvtk

#endif

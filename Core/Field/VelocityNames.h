// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file VelocityNames.h
 * @brief Which of a field's 3-component arrays is named like a velocity.
 *
 * Readers seldom mark an array as the active vectors: an Exodus or LS-DYNA
 * result offers ACCL, DISPL and VEL, an OpenFOAM case U and its gradients,
 * a weather model wind and its derivatives, and picking the first gave the
 * acceleration (the can: a carpet of strips coloured up to 1.8e7). The
 * Vectors property's default (the plugin's vtkSMBoundParticleVectorsDomain)
 * and the tracer's note of what it traces rank the names here: the input's
 * own active vectors first, then a name that says velocity, then the first;
 * but where that array's units fail the time line's check (gfs_wind10m's
 * active `velocity`, m/s on a degree grid with time in hours) and another's
 * pass it (its `velocity_deg_per_hour`), the one that passes
 * (preferFittingUnits).
 */
#ifndef BoundParticles_VelocityNames_h
#define BoundParticles_VelocityNames_h

#include <cstddef>
#include <string>
#include <vector>

namespace bp
{

/// How strongly `name` says velocity: 0 a velocity's own name (velocity,
/// vel, U, uvw, wind, flow...; any case, any separators), 1 a name holding
/// one as a word (velocity_deg_per_hour, WindVelocity, U_mean), -1 none
/// (and never a name of another quantity: acceleration, displacement,
/// vorticity, a gradient, normals, coordinates).
int velocityNameRank(const std::string& name);

/// The index in `names` of the best velocity name (the lowest rank, the
/// first among equals), or -1 where none is named like a velocity.
int pickVelocityName(const std::vector<std::string>& names);

/// Whether `name` holds a word of another vector quantity (acceleration,
/// displacement, vorticity, a gradient, normals, coordinates, a force...).
bool namesOtherQuantity(const std::string& name);

/// The index of the Vectors default among `names` by name alone: `active`
/// (the input's active vectors) where it is an index into `names`, else
/// pickVelocityName's, else 0; -1 for no names.
int pickDefaultVectors(const std::vector<std::string>& names, int active);

/// A 3-component array offered as Vectors, and whether its scale passes the
/// time line's units check (bp::resolveTimeLine warns of none).
struct VectorsCandidate
{
  std::string name;
  bool unitsFit = true;
};

/**
 * The Vectors default given `chosen`, the index pickDefaultVectors gave:
 * `chosen` itself where its units fit, or where no other's do; else, of the
 * candidates whose units fit, the one named most like a velocity (a
 * velocity's own name, then one holding it, then a name that says nothing;
 * never one of another quantity: an acceleration that fits is no velocity),
 * the first among equals. `chosen` where it is not an index into `candidates`.
 */
int preferFittingUnits(const std::vector<VectorsCandidate>& candidates, int chosen);

/**
 * Why preferFittingUnits took another array than `mismatched` (the input's
 * active vectors where `mismatchedActive`), whose units check warned
 * `warning` (one of bp::resolveTimeLine's): its findings, up to where the
 * warning turns to what the units may be and what to do.
 */
std::string fittingUnitsReason(
  const std::string& mismatched, bool mismatchedActive, const std::string& warning);

} // namespace bp

#endif

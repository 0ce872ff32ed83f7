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
 * own active vectors first, then a name that says velocity, then the first.
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

} // namespace bp

#endif

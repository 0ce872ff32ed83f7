// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Walls.h
 * @brief The field's own boundary as a wall (Boundary Stick, Slip or Bounce;
 * engine specification 2.8, "Walls"): the rules for one particle, which both
 * engines follow (the GPU engine in Shaders/bp_common.glsl).
 *
 * The walls are the sides of the domain box (Engine::domainOf: the whole
 * field's bounds, also under MPI) along its axes of more than one point; a
 * flat axis has none, nor has a periodic one (Periodic.h: Domain::bounded). A particle's step is
 * walled twice:
 *
 *  - after advection (wallAfterAdvection), from its position before the
 *    step: Stick puts a particle that crossed a side where its step's
 *    segment first meets it, Slip projects it onto the side (the normal
 *    component of its step beyond the wall removed), Bounce mirrors what
 *    lies beyond the side back into the box, scaled by the restitution;
 *  - after restoration (clampToBox): a particle the springs pushed out is
 *    put on the side (restoration never takes a particle through a wall).
 *
 * Stick holds a particle without new state: one that lies on a side
 * (onWall, compared exactly, as placed by either rule) is not advected and
 * goes back to its held position after restoration. A heavy particle's
 * velocity takes the same rule (wallVelocity): Stick zero, Slip without its
 * outward normal component, Bounce with that component reversed and scaled.
 */
#ifndef BoundParticles_Walls_h
#define BoundParticles_Walls_h

#include "BoundParticlesChoices.h"
#include "VectorField.h"

namespace bp
{

/// Whether Boundary `b` is a wall (Stick, Slip, Bounce).
inline bool isWall(Boundary b)
{
  return b == Boundary::Stick || b == Boundary::Slip || b == Boundary::Bounce;
}

/// The sides a particle met: bit 2a for the lower side of axis a, bit
/// 2a + 1 for the upper; 0 for none.
using WallHits = unsigned;
/// With the sides (and the faces of the cells outside the flow, MaskWalls.h),
/// in what the GPU engine's advect pass hands its slip share pass: the
/// particle went back to before the step, no face found.
constexpr WallHits WallMaskedCell = 1u << 6;

/// Whether p lies on a side of `box` (p[a] equal to its lower or upper bound
/// along an axis a that is not flat): a particle that Stick holds.
bool onWall(const Domain& box, const float p[3]);

/// Puts p on the sides of `box` it lies beyond (along axes that are not
/// flat); returns those sides. NaN stays NaN, and is beyond no side.
WallHits clampToBox(const Domain& box, float p[3]);

/**
 * The wall after advection: p, advected from `before`, goes back into `box`
 * by Boundary `b` (Stick, Slip or Bounce; anything else leaves p alone),
 * with `restitution` e in [0, 1] for Bounce. Returns the sides it met.
 *  - Stick: from a `before` inside the box, the first point where the
 *    segment before -> p meets a side (on it exactly); from one outside
 *    (an element released across a side), p clamped into the box.
 *  - Slip: p clamped into the box (projected onto the side).
 *  - Bounce: along each axis, the distance d beyond a side becomes e d
 *    inside it; then clamped (a reflection past the opposite side).
 */
WallHits wallAfterAdvection(
  Boundary b, float restitution, const Domain& box, const float before[3], float p[3]);

/**
 * A heavy particle's velocity v at the sides `hits` it met, by Boundary `b`:
 * Stick makes it 0 (whatever the sides); Slip removes the component along
 * each side's outward normal where it points out of the box; Bounce makes
 * that component -e times itself. A component pointing into the box stays.
 */
void wallVelocity(Boundary b, float restitution, WallHits hits, float v[3]);

} // namespace bp

#endif

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MaskWalls.h
 * @brief The walls of the cells outside the flow (a resampled mesh's mask,
 * vtkValidPointMask 0, NaN vectors: VectorField::outsideCellAt) under
 * Boundary Stick, Slip or Bounce (engine specification 2.8, "Walls"): the
 * rules for one particle, which both engines follow (the GPU engine in
 * Shaders/bp_common.glsl: bpWallOnOutsideCells, bpFirstOutsideFace,
 * bpOnOutsideFace).
 *
 * The wall is made of the faces between a cell inside the flow and a cell
 * outside it, each normal to a grid axis. A particle whose step before -> p
 * ends in a cell outside the flow meets the first such face the segment
 * crosses (a walk through the grid's cells, firstOutsideFace), and the
 * sides' rule acts on that face's plane, the particle kept `offset`
 * (surfaceWallOffset) on the inside of it: Stick puts it at the contact,
 * Slip sets its coordinate along the face's axis to the face's, Bounce
 * reflects the distance beyond the face scaled by the restitution (at least
 * the offset). The contact it keeps (where Stick puts the particle, and
 * where the next walk starts) lies in the cell the face leaves, at least the
 * offset from that cell's other faces along bounded axes (a rounding of the
 * segment's point may not take it into a neighbour). Where the result still lies in a cell outside
 * the flow (an inward staircase corner), the rule acts again on the face the move from the last
 * contact crosses, at most MaxMaskWallRules times in all; then the particle is put at its last
 * contact.
 */
#ifndef BoundParticles_MaskWalls_h
#define BoundParticles_MaskWalls_h

#include "Walls.h"

namespace bp
{

/// The most faces a walk crosses, and the most times the rule acts in a step.
constexpr int MaxMaskWallCrossings = 8;
constexpr int MaxMaskWallRules = 4;

/// A face between a cell inside the flow and one outside it that a segment met.
struct MaskFace
{
  int axis = -1;       ///< the face's normal axis
  float plane = 0.0f;  ///< its coordinate along that axis
  float toward = 0.0f; ///< +1 or -1: its normal toward the segment's start, along the axis
  float point[3] = {}; ///< where the segment meets it (on the plane exactly)
  int cell[3] = {};    ///< the cell inside the flow it leaves (VectorField::cellOf)
};

/**
 * The first face the segment from -> to crosses into a cell outside the
 * flow (at `weight`, VectorField::outsideCellAt): from the cell of `from`,
 * cell by cell, across the face along whichever axis the segment reaches
 * first (the lower axis on a tie), toward the cell of `to`. False where the
 * cell of `from` is itself outside, or no such face is met within
 * MaxMaskWallCrossings faces (a step across a periodic seam, or many cells
 * long).
 */
bool firstOutsideFace(
  const VectorField& field, float weight, const float from[3], const float to[3], MaskFace& face);

/**
 * The wall after advection at the cells outside the flow: p (already in
 * the box), advected from `before`, goes back inside the flow by Boundary
 * `b` (module comment). Returns the faces met as the sides' bits (bit 2a
 * where the cell outside lies below along a, 2a + 1 above), so that
 * wallVelocity takes a heavy particle's velocity by the same rule; 0 where p
 * is not in a cell outside the flow. Where no face is found p goes back to
 * `before`, and WallMaskedCell is returned. `first` gets the first face met.
 */
WallHits wallOnOutsideCells(Boundary b, float restitution, float offset, const VectorField& field,
  float weight, const float before[3], float p[3], MaskFace& first);

/// Whether p, in a cell inside the flow, lies within 2 offsets of a face of
/// its cell whose neighbour across it is outside the flow: Stick holds it.
bool onOutsideFace(const VectorField& field, float weight, float offset, const float p[3]);

} // namespace bp

#endif

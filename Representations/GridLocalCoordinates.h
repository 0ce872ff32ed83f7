// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GridLocalCoordinates.h
 * @brief The GPU draw in the engine's grid-local coordinates: the camera
 * matrices and the clipping planes moved to them, in double.
 *
 * The engine's positions are relative to the field's first point (the draw
 * settings' offset). Adding the offset to float positions would lose the
 * precision the elements need far from the world origin (floats are 0.5
 * apart at 6.4e6, Earth-centred coordinates, and 8 apart at 1e8), so the
 * offset goes into what the shader is given instead: the model-to-world,
 * model-to-view and model-to-display matrices (composed in double, as VTK
 * composes its VBO shift and scale) and the clipping planes' equations.
 */
#ifndef BoundParticles_GridLocalCoordinates_h
#define BoundParticles_GridLocalCoordinates_h

#include <array>

class vtkAbstractMapper3D;
class vtkActor;
class vtkMatrix4x4;
class vtkRenderer;
class vtkShaderProgram;

namespace bpvtk
{

/**
 * Sets MCWCMatrix, MCDCMatrix and MCVCMatrix (where used) of `program` for
 * model coordinates that are grid-local with origin `offset`, over the
 * values VTK set for model coordinates that are world ones. `toWorld` and
 * `scratch` hold the products (kept by the caller, not allocated per draw).
 * Nothing to do for a zero offset.
 */
void setGridLocalCamera(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* act,
  const std::array<double, 3>& offset, vtkMatrix4x4* toWorld, vtkMatrix4x4* scratch);

/**
 * Sets clipPlanes of `program` to `mapper`'s clipping planes (at most 6),
 * which VTK gives in world (data) coordinates, moved to grid-local ones: a
 * plane n.x + c = 0 over x = local + offset is n.local + (c + n.offset) = 0.
 */
void setGridLocalClippingPlanes(vtkShaderProgram* program, vtkAbstractMapper3D* mapper,
  vtkActor* act, const std::array<double, 3>& offset);

} // namespace bpvtk

#endif

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkOpenGLKeptCellsMapper
 * @brief A polydata mapper that uploads the index buffers again only when
 * the cells change, not whenever the points do.
 *
 * VTK 9.2's vtkOpenGLPolyDataMapper::BuildIBO compares a state that still
 * holds the polydata's modification time, so every new set of points also
 * rebuilds the index buffers from the cells: 45 ms a frame at 917,504
 * triangles on this machine, for cells that have not changed. The tracer
 * keeps its cell arrays from frame to frame, so the Bound Particles display
 * draws the CPU output with this mapper, which keeps the index buffers while
 * the cell arrays, the representation and the edge visibility are the ones
 * they were built for.
 *
 * Its bounds are those of the points, from the ranges the tracer leaves
 * cached on the points' array (VTK 9.2's polydata mapper marks every point
 * its cells use, a pass over all cells per frame; every particle of the
 * tracer's output belongs to its element's cells or lies within its element,
 * so the points' bounds are the bounds that matter for the camera).
 */
#ifndef vtkOpenGLKeptCellsMapper_h
#define vtkOpenGLKeptCellsMapper_h

#include "BoundParticlesRepresentationsModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkStateStorage.h" // for vtkStateStorage

class BOUNDPARTICLESREPRESENTATIONS_EXPORT vtkOpenGLKeptCellsMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOpenGLKeptCellsMapper* New();
  vtkTypeMacro(vtkOpenGLKeptCellsMapper, vtkOpenGLPolyDataMapper);
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkOpenGLKeptCellsMapper() = default;
  ~vtkOpenGLKeptCellsMapper() override = default;

  void BuildIBO(vtkRenderer* renderer, vtkActor* actor, vtkPolyData* poly) override;
  void ComputeBounds() override;

private:
  vtkOpenGLKeptCellsMapper(const vtkOpenGLKeptCellsMapper&) = delete;
  void operator=(const vtkOpenGLKeptCellsMapper&) = delete;

  vtkStateStorage CellsState; ///< what the index buffers were built from
};

#endif

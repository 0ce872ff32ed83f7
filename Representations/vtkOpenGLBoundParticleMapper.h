// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkOpenGLBoundParticleMapper
 * @brief Runs the GPU engine in the render window's context and draws its
 * state with vertex texture fetch.
 *
 * The mapper owns the GPU state (a bp::GpuEngine: particle state in RGBA32F
 * ping-pong textures, the field's time steps in 3D textures). Before it draws
 * it runs the engine calls that vtkBoundParticleTracer recorded into its work
 * queue, saving and restoring the GL state VTK keeps. It then draws the
 * template's triangles once per element (glDrawElementsInstanced): VTK's own
 * polydata shaders, so lights, Diffuse, Specular and the rest look as they do
 * in the Surface representation, with the vertex position, normal and colour
 * scalar fetched from the engine's textures. Nothing per particle is uploaded.
 *
 * A super set's links are drawn as the CPU output has them, a line from
 * particle i of an element to particle i of each lattice neighbour: a second
 * instanced draw with VTK's line shader, one instance per link, whose vertices
 * fetch both ends from the same textures. The pairs of linked elements are a
 * texture made once per configuration. An element placed outside the release
 * window is not drawn, nor are its links: their vertices are moved outside
 * the clip volume, so that depth peeling never sees their fragments.
 *
 * Colouring by a scalar goes through the mapper's lookup table (its range
 * and colours, sampled into a table texture): any array of the tracer's
 * output that has a colour source in Core/Output/OutputArrays.h (every one but
 * Normals; Velocity, Orientation, ElementSpin and ElementStretch by
 * magnitude or a component). ElementStretch and ElementFTLE are fitted in
 * the vertex shader from the element's particles against the template's
 * rest offsets and Aqq^+, uploaded once per configuration (DrawDeformation.h).
 *
 * Motion trails (Parameters::trailLength) are drawn from the engine's ring of
 * past state textures: for each slot recorded before the time shown, newest
 * first, the element draw again with the slot's positions, normals computed
 * in the vertex shader from them (as the CPU output computes a pose's), the
 * colour of the element now (Age: the pose's age), and elements whose
 * generation in the slot is not their own clipped, as hidden ones are. The
 * poses fade with age, by the colour map's opacity where it maps opacity,
 * otherwise by 1 - age / (span + interval); with trails the actor is always
 * drawn in the translucent pass, so they composite with depth peeling.
 *
 * The model coordinates of the draw are the engine's grid-local ones: the
 * world position of their origin (the field's first point) is added only in
 * the camera matrices, computed in double, so the elements are drawn as
 * precisely a million or a hundred million units from the world origin as
 * at it (float world positions would be 0.5 apart at 6.4e6, Earth-centred
 * coordinates, and 8 apart at 1e8). Clipping planes and the Layer colour
 * range are moved to grid-local coordinates the same way.
 *
 * A replay from the start of a long trace runs in one render and can take
 * seconds: while it runs, the mapper reports its progress (0 to 1 over the
 * calls, every 0.1 s once it has lasted that long) through its container
 * algorithm, the display, whose progress ParaView shows (before ParaView 6.1,
 * whose GUI processes its events on every report and hung inside the
 * render), and stops between two steps when the container (or the mapper) is
 * asked to abort. The engine then stands on a step boundary, which the
 * mapper records in the queue's report and the tracer's cursor takes at its
 * next decision, so the next update goes on from there (bp::ReplayProgress,
 * bp::RendererReportWriter::stoppedAt, bp::WorkQueue::settleCursor).
 *
 * The mapper's parts, one role a file, are listed at the top of its .cxx.
 *
 * @sa vtkBoundParticleRepresentation, bp::GpuEngine, bp::WorkQueue
 */
#ifndef vtkOpenGLBoundParticleMapper_h
#define vtkOpenGLBoundParticleMapper_h

#include "BoundParticlesRepresentationsModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"

#include <chrono> // for std::chrono::steady_clock
#include <memory> // for std::unique_ptr, std::shared_ptr
#include <string> // for std::string
#include <vector> // for std::vector

#ifndef __VTK_WRAP__
namespace bp
{
class WorkQueue;
class RendererReportWriter;
struct EngineCall;
struct EngineState;
}
#endif
class vtkOpenGLRenderWindow;
class vtkRenderWindow;

class BOUNDPARTICLESREPRESENTATIONS_EXPORT vtkOpenGLBoundParticleMapper
  : public vtkOpenGLPolyDataMapper
{
public:
  static vtkOpenGLBoundParticleMapper* New();
  vtkTypeMacro(vtkOpenGLBoundParticleMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

#ifndef __VTK_WRAP__
  /// The queue whose calls this mapper runs and whose state it draws, and
  /// its report's writer, lent by the display that owns both (null with a
  /// null queue); the display takes them back before it goes.
  void SetWorkQueue(
    const std::shared_ptr<const bp::WorkQueue>& queue, bp::RendererReportWriter* writer);
#endif

#ifndef __VTK_WRAP__
  /**
   * The GPU engine's state at its committed step boundary, read back for the
   * tracer's State output (the queue's state reader,
   * bp::RendererReportWriter::setStateReader, set by the display): in
   * `window`'s context (made current, and the one current before put back),
   * the calls still queued run first as a render runs them, then the state
   * is read (save()'s copy while a short step is shown). What is drawn does
   * not change. Empty on success, otherwise why not: the view has not drawn
   * yet, the run was stopped, the engine failed or holds no trace.
   */
  std::string ReadEngineState(vtkRenderWindow* window, bp::EngineState& state);
#endif

  /**
   * Colours by the named point array of the tracer's output (null or "" for
   * the solid colour); `component` -1 is the magnitude of a vector array.
   * Returns false, colouring solid, for an array the table gives no colour
   * source.
   */
  bool SetColorArray(const char* name, int component);

  /// What went wrong in the last render; empty when the GPU engine ran.
  const std::string& GetLastError() const;

  /// The field's bounds: elements never leave them for long.
  using vtkOpenGLPolyDataMapper::GetBounds;
  double* GetBounds() override;

  /**
   * Whether the elements are drawn translucent, so that the actor is drawn
   * in the translucent pass with depth peeling: with trails (they fade), and
   * where the colour map makes them so (ParaView's opacity mapping). VTK
   * decides from the input's scalars, and this mapper's input, the template,
   * has none: the decision is the lookup table's, as VTK makes it for the
   * CPU output's scalars.
   */
  bool HasTranslucentPolygonalGeometry() override;

  /**
   * The age of the oldest trail pose the display expects (0: no trails), from
   * the range of Age on its input: VTK decides whether the actor is
   * translucent before the mapper runs the configuration queued for the
   * frame, so a frame that switches trails on must know from its input.
   */
  void SetExpectedTrailSpan(double span);

  /**
   * Whether this ParaView lets the GPU run report its progress (not 6.1 and
   * later, whose GUI processes events on a report).
   */
  static bool ReportsReplayProgress();

  /**
   * The display's update reported progress 0 but not its end (its progress
   * shifted and scaled to 0, SetProgressShiftScale): the next render's run
   * reports the rest from 0 to 1, so the progress an observer of the display
   * sees rises once over update and run. The render puts the shift and
   * scale back, and reports 1 at the end of a run too short to report.
   */
  void OweProgressEnd()
  {
    this->ProgressOwed = true;
  }

  /// Runs the queued engine work (reporting progress where ParaView allows,
  /// and taking an abort request, while a long one runs), then draws.
  void Render(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

  /// For tests and benchmarks: a cap below GL_MAX_TEXTURE_SIZE.
  void SetTextureSizeLimit(int texels);

protected:
  vtkOpenGLBoundParticleMapper();
  ~vtkOpenGLBoundParticleMapper() override;

  bool ProgressOwed = false; ///< OweProgressEnd(): the render's run ends the progress

  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  /**
   * The engine's positions are grid-local (relative to the field's first
   * point, the draw settings' offset): the model-to-view and model-to-display
   * matrices get the translation by the offset composed in, in double, as
   * VTK composes its VBO shift and scale. Float positions then keep the
   * precision the field's own extent needs wherever the field lies.
   */
  void SetCameraShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;

private:
  /// Whether the colour map (ParaView's opacity mapping) makes anything translucent.
  bool ColorMapIsTranslucent();
  /// Whether the user asked to stop the running replay; the request is taken.
  bool TakeAbortRequest();
#ifndef __VTK_WRAP__
  /// Applies the queue's calls to the engine in `window`'s current context,
  /// with progress and abort; a failure makes the display draw the CPU result.
  /// True when the user stopped the run before its end.
  bool RunCalls(const std::vector<bp::EngineCall>& calls, vtkOpenGLRenderWindow* window);
  /// After a configure that succeeded: the template as this mapper's input,
  /// and the draw's tables for the new system (DrawTables.h).
  void ConfigureDraw(const bp::EngineCall& configure);
  /// After a run of `calls` that took `took`: a long one that was not
  /// stopped gives the queue the engine's rate (RendererReport::particleStepsPerSecond).
  void MeasureRate(const std::vector<bp::EngineCall>& calls,
    std::chrono::steady_clock::duration took, bool stopped);
#endif
  /// A failure of the queued work: an error, the last error, and the queue's
  /// failure, so that the display draws the CPU result from the next update on.
  void Fail(const std::string& message);
  /// Before the draw: the next field time step's share of uploading, and the
  /// field samples a colouring by Velocity or Vorticity reads.
  void PrepareEngineTextures();
  /// The link and corner tables, uploaded once per configuration.
  void UploadTables(vtkOpenGLRenderWindow* window);
  /// The cells of VTK primitive `primitive`: the elements and their trail
  /// poses, and on the line primitive the super set's links.
  void DrawPrimitive(int primitive, vtkRenderer* ren, vtkActor* act);
  /// The element draw, once for the elements and once per trail pose.
  void DrawElementCells(vtkOpenGLHelper& helper, unsigned int mode, vtkOpenGLRenderWindow* window);

  vtkOpenGLBoundParticleMapper(const vtkOpenGLBoundParticleMapper&) = delete;
  void operator=(const vtkOpenGLBoundParticleMapper&) = delete;

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif

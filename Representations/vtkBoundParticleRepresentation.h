// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticleRepresentation
 * @brief The "Bound Particles" display of a Bound Particle Tracer.
 *
 * It asks its input for GPU work: on its own update request it sets
 * vtkBoundParticleTracer::GPU_WORK_QUEUE() to its work queue's id, and takes
 * it back to 0 once the update is done, so every other consumer of the same
 * output gets the CPU result. When nothing else in its view draws from the
 * data, it takes the request back only when the view renders: its own
 * decorations (the axes grid, the selection), which update in between, then
 * get the GPU output's bounds and ranges instead of a CPU step per frame.
 *
 * With the tracer's Engine set to GPU the input then carries no particles:
 * two points spanning the field, each array with its expected range over
 * them (for the camera, the axes grid and the colour map), and the queue's
 * id. The vtkOpenGLBoundParticleMapper runs the recorded work and draws the
 * GPU state. Otherwise (Engine CPU, or after a GPU failure) the display
 * draws the CPU polydata with a polydata mapper that keeps its index buffers
 * while the cells stay (vtkOpenGLKeptCellsMapper), coloured the same way;
 * trails that fade get colours made here (TrailFade.h). The tracer's State
 * output reads the GPU engine's state back through the queue: the display
 * lends it the mapper's read-back in its view's render window
 * (vtkOpenGLBoundParticleMapper::ReadEngineState). Once the tracer has
 * answered a request with its CPU result (Engine CPU, or Automatic on a
 * software renderer), the display asks as every other consumer does until
 * the pipeline or the renderer changes, so that the tracer runs once a frame
 * and not once for it and again for its decorations.
 *
 * The display properties (colour, opacity, lighting, the colour array and its
 * lookup table, transforms) are the Surface representation's, shared through
 * the GeometryRepresentation extension in the plugin's XML.
 */
#ifndef vtkBoundParticleRepresentation_h
#define vtkBoundParticleRepresentation_h

#include "BoundParticlesRepresentationsModule.h" // for export macro
#include "vtkPVDataRepresentation.h"

#include <memory> // for std::unique_ptr

class vtkPolyData;
class vtkScalarsToColors;

class BOUNDPARTICLESREPRESENTATIONS_EXPORT vtkBoundParticleRepresentation
  : public vtkPVDataRepresentation
{
public:
  static vtkBoundParticleRepresentation* New();
  vtkTypeMacro(vtkBoundParticleRepresentation, vtkPVDataRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  int ProcessViewRequest(vtkInformationRequestKey* request_type, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

  void SetVisibility(bool value) override;

  ///@{
  /// Forwarded to the actor's property (shared with the Surface representation).
  void SetColor(double r, double g, double b);
  void SetDiffuseColor(double r, double g, double b);
  void SetAmbientColor(double r, double g, double b);
  void SetSpecularColor(double r, double g, double b);
  void SetOpacity(double value);
  void SetAmbient(double value);
  void SetDiffuse(double value);
  void SetSpecular(double value);
  void SetSpecularPower(double value);
  void SetInterpolation(int value);
  void SetPointSize(double value);
  void SetLineWidth(double value);
  ///@}

  ///@{
  /// Forwarded to the actor.
  void SetPosition(double x, double y, double z);
  void SetScale(double x, double y, double z);
  void SetOrientation(double x, double y, double z);
  void SetOrigin(double x, double y, double z);
  void SetUserTransform(const double matrix[16]);
  void SetPickable(int value);
  ///@}

  ///@{
  /// Colouring: the array (ColorArrayName) and the lookup table.
  using Superclass::SetInputArrayToProcess;
  void SetInputArrayToProcess(
    int idx, int port, int connection, int fieldAssociation, const char* name) override;
  void SetLookupTable(vtkScalarsToColors* lut);
  void SetMapScalars(int value);
  void SetInterpolateScalarsBeforeMapping(int value);
  ///@}

  ///@{
  /// For tests: caps the GPU engine's textures below GL_MAX_TEXTURE_SIZE
  /// (0, the default: no cap).
  void SetGpuTextureSizeLimit(int texels);
  int GetGpuTextureSizeLimit() const;
  ///@}

  /// With the GPU engine and an unsteady field: read the next time step
  /// ahead of need and upload it a slab of z layers per frame (on, the
  /// default), or upload each time step whole in the frame that first needs
  /// it (off).
  void SetStreamTimeSteps(bool stream);
  bool GetStreamTimeSteps() const;

protected:
  vtkBoundParticleRepresentation();
  ~vtkBoundParticleRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  bool AddToView(vtkView* view) override;
  bool RemoveFromView(vtkView* view) override;

private:
  /// Whether another visible display in this view draws from this data (a
  /// downstream filter's, say): then the request is not held.
  bool ViewHasOtherConsumers();
  /// Sets the GPU request on the input back to 0 if it was held.
  void ReleaseGpuRequest();

  vtkBoundParticleRepresentation(const vtkBoundParticleRepresentation&) = delete;
  void operator=(const vtkBoundParticleRepresentation&) = delete;

  /// The colour array and lookup table to both mappers; a warning when the
  /// GPU draw cannot colour by the array.
  void UpdateColoring();
  /// Whether the CPU output `piece` has trails that this display fades
  /// itself (no colour map mapping opacity); then makes their colours.
  bool FadesTrails(vtkPolyData* piece);

  struct vtkInternals;
  std::unique_ptr<vtkInternals> Internals;
};

#endif

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class vtkBoundParticleTracer
 * @brief Traces bound particles (small shapes of particles tied by springs)
 * through a steady or unsteady vector field on any grid or mesh (meshes and
 * composite data resampled onto a uniform grid first).
 *
 * Each of NumberOfElements elements is an instance of ElementShape, scaled to
 * ElementSize, placed in the emitter box, advected with the flow and restored
 * to its shape every step (docs/engine-specification.md; the maths lives in
 * the VTK-free core, Core/Engine/Engine.h). The output is a vtkPolyData of all
 * particles: the shape's triangles per element (its springs as lines where it
 * has no triangles, a super set's links as lines too), or vertices for one-particle
 * elements, with the point arrays of the table in Core/Output/OutputArrays.cpp
 * (bp::outputArrays(); OutputArrays selects them).
 *
 * Pipeline time drives the simulation (Core/Plan/TracePlan.h decides each
 * request). A request for a time at or after where the trace stands steps
 * forward from there; an earlier time, or any change to the filter or its
 * input, replays from the start. Steps end on the grid start + k*dt and on
 * the data's time steps, so a replay and an incremental run pass through the
 * same states bit for bit. An unsteady input is requested one time step per
 * pass and sampled linearly between the two steps that bracket each moment;
 * at most three are held (the third read ahead for a GPU display). A steady
 * input gets NumberOfTimeSteps time values over [0, Duration] so that
 * animation plays it.
 *
 * In parallel (pvbatch, pvserver under MPI) each process asks its input for
 * one block of the grid with ghost layers, owns the elements whose centres lie
 * in its block and outputs those; in each step, after resets and before
 * advection, elements move to the
 * process that owns their new centre through the global
 * vtkMultiProcessController (Core/Distributed/Partition.h). Draws hash global element ids,
 * so the set of elements does not depend on the number of processes.
 */
#ifndef vtkBoundParticleTracer_h
#define vtkBoundParticleTracer_h

#include "BoundParticlesFiltersModule.h" // for export macro
#include "vtkBoundParticleSetGet.h"      // for vtkBPEnumMacro, vtkBPClampedSetMacro
#include "vtkNew.h"                      // for vtkNew
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

#include <memory> // for std::unique_ptr
#include <string> // for std::string
#include <vector> // for std::vector

class vtkBoundParticleSeedType;
class vtkBoundParticleTracerInternals; // the trace's state between passes
class vtkDataArraySelection;
class vtkInformationIntegerKey;
class vtkInformationIntegerRequestKey;
class vtkPolyData;
#ifndef __VTK_WRAP__
namespace bp
{
struct TraceSettings;
}
namespace bpvtk
{
struct FieldProbe;
struct TracerConfig;
struct TracerInputStep;
struct TracerPass;
struct TimeLineSettings;
class TracerTimeLine;
}
#endif

class BOUNDPARTICLESFILTERS_EXPORT vtkBoundParticleTracer : public vtkPolyDataAlgorithm
{
public:
  static vtkBoundParticleTracer* New();
  vtkTypeMacro(vtkBoundParticleTracer, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  // An enumerated property takes one of Core's enumerations
  // (Core/Choices/BoundParticlesChoices.h, where the panel's text of each
  // value is too): vtkBPEnumMacro (vtkBoundParticleSetGet.h) declares
  // SetX(int), which clamps a number that names no value with a warning,
  // GetXAsString(), the value's text, and the typed SetX(E) and GetX() for
  // C++. Python and the panel set them by the proxy XML's texts.

  ///@{
  /**
   * Points per axis of the uniform grid that any input other than an image or
   * a rectilinear grid (an unstructured, curvilinear or polygonal mesh, a
   * multiblock or partitioned collection) is resampled onto
   * (TracerResample.h). 0 on an axis (default 0 0 0) chooses it: about as
   * many points as the input has cells, cells close to cubes over the data's
   * bounds. An axis along which the data is flat always has one point. The
   * grid used is in the output's field data (ResampledDimensions,
   * ResampledSpacing). Images and rectilinear grids are traced as they are.
   */
  vtkSetVector3Macro(ResampleDimensions, int);
  vtkGetVector3Macro(ResampleDimensions, int);
  ///@}

  ///@{
  /// The shape of every element (thesis Fig. 3.4), unless an element template
  /// is connected: Point, Square, Strip4, Strip8 (default), Strip16, Cross,
  /// Paddlewheel, Tetrahedron or Fish (the 23-particle Tu-Terzopoulos
  /// skeleton). Strips act like short stream ribbons; paddlewheels and crosses
  /// turn with the local vorticity.
  // Declares SetElementShape, GetElementShape and GetElementShapeAsString.
  vtkBPEnumMacro(ElementShape, bp::BuiltinShape);
  ///@}

  ///@{
  /// The optional second input: any vtkPolyData as the element template,
  /// instead of ElementShape. Points become particles (centred and scaled to
  /// ElementSize), polygons and strips the drawn triangles, lines the springs
  /// (with the optional cell array "Stiffness" in [0, 1]); the optional point
  /// array "Pinned" (non-zero) pins particles in place.
  void SetTemplateConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(1, output); }

  /// The optional third input: any vtkDataSet whose points are the release
  /// centres, taken in order and cycling (release r = generation *
  /// NumberOfElements + element id is at point r modulo their count; at most
  /// 65,536), instead of the emitter box or the SeedType; with a
  /// vtkBoundParticleSurfaceSeeds Seed Type, its surface is where releases
  /// land instead. Minimum Release Speed does not apply.
  void SetSeedSourceConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(2, output); }
  void SetTemplateData(vtkPolyData* shape);
  ///@}

  ///@{
  /**
   * Where elements are released when no Seed Source is connected: nullptr
   * (the default) is the emitter box (EmitterCenter, EmitterSize); a
   * vtkBoundParticlePointCloudSeeds or vtkBoundParticleLineSeeds gives the
   * release centres, taken in order and cycling as a Seed Source's points.
   * The filter computes them itself, so they are the same on every process.
   * A connected Seed Source wins (with a warning when this is set too), and
   * with Linking the seeds are not used. A vtkBoundParticleSurfaceSeeds
   * (Surface, an inlet) needs the Seed Source instead: its points are drawn
   * over the Seed Source's surface by the flux through it at the trace's
   * start; with none connected nothing is released (an error says so).
   * Changing the seeds' parameters modifies the filter (GetMTime).
   */
  void SetSeedType(vtkBoundParticleSeedType* seeds);
  vtkBoundParticleSeedType* GetSeedType();
  ///@}

  /// The filter's time, or its Seed Type's or its output array selection's
  /// when that changed later.
  vtkMTimeType GetMTime() override;

  ///@{
  /// Springs of a template mesh that has no lines: its Edges (the element
  /// folds freely), plus across every shared edge the far corners (Edges +
  /// Diagonals, default), or All Pairs of particles (rigid).
  // Declares SetTemplateSprings, GetTemplateSprings and GetTemplateSpringsAsString.
  vtkBPEnumMacro(TemplateSprings, bp::MeshSprings);
  ///@}

  ///@{
  /// Number of elements. At least 1; elements times particles at most 2^26.
  vtkSetMacro(NumberOfElements, vtkIdType);
  vtkGetMacro(NumberOfElements, vtkIdType);
  ///@}

  ///@{
  /// Diameter of an element in world units; 0 (default) picks the larger of two
  /// cell lengths and 1/40 of the field's diagonal.
  vtkSetMacro(ElementSize, double);
  vtkGetMacro(ElementSize, double);
  ///@}

  ///@{
  /// The emitter box where elements are placed: centre and full size. A
  /// negative size on an axis (the default) spans the field's bounds there.
  vtkSetVector3Macro(EmitterCenter, double);
  vtkGetVector3Macro(EmitterCenter, double);
  vtkSetVector3Macro(EmitterSize, double);
  vtkGetVector3Macro(EmitterSize, double);
  ///@}

  ///@{
  /// Where releases land in the emitter box: Random (default), uniform draws
  /// (weighted by the Release Weights array, when one is chosen:
  /// SetInputArrayToProcess(1, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS,
  /// name)); Lattice, element e at point e of a regular lattice filling the
  /// box (flat on a 2D field), release after release, with one lifetime per
  /// generation. Not with Linking, whose super sets have their own lattice.
  /// LatticeSpacing (world units) sets the lattice; 0 (default) takes it from
  /// NumberOfElements, which is then the target (the lattice's size is the
  /// element count). LatticeSpacing is clamped to [0, VTK_DOUBLE_MAX]; a
  /// value outside warns.
  // Declares SetReleasePattern, GetReleasePattern and GetReleasePatternAsString.
  vtkBPEnumMacro(ReleasePattern, bp::ReleasePattern);
  vtkBPClampedSetMacro(LatticeSpacing, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(LatticeSpacing, double);
  ///@}

  ///@{
  /// How each element is turned when it is placed: Along Flow (default), its
  /// long (x) axis turned onto the flow at its release centre by the
  /// shortest turn from ElementRotation, so that strips read as short stream
  /// ribbons from the first frame; Random, a uniform random rotation; Fixed,
  /// every element turned by ElementRotation (degrees about X, then Y, then
  /// Z). On a flat field the turns are about its flat axis only.
  // Declares SetReleaseOrientation, GetReleaseOrientation and GetReleaseOrientationAsString.
  vtkBPEnumMacro(ReleaseOrientation, bp::Orientation);
  vtkSetVector3Macro(ElementRotation, double);
  vtkGetVector3Macro(ElementRotation, double);
  ///@}

  ///@{
  /// Lifetimes are drawn uniformly from [min, max] (time units). (0, 0), the
  /// default, picks half to all of the time the fastest flow takes to cross
  /// the field's longest side, within the animation's time range.
  vtkSetVector2Macro(LifetimeRange, double);
  vtkGetVector2Macro(LifetimeRange, double);
  ///@}

  ///@{
  /// Largest simulation step. In Cell Length units (StepSizeUnit's default;
  /// StepSize 0.5) a step moves the fastest particle of the field that many
  /// cells; in Time units it is the step in the data's time units. Must be
  /// positive.
  vtkSetMacro(StepSize, double);
  vtkGetMacro(StepSize, double);
  // Declares SetStepSizeUnit, GetStepSizeUnit and GetStepSizeUnitAsString.
  vtkBPEnumMacro(StepSizeUnit, bp::StepUnit);
  ///@}

  ///@{
  /// Memory (MiB) the trace's checkpoints may take: copies of the whole
  /// state on step boundaries, spread evenly over the trace, so that going
  /// back in time resumes from the latest one before the time asked for
  /// instead of replaying from the start (bit for bit the same). -1
  /// (default): half the trace's own size; 0 keeps none; at most half of what
  /// the process can allocate. The GPU engine keeps its checkpoints in GPU
  /// memory within the same budget. Clamped to [-1, 1e7], a value outside said.
  vtkBPClampedSetMacro(CheckpointMemory, double, -1.0, 1.0e7);
  vtkGetMacro(CheckpointMemory, double);
  ///@}

  ///@{
  /// A trace's state to go on from (File > Save Data on the State output,
  /// output 2, .vtp or .pvtp in Binary): times at or after the state's are
  /// traced from it, bit for bit as the trace that saved it; earlier ones
  /// from the start. Settings and input must be those it was saved with: a
  /// state that differs (a setting, template, grid or field, a file cut
  /// short, altered or ASCII) fails with a message naming the difference.
  /// Both engines resume; only the CPU engine saves. Empty (default): none.
  vtkSetStdStringFromCharMacro(InitialStateFile);
  vtkGetCharFromStdStringMacro(InitialStateFile);
  ///@}

  ///@{
  /// Advection integrator: Euler (thesis eq. 2.2, default), Runge-Kutta 2
  /// (midpoint) or Runge-Kutta 4 (classic).
  // Declares SetIntegrator, GetIntegrator and GetIntegratorAsString.
  vtkBPEnumMacro(Integrator, bp::Integrator);
  ///@}

  ///@{
  /// Shape restoration: Averaged Jacobi (thesis §3.5, default), Jacobi (sum
  /// of corrections times RelaxationFactor), Gauss-Seidel, or Shape Matching
  /// (best rigid fit, Müller et al. 2005, goals blended by
  /// ShapeMatchingStiffness); RestorationIterations iterations per step
  /// (default 1).
  // Declares SetRestoration, GetRestoration and GetRestorationAsString.
  vtkBPEnumMacro(Restoration, bp::Restoration);
  vtkSetMacro(RestorationIterations, int);
  vtkGetMacro(RestorationIterations, int);
  vtkSetMacro(RelaxationFactor, double);
  vtkGetMacro(RelaxationFactor, double);
  /// Clamped to [0.0, 1.0]; a value outside warns.
  vtkBPClampedSetMacro(ShapeMatchingStiffness, double, 0.0, 1.0);
  vtkGetMacro(ShapeMatchingStiffness, double);
  ///@}

  ///@{
  /// Shape matching's fit: Rigid (default) or Linear (Müller et al. 2005,
  /// §4.3: goals from beta * A + (1 - beta) * R, A the best affine fit, so
  /// elements may also shear and stretch). LinearShapeMatchingBeta is beta,
  /// clamped to [0.0, 1.0]; a value outside warns.
  // Declares SetShapeMatchingMode, GetShapeMatchingMode and GetShapeMatchingModeAsString.
  vtkBPEnumMacro(ShapeMatchingMode, bp::ShapeFit);
  vtkBPClampedSetMacro(LinearShapeMatchingBeta, double, 0.0, 1.0);
  vtkGetMacro(LinearShapeMatchingBeta, double);
  ///@}

  ///@{
  /// Super sets (thesis §5.1): Linking None (default), Chain, Ring, Sheet,
  /// Tube or Torus joins particle i of each element to particle i of its
  /// neighbours on a lattice (element order; W x H for the last three,
  /// W = LatticeWidth, 0 for near square) with springs of LinkStiffness, so
  /// all elements form one deformable structure. The structure is released
  /// from lattice sites filling the emitter box, with one orientation and one
  /// lifetime, and lives out its lifetime even where it leaves the field. The
  /// links are output as lines.
  // Declares SetLinking, GetLinking and GetLinkingAsString.
  vtkBPEnumMacro(Linking, bp::Linking);
  /// Clamped to [0, VTK_INT_MAX]; a value outside warns.
  vtkBPClampedSetMacro(LatticeWidth, int, 0, VTK_INT_MAX);
  vtkGetMacro(LatticeWidth, int);
  /// Clamped to [0.0, 1.0]; a value outside warns.
  vtkBPClampedSetMacro(LinkStiffness, double, 0.0, 1.0);
  vtkGetMacro(LinkStiffness, double);
  ///@}

  ///@{
  /// None (default): elements move with the flow. Centre: each element is
  /// moved back, after every step, so that its centre stays where it was
  /// released; it still turns and deforms with the local flow (a vorticity
  /// meter in place). Not with Linking (refused with a message).
  // Declares SetAnchor, GetAnchor and GetAnchorAsString.
  vtkBPEnumMacro(Anchor, bp::Anchor);
  ///@}

  ///@{
  /// Heavy particles (Core/Engine/Inertia.h). None (default): massless
  /// tracers. Maxey-Riley: each particle follows the reduced Maxey-Riley
  /// equation, dv/dt = (u - v) / ResponseTime + beta Du/Dt + (1 - beta)
  /// Gravity with beta = 3 / (1 + 2 DensityRatio), starting at the flow's
  /// velocity. The response time is in the data's time units (0 is
  /// massless), Gravity in length per time squared. Not with Anchor; both
  /// engines. Refused: ResponseTime < 0 or NaN, DensityRatio <= 0, NaN Gravity.
  // Declares SetInertia, GetInertia and GetInertiaAsString.
  vtkBPEnumMacro(Inertia, bp::Inertia);
  vtkSetMacro(ResponseTime, double);
  vtkGetMacro(ResponseTime, double);
  vtkSetMacro(DensityRatio, double);
  vtkGetMacro(DensityRatio, double);
  vtkSetVector3Macro(Gravity, double);
  vtkGetVector3Macro(Gravity, double);
  ///@}

  ///@{
  /// When an element is put back into the emitter besides running out of lifetime (Boundary
  /// Release Again; Terminate ends it, walls keep it in): Center Leaves (default, the thesis)
  /// the field, or Any Particle Leaves it, which keeps particles from sampling outside the data.
  // Declares SetResetWhen, GetResetWhen and GetResetWhenAsString.
  vtkBPEnumMacro(ResetWhen, bp::ResetWhen);
  ///@}

  ///@{
  /// What happens to an element that leaves the field (through a side of the
  /// grid, or into a cell outside the flow; Reset When says whether its
  /// centre or any particle counts): Release Again (default) puts it back
  /// into the emitter at once as its next generation; Terminate hides it
  /// until its lifetime runs out, and only then releases it again, so fewer
  /// elements are shown while some wait. Stick, Slip and Bounce make the
  /// field's boundary a wall that keeps every particle in: a particle that
  /// crosses a side of the grid is held where it met it (Stick), put on it
  /// and slides along it (Slip), or reflected back with the Restitution
  /// (Bounce), and the springs restore the rest of the element, so a strip
  /// lies down along a wall or tumbles off it; heavy particles (Inertia)
  /// lose their velocity, its normal component, or have that reversed times
  /// the Restitution. The faces of the cells outside the flow are such a
  /// wall too, with the same rules. Walled elements are never released for leaving. Not with
  /// Linking; walls not with Anchor = Centre. Both engines do the same.
  /// Output 3 (Interactions) has an event for each element that leaves and
  /// each particle's first contact with a wall (each bounce).
  // Declares SetBoundary, GetBoundary and GetBoundaryAsString.
  vtkBPEnumMacro(Boundary, bp::Boundary);
  ///@}

  ///@{
  /// Bounce's coefficient of restitution, 0 to 1 (default 1, a mirror): a
  /// step beyond a wall comes back this share of the way, a heavy particle
  /// leaves with this share of its normal velocity. 0 is Slip. Used by
  /// Boundary = Bounce only; outside [0, 1] (or NaN) is refused.
  vtkSetMacro(Restitution, double);
  vtkGetMacro(Restitution, double);
  ///@}

  ///@{
  /// The optional fourth input, Surfaces: any data set whose surface (a
  /// volume's boundary; in a 2D field lines, across the plane) acts on the
  /// elements that cross it: a Gate lets them through, an Outlet ends them
  /// as Terminate does, a Wall acts as Boundary does at the sides (Stick,
  /// Slip and Bounce per particle); output 3 records each event.
  /// SurfaceInteraction is what every cell does (Gate, default; Outlet;
  /// Wall) unless SurfaceInteractionArray names a cell array of the Surfaces
  /// saying it per cell (0, 1, 2; "None", the default: none). Not with
  /// Linking or Anchor = Centre. A GPU display runs the CPU engine past 4096 Outlet/Wall triangles.
  void SetSurfacesConnection(vtkAlgorithmOutput* output) { this->SetInputConnection(3, output); }
  // Declares SetSurfaceInteraction, GetSurfaceInteraction and GetSurfaceInteractionAsString.
  vtkBPEnumMacro(SurfaceInteraction, bp::SurfaceInteraction);
  vtkSetStdStringFromCharMacro(SurfaceInteractionArray);
  vtkGetCharFromStdStringMacro(SurfaceInteractionArray);
  ///@}

  ///@{
  /// Periodic sides: one flag per axis x, y, z (default 0 0 0, none). Along
  /// a periodic axis the grid (the image, the rectilinear grid, or the grid
  /// an unstructured input is resampled onto) repeats with a period of its
  /// extent, its last plane standing for its first: the field is sampled
  /// across the seam, and an element whose centre leaves through one side
  /// moves whole, by one period, to the other (its shape untouched; never
  /// released for leaving there). Boundary applies to the other axes' sides
  /// only. Refused along an axis of one grid point and with Linking. Trails
  /// break at the jump (a pose over half a period away is left out). Under MPI the
  /// processes split the other axes into blocks (where they cannot, every
  /// axis periodic, all axes, each process then holding the whole field);
  /// every process holds the whole of a periodic axis and hands an element
  /// that crosses the seam to the owner of its new centre: the same trace on
  /// any number of processes. Both engines do the same.
  vtkSetVector3Macro(Periodic, int);
  vtkGetVector3Macro(Periodic, int);
  ///@}

  ///@{
  /// Releases avoid stagnant flow: an element whose centre moves slower than
  /// this fraction of the field's top speed (at the start) over its first
  /// step is released again. 0 keeps every release.
  vtkSetMacro(MinimumReleaseSpeed, double);
  vtkGetMacro(MinimumReleaseSpeed, double);
  ///@}

  ///@{
  /// The release window: with ReleaseWindow on, elements are released only
  /// at steps that start at a time in [ReleaseStart, ReleaseStop]; one due
  /// outside it waits hidden (not drawn, no cells in the output) until then,
  /// so a burst can be released (ReleaseStart = ReleaseStop) and followed.
  vtkSetMacro(ReleaseWindow, int);
  vtkGetMacro(ReleaseWindow, int);
  vtkBooleanMacro(ReleaseWindow, int);
  vtkSetMacro(ReleaseStart, double);
  vtkGetMacro(ReleaseStart, double);
  vtkSetMacro(ReleaseStop, double);
  vtkGetMacro(ReleaseStop, double);
  ///@}

  ///@{
  /// Which way the trace runs (Core/Plan/TimeDirection.h): Forward (default),
  /// or Backward: elements are released at the latest time of the release
  /// window (the data's last time without one) and advected toward earlier
  /// times through the reversed flow, so the trace shown at time t holds
  /// elements traced back to t; the FTLE then marks attracting structures.
  /// The offered time steps stay the data's. Massless elements only
  /// (Inertia None), and not in situ.
  // Declares SetTimeDirection, GetTimeDirection and GetTimeDirectionAsString.
  vtkBPEnumMacro(TimeDirection, bp::TimeDirection);
  ///@}

  ///@{
  /// Motion trails: with Trails on, each element also shows its last TrailLength poses, one every
  /// TrailSpacing steps, as extra cells whose points carry their pose's Age (time before the one
  /// shown) and their element's values of the other arrays; a released element starts anew, and
  /// a Periodic jump breaks the trail (its poses over half a period away are left out).
  vtkSetMacro(Trails, int);
  vtkGetMacro(Trails, int);
  vtkBooleanMacro(Trails, int);
  vtkSetMacro(TrailLength, int);
  vtkGetMacro(TrailLength, int);
  vtkSetMacro(TrailSpacing, int);
  vtkGetMacro(TrailSpacing, int);
  ///@}

  /// Seed of the counter-based random numbers: the same seed, the same trace.
  vtkSetMacro(Seed, int);
  vtkGetMacro(Seed, int);

  ///@{
  /// For a steady input: the time range [0, Duration] and the number of time
  /// values the filter offers to the animation. Duration 0 (the default) is
  /// automatic: as long as the fastest flow takes to cross the field five
  /// times, but at most 10 steps per offered time (bp::resolveTimeLine).
  vtkSetMacro(Duration, double);
  vtkGetMacro(Duration, double);
  vtkSetMacro(NumberOfTimeSteps, int);
  vtkGetMacro(NumberOfTimeSteps, int);
  ///@}

  ///@{
  /// For an unsteady input: the frames offered per input time step (the
  /// input's times, and evenly between them). 0 (the default) is automatic:
  /// as many as keep a frame within 10 steps.
  vtkSetMacro(FramesPerInputStep, int);
  vtkGetMacro(FramesPerInputStep, int);
  ///@}

  ///@{
  /// The axis (0 X, 1 Y, 2 Z; default 2) for the Layer array (an element's
  /// initial centre along it) and the Radius array (distance of that centre
  /// from the axis line through the field's centre). Clamped to [0, 2]; a
  /// value outside warns.
  vtkBPClampedSetMacro(ColoringAxis, int, 0, 2);
  vtkGetMacro(ColoringAxis, int);
  ///@}

  ///@{
  /**
   * Which point arrays the CPU output carries, by name (the rows of the table
   * in Core/Output/OutputArrays.cpp; which are on by default is in the table
   * of docs/user-guide.md, section "Output"), as a
   * vtkDataArraySelection, the way VTK's readers select theirs. A name the
   * table lacks is refused with a warning. An array left out is not computed,
   * which is what makes a frame of Play cheaper: the field samples behind
   * Velocity, Speed and Vorticity cost about a step of the engine per output.
   * Changing the selection changes the output only, never the trace. The
   * GPU display colours by any of them, whatever this says.
   */
  vtkDataArraySelection* GetOutputArraySelection();
  int GetNumberOfOutputArrays();
  const char* GetOutputArrayName(int index);
  int GetOutputArrayStatus(const char* name);
  void SetOutputArrayStatus(const char* name, int status);
  /// Switches every output array off (the property's clean command: the
  /// names it then sets are the ones switched on).
  void DisableAllOutputArrays();
  ///@}

  ///@{
  /// Whether the output carries the Vorticity point array (|curl v| of the
  /// field's interpolant at each particle), the same as Vorticity's status in
  /// the output arrays (both must be on). Default on.
  vtkSetMacro(ComputeVorticity, vtkTypeBool);
  vtkGetMacro(ComputeVorticity, vtkTypeBool);
  vtkBooleanMacro(ComputeVorticity, vtkTypeBool);
  ///@}

  ///@{
  /// Which engine steps the trace shown by a **Bound Particles** display:
  /// CPU, GPU, or Automatic (default): the GPU on a hardware renderer, the
  /// CPU on a software one (llvmpipe, softpipe, swrast: there the GPU engine
  /// is slower), said once in Output Messages; the CPU until the display
  /// first drew. With the GPU, that display runs the GPU engine in its render
  /// window and this filter only records the work (see GPU_WORK_QUEUE());
  /// every other consumer (Surface, writers, other filters) still gets the
  /// CPU result, so nothing downstream ever sees a stale trace.
  // Declares SetEngine, GetEngine and GetEngineAsString.
  vtkBPEnumMacro(Engine, bp::EngineChoice);
  ///@}

  /**
   * Request key. A renderer that runs the GPU engine sets it on its input
   * request to the id of its work queue (BoundParticleWorkQueues.h). With Engine = GPU
   * the filter then records the engine calls into that queue instead of
   * making them, and outputs no particles: only the field data
   * BoundParticlesWorkQueue (the queue's id), TimeStep, ElementSize and
   * SimulationTime, and two points spanning the field carrying every array of
   * the CPU output at the range it is expected to span (Core/Output/OutputArrays.h). Any
   * other value (0, or no key) gets the CPU result; the key's value is part of
   * what makes the output up to date, so the two never mix.
   */
  static vtkInformationIntegerRequestKey* GPU_WORK_QUEUE();
  /// Where the output records the GPU_WORK_QUEUE it was made for.
  static vtkInformationIntegerKey* DATA_GPU_WORK_QUEUE();

  /// Hands the memory this process has freed back to the system (glibc keeps
  /// it otherwise): a tracer when destroyed, the GUI again once a deleted
  /// tracer's displays (with their copies of its output) are gone too.
  static void ReturnFreedMemory();

  ///@{
  /// What the last update did: the simulation time of the output, the number
  /// of steps it took, whether it replayed from the start, the steps between
  /// two checkpoints of its trace (0: none kept; CheckpointMemory), and the
  /// resolved step (time units) and element size (world units).
  double GetSimulationTime() const;
  vtkIdType GetStepsInLastUpdate() const;
  bool GetLastUpdateReplayed() const;
  vtkIdType GetCheckpointSpacing() const;
  double GetResolvedTimeStep() const;
  double GetResolvedElementSize() const;
  ///@}

  ///@{
  /// For the Vectors property's default (vtkSMBoundParticleVectorsDomain),
  /// found by RequestInformation while Vectors is not set (on the data its
  /// probe delivered; on the data an input holds where it has not run yet;
  /// nothing is updated for them), kept once Vectors is set while the input
  /// is the same: where the input is an image or rectilinear grid with
  /// several 3-component point arrays, the time line automatic, and the array
  /// Vectors takes by name fails the time line's units check while another
  /// passes it (bp::preferFittingUnits), the array that fails and the one to
  /// take instead. Empty otherwise, and in an MPI run.
  const char* GetUnitsMismatchedVectors();
  const char* GetUnitsFittingVectors();
  ///@}

  /// How many input time steps the filter holds (at most three: the two
  /// around the current time and, for the GPU display, the next one).
  int GetNumberOfCachedTimeSteps() const;

protected:
  vtkBoundParticleTracer();
  ~vtkBoundParticleTracer() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  /// Port 0: the elements (vtkPolyData); port 1: the FTLE map (vtkImageData);
  /// port 2: the trace's state (vtkPolyData, filled only when it is asked for);
  /// port 3: Interactions, one vertex per event at the field's sides and the
  /// Surfaces so far (TracerInteractions.h has its arrays); CPU engine only.
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  ///@{
  /// The State output: filled only when it is asked for
  /// (bpvtk::markNotGenerated), with the time last shown, and out of date
  /// once another time is shown.
  vtkTypeBool ProcessRequest(
    vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int ComputePipelineMTime(vtkInformation*, vtkInformationVector**, vtkInformationVector*,
    int port, vtkMTimeType* mtime) override;
  ///@}
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /// One pipeline pass of an update (RequestData guards it against failed allocations).
  int ExecuteUpdatePass(vtkInformation*, vtkInformationVector**, vtkInformationVector*);
#ifndef __VTK_WRAP__
  /// Ends the update (quietly when aborted, with the error once when failed:
  /// bpvtk::markFailedUpdate), or this pass asking upstream for another time step.
  int EndUpdatePass(const bpvtk::TracerPass&, vtkInformation* request, vtkInformationVector*);
  /// The properties as the VTK-free core takes them.
  bp::TraceSettings Settings() const;
  /// The properties as the internals read them (they read nothing else).
  bpvtk::TracerConfig Config();
  /// What this pass brought on input 0: the data, and the Vectors array
  /// when it is a dataset traced as it is.
  bpvtk::TracerInputStep InputStep(vtkInformationVector** inputVector);
  /// The properties that make the time line (bpvtk::TracerTimeLine).
  bpvtk::TimeLineSettings TimeLineProperties() const;
  /// RequestInformation for an input that offers only its present time step
  /// (in situ, `TracerInSitu.h`): the trace advances with each step.
  int RequestStreamInformation(vtkInformation* inInfo, vtkInformationVector* outputVector);
  /// The field's facts, read once upstream (TracerFieldProbe.h; collective).
  bpvtk::FieldProbe ProbeField(vtkInformation* inInfo, const std::vector<double>& inputTimes);
  /// The probe of the data the input delivered (bpvtk::DeliveredInput).
  bpvtk::FieldProbe ProbeDelivered(
    vtkDataObject* data, vtkInformation* inInfo, const std::vector<double>& inputTimes);
#endif

  bp::BuiltinShape ElementShape = bp::BuiltinShape::Strip8;
  bp::MeshSprings TemplateSprings = bp::MeshSprings::EdgesAndDiagonals;
  bp::Orientation ReleaseOrientation = bp::Orientation::AlongFlow;
  bp::ReleasePattern ReleasePattern = bp::ReleasePattern::Random;
  bp::EngineChoice Engine = bp::EngineChoice::Automatic;
  bp::StepUnit StepSizeUnit = bp::StepUnit::CellLength;
  bp::Integrator Integrator = bp::Integrator::Euler;
  bp::Restoration Restoration = bp::Restoration::AveragedJacobi;
  bp::ShapeFit ShapeMatchingMode = bp::ShapeFit::Rigid;
  bp::Anchor Anchor = bp::Anchor::None;
  bp::Inertia Inertia = bp::Inertia::None;
  bp::Linking Linking = bp::Linking::None;
  bp::ResetWhen ResetWhen = bp::ResetWhen::CenterLeaves;
  bp::Boundary Boundary = bp::Boundary::ReleaseAgain;
  double Restitution = 1.0;
  bp::SurfaceInteraction SurfaceInteraction = bp::SurfaceInteraction::Gate;
  std::string SurfaceInteractionArray = "None";
  int Periodic[3] = { 0, 0, 0 };
  int ColoringAxis = 2;
  int ResampleDimensions[3] = { 0, 0, 0 };
  vtkIdType NumberOfElements = 1000;
  double ElementSize = 0.0;
  double EmitterCenter[3] = { 0.0, 0.0, 0.0 };
  double EmitterSize[3] = { -1.0, -1.0, -1.0 };
  double LatticeSpacing = 0.0;
  double ElementRotation[3] = { 0.0, 0.0, 0.0 };
  double LifetimeRange[2] = { 0.0, 0.0 };
  double StepSize = 0.5;
  double CheckpointMemory = -1.0;
  std::string InitialStateFile;
  int RestorationIterations = 1;
  double RelaxationFactor = 0.2;
  double ShapeMatchingStiffness = 1.0;
  double LinearShapeMatchingBeta = 0.5;
  int LatticeWidth = 0;
  double LinkStiffness = 1.0;
  double ResponseTime = 0.1;
  double DensityRatio = 1000.0;
  double Gravity[3] = { 0.0, 0.0, 0.0 };
  double MinimumReleaseSpeed = 0.01;
  int ReleaseWindow = 0;
  double ReleaseStart = 0.0;
  double ReleaseStop = 0.0;
  bp::TimeDirection TimeDirection = bp::TimeDirection::Forward;
  int Trails = 0;
  int TrailLength = 8;
  int TrailSpacing = 4;
  int Seed = 0;
  double Duration = 0.0;
  int NumberOfTimeSteps = 101;
  int FramesPerInputStep = 0;
  vtkTypeBool ComputeVorticity = true;
  /// The output arrays switched on: every row of bp::outputArrays(), in order.
  vtkNew<vtkDataArraySelection> OutputArraySelection;
  /// The Seed Type's points; nullptr for the emitter box.
  vtkSmartPointer<vtkBoundParticleSeedType> SeedType;

private:
  vtkBoundParticleTracer(const vtkBoundParticleTracer&) = delete;
  void operator=(const vtkBoundParticleTracer&) = delete;

  std::unique_ptr<vtkBoundParticleTracerInternals> Internals;
#ifndef __VTK_WRAP__
  /// The time line offered, its warnings, and the Vectors default's units check.
  std::unique_ptr<bpvtk::TracerTimeLine> TimeLine;
#endif
};

#endif

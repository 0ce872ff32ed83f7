// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuEngine.h
 * @brief The GPU engine: the step of docs/engine-specification.md as GLSL
 * kernels over float textures, run as compute shaders or fragment passes.
 *
 * The same step as bp::Engine, computed per texel by the GLSL kernels in
 * Shaders/ (reset, advect, K restoration iterations, reposition test,
 * finalize, and with Parameters::trackPoses the pose fit; normals on
 * demand), ping-ponging RGBA32F textures; a motion trail is a ring of
 * copies of the state textures, recorded by blits. Particle state
 * is laid out in blocks of one template particle index each (thesis §3.5.1),
 * every block a near-square grid of elements, so the texture is near square
 * and no count needs to be a power of two; the limit is GL_MAX_TEXTURE_SIZE.
 * The field's time steps are 3D textures sampled exactly with texelFetch.
 *
 * Two paths run the same kernels (GpuPath.h): on OpenGL 4.3 and later the
 * compute path, each kernel a compute dispatch and, for a system whose
 * elements fit a workgroup, the whole step one fused dispatch that keeps an
 * element's particles in shared memory from reset to pose; on OpenGL 3.3 the
 * fragment path, a full-screen fragment pass per kernel. Both write the same
 * textures, which a renderer draws from with vertex texture fetch.
 * BOUNDPARTICLES_GPU_PATH=compute|fragment forces a path.
 *
 * Plain OpenGL through libepoxy, no VTK: it runs in any current context, a
 * headless EGL one (tests, benchmarks) or a render window's. Every
 * restoration runs here: averaged Jacobi and Jacobi as gathers over each
 * particle's springs, Gauss-Seidel as one pass (or one barrier) per colour
 * of a spring colouring (the CPU engine applies the springs in the same
 * colour order), shape matching as a fit per element and a move per
 * particle. A step never waits for the GPU nor reads from it.
 *
 * Inside, by role: GpuSystem.h (what configure() makes, a step's passes),
 * GpuPasses.h (running and reading back passes; the programs built for the
 * trace's integrator, poses and inertia by #define), GpuProgramCache.h (each
 * program compiled once, kept across configure()), ShaderSource.h (a program's
 * GLSL put together, compiled, its errors named by file and line),
 * GpuTemplate.h (the template's tables), GpuState.h (the state textures),
 * GpuFieldCache.h (resident time steps), PassObserver.h (told about every pass),
 * all GL objects held by the owners of GlObjects.h. GpuStepper.h puts the
 * engine behind the Stepper verbs (Core/Stepping/Stepper.h).
 */
#ifndef BoundParticles_GpuEngine_h
#define BoundParticles_GpuEngine_h

#include "ElementTemplate.h"
#include "Engine.h"
#include "GpuPath.h"
#include "PassObserver.h"
#include "VectorField.h"

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace bp
{

class GpuEngine
{
public:
  GpuEngine();
  ~GpuEngine(); // releases GL objects only through release()

  /// Takes the passes, compiled for the parameters' integrator, poses and
  /// inertia, from the engine's program cache (compiling those it does not
  /// hold yet) and sizes the textures; the GL context must be current.
  /// Empty on success, otherwise why the GPU cannot run this system (and,
  /// as after release(), no GL object is left, no program cached).
  std::string configure(const ElementTemplate& shape, const Parameters& parameters);

  /// Makes the field's time steps resident: a time step already uploaded (or
  /// staged) is not uploaded again, the rest of a partly staged one is
  /// uploaded now. At most three time steps are resident; the least recently
  /// used one outside the current field makes room.
  std::string setField(const VectorField& field);

  /// Uploads whole z layers (at least one, about maxBytes) of a time step the
  /// field will need next, into the resident slot not in use, so that moving
  /// on to it with setField() does not upload a whole volume at once. The
  /// slice must be on the current field's grid. Returns the layers still to
  /// upload (0 when it is resident).
  int stageSlice(const FieldSlice& slice, std::size_t maxBytes);

  /// stageSlice() in slabs of about 1 MiB until `seconds` have passed (at
  /// least one slab): what a renderer spends of a frame on the next time
  /// step. Returns the layers still to upload.
  int stageSliceWithin(const FieldSlice& slice, double seconds);

  /// How many field time steps are resident (at most three).
  int residentTimeSteps() const;

  /// The emitter box releases draw from from now on (Engine::setEmitter); the
  /// state copies (saveState) hold no parameters, so restoreState keeps it.
  void setEmitter(const std::array<float, 3>& min, const std::array<float, 3>& max);

  /// Places every element (generation 0).
  void initialize(double startTime = 0.0);

  /// One step of size h from time t, on the field last set.
  void step(double t, double h);

  /// Recomputes the normals texture from the positions.
  void updateNormals();

  /// The state in the CPU engine's element-major order (null to skip).
  void read(
    std::vector<float>* positions, std::vector<float>* forces, std::vector<float>* normals) const;
  /// Heavy particles: each particle's slip, as Engine::slips() (empty
  /// without inertia).
  void readSlips(std::vector<float>& slips) const;
  /// `hidden`: 1 for an element placed outside the release window, 2 for one
  /// terminated at the boundary (Boundary Terminate), an Outlet or a Wall, else 0.
  void readElements(std::vector<float>* lifetimes, std::vector<float>* generations,
    std::vector<float>* centers, std::vector<float>* orientations = nullptr,
    std::vector<float>* resetFlags = nullptr, std::vector<float>* hidden = nullptr) const;

  /// Each element's pose (x, y, z, w) and spin (angular velocity xyz,
  /// SpinVorticityRatio), 4 floats per element in the CPU engine's order, as
  /// Engine::poses() and Engine::spins() (null to skip either).
  void readPoses(std::vector<float>* poses, std::vector<float>* spins) const;

  /// @name Motion trails (Parameters::trailLength): k = 0 the newest pose, k < trailLength()
  ///@{
  int trailLength() const;
  /// When the k-th newest pose was recorded; -infinity: not yet.
  double trailTime(int k) const;
  /// The k-th newest pose's positions (as read()) and each element's
  /// generation then (NoTrailPose where nothing is recorded), as the CPU
  /// engine's trailPositions() and trailGenerations() of trailSlot(k).
  void readTrail(
    int k, std::vector<float>* positions, std::vector<std::uint32_t>* generations) const;
  ///@}

  /// Keeps a copy of the state (particles, elements, centres, orientations,
  /// poses, spins, and the trail's times and the slot a step records into):
  /// a step to a time between two step boundaries is shown, then taken back
  /// with restoreState(), as the CPU filter steps a copy.
  void saveState();
  void restoreState();

  /// @name A state to save and resume (Core/Engine/EngineState.h, GpuEngineState.h)
  ///@{
  /// The state at the step boundary as the CPU engine's Engine::saveState()
  /// gives it (with `saved`, saveState()'s copy: a short step is shown past
  /// it); empty on success, otherwise why not.
  std::string readState(EngineState& state, bool saved = false) const;
  /// Replaces every element by the state's, with its trail ring and emitter
  /// box, on an engine configured with the template and parameters it was
  /// saved with: a state the CPU engine saved goes on here, one read here
  /// goes on bit for bit. Refuses (nothing changed) a state that is not
  /// whole or that the GPU cannot hold (bp::gpuStateRefusal): empty on
  /// success, otherwise why not.
  std::string loadState(const EngineState& state);
  ///@}

  /// @name Checkpoints: copies of the state saveState() copies and of the
  /// whole trail ring, kept on the GPU by texture copies (no read-back),
  /// keyed by the steps from the start (Stepper::keepCheckpoint). A
  /// configure() or release() drops them.
  ///@{
  void keepCheckpoint(long long steps);
  /// Goes back to the copy kept after `steps` steps: a run that steps on
  /// from there gives the bits of one that never stopped. False (nothing
  /// changed) if no copy was kept there.
  bool resumeCheckpoint(long long steps);
  void dropCheckpoints();
  int checkpointCount() const;
  /// The GPU memory one checkpoint takes (bp::gpuCheckpointBytes).
  double checkpointBytes() const;
  ///@}

  /// Samples the field at every particle at time t (velocity and |curl v|,
  /// as bp::sampleAtPositions) into the samples texture, for colouring.
  void updateFieldSamples(double t);

  /// The samples of updateFieldSamples() in element-major order.
  void readFieldSamples(std::vector<float>* velocity, std::vector<float>* vorticity) const;

  /// What a renderer needs to draw the state with vertex texture fetch: the
  /// GL names of the current textures and the layout (bp_shared.glsl).
  struct DrawInputs
  {
    unsigned positions = 0; ///< per particle: grid-local position, force
    unsigned normals = 0;   ///< per particle: unit normal
    unsigned samples = 0;   ///< per particle: velocity, |curl v| (updateFieldSamples)
    unsigned elements = 0;  ///< per element: lifetime, generation, flags
    unsigned centers = 0;   ///< per element: the generation's initial centre
    unsigned poses = 0;     ///< per element: pose quaternion (x, y, z, w)
    unsigned spins = 0;     ///< per element: angular velocity xyz, SpinVorticityRatio
    unsigned slips = 0;     ///< per particle: the slip (heavy particles; 0: none)
    int elementGrid[2] = { 0, 0 };
    int blocksPerRow = 0;
    int elementCount = 0;
    int particlesPerElement = 0;
    /// One pose of the motion trail: an element's trail pose is shown while
    /// its generation there (elements' .y; -1 where none) is the element's own.
    struct TrailSlot
    {
      unsigned positions = 0; ///< per particle: position, force, as `positions`
      unsigned elements = 0;  ///< per element: lifetime, generation, flags, as `elements`
      double time = 0.0;      ///< when it was recorded; -infinity: not yet
    };
    int trailLength = 0;
    std::vector<TrailSlot> trail; ///< trailLength slots, newest first
    /// The field's Domain::halfPeriods() (0 along an axis that is not
    /// periodic): a pose across a periodic seam from its element is not drawn.
    float trailHalfPeriods[3] = { 0, 0, 0 };
  };
  DrawInputs drawInputs() const;

  /// The Jacobi restoration pass with the template's springs written into
  /// the program as code (thesis §3.5), instead of read from a buffer; takes
  /// effect at the next configure(). Both give the same bits; the benchmark
  /// (bench/) measures which is faster.
  void setGeneratedSprings(bool generated);
  bool generatedSprings() const;

  /// On the compute path, whether a system whose elements fit a workgroup
  /// runs its step as one fused dispatch or as a dispatch per kernel, as a
  /// super set does (FusedSteps, GpuPath.h; Automatic by default); takes
  /// effect at the next configure(). Both run the same kernels; tests
  /// compare them.
  void setFusedSteps(FusedSteps choice);
  /// The path configure() chose (GpuPath.h), and whether the step is fused.
  GpuPath path() const;
  bool fusedStep() const;
  /// How many uniform locations the driver was asked since configure(): each
  /// program's names once, then none while stepping (GpuPasses::uniformLocation).
  long uniformLookups() const;
  /// How many programs were compiled since the engine was made or
  /// released, and how many it keeps: each configure() takes its programs
  /// from the engine's cache, which compiles a program the first time its
  /// source (path, kernel, KernelSpecialisation where the kernel depends on
  /// it) is asked for only (GpuProgramCache.h).
  long programsCompiled() const;
  std::size_t programsKept() const;

  /// Tells `observer` about every pass and copy from now on, across
  /// configure() and release(), or stops (null). Not owned: it must outlive
  /// the steps it observes. Tests and benchmarks time the passes with it
  /// (PassTimer, Gpu/Support/PassTimer.h); null costs a check per pass.
  void setPassObserver(PassObserver* observer);

  /// Caps the texture size below GL_MAX_TEXTURE_SIZE (for tests of the limit).
  void setTextureSizeLimit(int texels);

  /// Texture sizes, for reports: particle texture and element texture.
  int particleTextureWidth() const;
  int particleTextureHeight() const;

  /// Deletes the GL objects, the cached programs with them; the context
  /// must be current.
  void release();

private:
  struct Internals;
  std::unique_ptr<Internals> I;
};

} // namespace bp

#endif

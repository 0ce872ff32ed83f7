// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuPasses.h
 * @brief The GPU engine's passes: compiled for a path, fed, run and read back.
 *
 * Every kernel of Shaders/ runs as a pass of its own on either path
 * (GpuPath.h): on the fragment path a full-screen triangle drawn into one to
 * four RGBA32F textures, on the compute path a dispatch of an invocation per
 * texel that stores into them as images. The compute path also has the fused
 * step (bp_step.comp), a whole step in one dispatch, for systems whose
 * elements fit a workgroup (FusedStep). A pass begins with the uniforms
 * every pass shares (the layout, the placement parameters, the super set's
 * lattice, the field), then takes its own textures and uniforms by name, so
 * a pass ignores what it does not use. An observer, when one is set, is
 * told about every pass and copy (PassObserver.h).
 *
 * The programs are compiled for the trace's KernelSpecialisation: the
 * integrator, whether poses are fitted and whether particles are heavy are
 * #defines of the programs that use them (BP_INTEGRATOR, BP_TRACK_POSES,
 * BP_INERTIAL), not uniforms they branch on. They come from a
 * GpuProgramCache that outlives the passes, so a configure with settings
 * seen before compiles nothing again (GpuProgramCache.h).
 *
 * Every call needs the GL context current; the programs and framebuffers are
 * deleted as GlObjects.h says.
 */
#ifndef BoundParticles_GpuPasses_h
#define BoundParticles_GpuPasses_h

#include "Engine.h"
#include "GlObjects.h"
#include "GpuPath.h"
#include "GpuProgramCache.h"
#include "ParticleLayout.h"
#include "PassObserver.h"
#include "ShaderSource.h"

#include <cstddef>
#include <functional>
#include <initializer_list>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace bp
{

class GpuPass;
class GpuPasses;

/// Where each element and particle sits in the engine's textures (bp_shared.glsl).
struct GpuLayout
{
  int elementCount = 0;          ///< E
  int particlesPerElement = 0;   ///< n, the template's particles
  int elementGrid[2] = { 0, 0 }; ///< element e at (e % W, e / W) of a W x H grid
  int blocksPerRow = 0;          ///< particle i of every element in block i, so many a row
  int particleTextureWidth = 0;  ///< blocksPerRow * W
  int particleTextureHeight = 0; ///< rows of blocks * H
  GpuLayout() = default;
  /// `layout` is ParticleLayout::of(elements, particles), checked
  /// against the GPU's texture size.
  GpuLayout(const ParticleLayout& layout, std::size_t elements, std::size_t particles);

  /// The row-major texel index of particle i of element e.
  std::size_t particleTexel(int e, int i) const;
};

/// What every pass reads besides its own inputs (bp_common.glsl).
struct SharedPassInputs
{
  const GpuLayout* layout = nullptr;
  const Parameters* parameters = nullptr;
  bool linked = false;     ///< a super set, released as one from its lattice
  GLuint latticeSites = 0; ///< per element: its lattice site (bound even when unused)
  /// Binds the field's textures and uniforms to a pass (GpuSystem sets it to
  /// its field cache's applyTo); empty, or doing nothing, before a field is set.
  std::function<void(GpuPass&)> bindField;
};

/// How the fused step restores shapes (BP_RESTORATION in bp_step.comp, which
/// compares it with the BP_FUSED_* #defines written from this enum).
enum class FusedRestore
{
  None = 0,     ///< no springs, no shape matching (BP_FUSED_NONE)
  Jacobi,       ///< Jacobi or averaged Jacobi (BP_FUSED_JACOBI)
  GaussSeidel,  ///< BP_FUSED_GAUSS_SEIDEL
  ShapeMatching ///< BP_FUSED_SHAPE_MATCHING
};

/// What a GPU's compute stage allows, as the fused step needs it.
struct ComputeLimits
{
  int threads = 0;     ///< invocations a workgroup (and its x size, the smaller)
  int sharedBytes = 0; ///< GL_MAX_COMPUTE_SHARED_MEMORY_SIZE
  /// Images one compute program may bind: the smaller of
  /// GL_MAX_COMPUTE_IMAGE_UNIFORMS and GL_MAX_IMAGE_UNITS.
  int images = 0;
};

/// The fused step of the compute path (bp_step.comp), as compiled for a system.
struct FusedStep
{
  int particles = 0;     ///< n, the template's particles (BP_N)
  int groupElements = 0; ///< elements a workgroup holds; 0: no fused step
  FusedRestore restoration = FusedRestore::None; ///< BP_RESTORATION
  bool inertial = false; ///< heavy particles: slips stepped and shared (BP_INERTIAL)
  /// The fused step for a system, or none (groupElements 0) where its
  /// elements do not fit a workgroup of `limits.threads` invocations and
  /// `limits.sharedBytes` of shared memory, the images it stores into are
  /// more than `limits.images`, or a super set's links join elements.
  /// `wantedElements` above 0 asks for that many elements a workgroup
  /// (BOUNDPARTICLES_FUSED_GROUP) in place of a SIMD group's worth; fewer
  /// where the limits hold fewer.
  static FusedStep of(const Parameters& parameters, int particles, bool springs,
    const ComputeLimits& limits, int wantedElements = 0);
  /// The images the fused step stores into: the particles, each element
  /// texture, and the slips of heavy particles (bp_step.comp).
  static int imagesBound(bool inertial);
};

/// What the programs of a trace are compiled for: the settings the
/// kernels once branched on in uniforms, #defines now (GpuProgramCache.h
/// keeps a program per source, so per specialisation where it differs).
struct KernelSpecialisation
{
  /// BP_INTEGRATOR: BP_INTEGRATOR_EULER, _RK2 or _RK4 (bp_advect.glsl).
  Integrator integrator = Integrator::Euler;
  /// BP_TRACK_POSES: the fused step fits poses and spins (bp_step.comp);
  /// a pass of its own runs only where they are fitted (GpuSystem::step).
  bool trackPoses = false;
  /// BP_INERTIAL: heavy particles (bp::carriesInertia): the advect kernel
  /// adds the slip's displacement, the fused step steps and shares slips.
  bool inertial = false;

  static KernelSpecialisation of(const Parameters& parameters);
  /// "#define BP_INTEGRATOR BP_INTEGRATOR_RK4\n" and so on: the
  /// integrator always, BP_INERTIAL with `inertia` where particles are
  /// heavy, BP_TRACK_POSES with `poses` where poses are fitted.
  std::string defines(bool inertia, bool poses) const;
};

/// One pass being set up: its program in use, texture units handed out in turn.
class GpuPass
{
public:
  /// Binds `texture` to a texture unit for the sampler `name`: the next
  /// unit, or the one `name` has in this pass already. A sampler the program
  /// does not use takes none.
  GpuPass& texture(const char* name, GLuint texture, GLenum target = GL_TEXTURE_2D);
  void setInt(const char* name, int value) const;
  void setUnsigned(const char* name, unsigned value) const;
  void setFloat(const char* name, float value) const;
  void setVec3(const char* name, const float* value) const;
  void setVec4(const char* name, const float* value) const;
  void setIVec2(const char* name, int x, int y) const;
  void setIVec3(const char* name, int x, int y, int z) const;

  /// Runs the pass over a `width` x `height` domain into `targets` (at
  /// most four): on the fragment path the full-screen triangle drawn into
  /// them as colour attachments, in order; on the compute path an
  /// invocation per texel storing into them as images 0, 1, ...
  void run(std::initializer_list<GLuint> targets, int width, int height) const;
  /// run() over the element grid: an invocation per element.
  void runPerElement(std::initializer_list<GLuint> targets) const;
  /// run() over the particle texture: an invocation per particle.
  void runPerParticle(std::initializer_list<GLuint> targets) const;
  /// Dispatches `groups` workgroups (the fused step), `images` bound to
  /// image units 0, 1, ... (0: none there).
  void runGroups(std::size_t groups, std::initializer_list<GLuint> images) const;

private:
  friend class GpuPasses;
  GpuPass(const GpuPasses& passes, const GpuLayout& layout, GLuint program)
    : Passes(passes)
    , Layout(layout)
    , Program(program)
  {
  }
  int location(const char* name) const;
  void draw(std::initializer_list<GLuint> targets, int width, int height) const;
  void dispatch(std::initializer_list<GLuint> targets, int width, int height) const;

  /// Tells the observer the pass's traffic: its textures' bytes and `written`.
  void tellTraffic(std::size_t written) const;

  const GpuPasses& Passes;
  const GpuLayout& Layout;
  GLuint Program = 0;
  int Unit = 0;
  std::vector<std::pair<std::string, int>> Units; ///< the unit of each sampler bound
  /// With an observer: the bytes of the texture on each unit (by unit).
  std::vector<std::size_t> UnitBytes;
};

class GpuPasses
{
public:
  /// Takes every pass for `path` from `cache` (compiled there the first
  /// time its source is asked for), and on the compute path the fused step
  /// as `fused` says (none where fused.groupElements is 0), and makes the
  /// framebuffers. The kernels that depend on the integrator, heavy
  /// particles or poses are built for `specialisation`: the advect kernel
  /// (and the slip kernels, which include it) for its integrator and
  /// inertia, the fused step for all three. `springSumCode`, when not
  /// empty, is the template's springs written as code (GpuTemplate.h) for
  /// the Jacobi kernel instead of its springs buffer. Empty on success,
  /// otherwise the compiler's or linker's log, naming the pass's file and
  /// each message's file and line (ShaderSource.h).
  std::string compile(GpuPath path, const std::string& springSumCode, const FusedStep& fused,
    const KernelSpecialisation& specialisation, GpuProgramCache& cache);

  GpuPath path() const { return this->Path; }
  /// What compile() built the programs for.
  const KernelSpecialisation& specialisation() const { return this->Specialisation; }

  /// Uses `program` (a name in `programs`) with the uniforms every pass shares.
  GpuPass begin(GLuint program, const SharedPassInputs& shared) const;

  /// A texture's texels, 4 floats each, row by row.
  void readTexture(GLuint texture, int width, int height, std::vector<float>& out) const;
  /// A particle texture in the CPU engine's element-major order: xyz into
  /// `xyz` (3 per particle) and w into `w` (null to skip either).
  void readParticles(
    GLuint texture, const GpuLayout& layout, std::vector<float>* xyz, std::vector<float>* w) const;
  /// Writes a texture's texels, 4 floats each, row by row (readTexture's
  /// inverse: a saved state's upload, GpuEngine::loadState).
  void writeTexture(GLuint texture, int width, int height, const std::vector<float>& texels) const;
  /// Writes a particle texture from `xyz` (3 per particle) and `w` (1 per
  /// particle; null: 0) in the CPU engine's element-major order
  /// (readParticles' inverse); its padding texels keep their values.
  void writeParticles(GLuint texture, const GpuLayout& layout, const std::vector<float>& xyz,
    const std::vector<float>* w) const;
  /// Copies a texture's texels into another of the same size (a blit: GL 3.3).
  void copyTexture(GLuint from, GLuint to, int width, int height) const;
  /// Sets every texel of a texture to `value` (4 floats), without an upload.
  void clearTexture(GLuint texture, const float* value) const;

  /// Tells `observer` about every pass and copy from now on (null: none).
  void setObserver(PassObserver* observer) { this->Observer = observer; }

  /// A uniform's location in `program`, asked of the driver the first time only.
  int uniformLocation(GLuint program, const char* name) const;
  /// How many times uniformLocation() asked the driver since compile().
  long uniformLookups() const { return this->LocationLookups; }

  /// The passes (a kernel of Shaders/ each), in the order a step runs them:
  /// the names of programs the GpuProgramCache given to compile() owns.
  struct Programs
  {
    GLuint reset = 0;       ///< places flagged elements (all, initialising)
    GLuint slip = 0;        ///< heavy particles: the slip's step and displacement
    GLuint slipShare = 0;   ///< heavy particles: an element's shared slip
    GLuint advect = 0;      ///< moves particles through the field
    GLuint restore = 0;     ///< (averaged) Jacobi over each particle's springs
    GLuint gaussSeidel = 0; ///< one colour of springs
    GLuint match = 0;       ///< shape matching: a fit per element
    GLuint matchApply = 0;  ///< shape matching: a move per particle
    GLuint link = 0;        ///< a super set's links between elements
    GLuint wall = 0;        ///< the walls after restoration (Boundary Stick, Slip, Bounce)
    GLuint test = 0;        ///< the reposition test
    GLuint finalize = 0;    ///< the new state
    GLuint normals = 0;     ///< per particle, from the template's triangles
    GLuint pose = 0;        ///< the pose fit and spin (Parameters::trackPoses)
    GLuint samples = 0;     ///< the field at every particle, for colouring
    GLuint step = 0;        ///< the compute path's fused step (bp_step.comp), or 0: none
  };
  Programs programs;
  /// What the fused step was compiled for (groupElements 0: none).
  FusedStep fused;

private:
  friend class GpuPass;
  /// The name a program is told to the observer by.
  const std::string& nameOf(GLuint program) const;
  /// Builds the fused step with the Jacobi kernel `restore`.
  std::string compileFusedStep(
    const ShaderPiece& restore, const std::string& generated, GpuProgramCache& cache);

  GpuPath Path = GpuPath::Fragment;
  KernelSpecialisation Specialisation;
  std::vector<std::pair<GLuint, std::string>> Names; ///< each program's name
  GlVertexArray Triangle; ///< empty: bp_fullscreen.vert makes the triangle from gl_VertexID
  GlFramebuffer Framebuffer;
  GlFramebuffer CopyTarget; ///< the draw side of copyTexture's blit
  PassObserver* Observer = nullptr; ///< not owned
  /// Each program's uniform locations by name, as the driver gave them.
  mutable std::unordered_map<GLuint, std::unordered_map<std::string, int>> Locations;
  mutable long LocationLookups = 0;
};

} // namespace bp

#endif

// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GpuPath.h
 * @brief Which of the GPU engine's two paths runs a system: compute shaders
 * or fragment passes, and the one message that says so.
 *
 * The compute path (OpenGL 4.3 and later) runs each kernel as a compute
 * dispatch, and a system's whole step as one fused dispatch where its
 * elements fit a workgroup (GpuPasses.h); the fragment path (OpenGL 3.3)
 * draws a full-screen triangle per pass. Both run the same kernels
 * (Shaders/), so they give the same physics.
 *
 * The path is the compute path wherever the context has OpenGL 4.3, unless
 * the environment variable BOUNDPARTICLES_GPU_PATH says `fragment`;
 * `compute` on an older context falls back to the fragment path with a
 * warning that names the context's version. The path in use is said once
 * per process (and once more for each other path or context), through the
 * message sink.
 */
#ifndef BoundParticles_GpuPath_h
#define BoundParticles_GpuPath_h

#include <string>
#include <vector>

namespace bp
{

enum class GpuPath
{
  Fragment, ///< full-screen fragment passes: any OpenGL 3.3 core context
  Compute   ///< compute shaders and a fused step: OpenGL 4.3 and later
};

/// "fragment" or "compute".
const char* gpuPathName(GpuPath path);

/**
 * The value of the environment variable `variable` (`value`: its value, null
 * when unset) if it is one of `accepted`; empty when it is unset or empty,
 * and also when it is none of them, in which case `warning` gets a message
 * that names the variable, the value and the accepted values, and goes on
 * with `otherwise` (what happens instead).
 */
std::string acceptedValue(const char* variable, const char* value,
  const std::vector<std::string>& accepted, const std::string& otherwise, std::string& warning);

/// The environment variable that forces a path.
constexpr const char* GpuPathVariable = "BOUNDPARTICLES_GPU_PATH";
/// The lowest OpenGL version (major * 10 + minor) the compute path runs on.
constexpr int ComputePathVersion = 43;

/// The path for a context and what to say about it.
struct GpuPathChoice
{
  GpuPath path = GpuPath::Fragment;
  std::string note;    ///< the path in use and why, for the log
  std::string warning; ///< empty unless a request could not be followed (one a line)
};

/**
 * The path for a context of OpenGL `version` (major * 10 + minor, as
 * epoxy_gl_version()) described by `context` (its GL_VERSION, for
 * messages), asked for by `requested` (BOUNDPARTICLES_GPU_PATH's value;
 * null or empty: automatic).
 */
GpuPathChoice chooseGpuPath(int version, const std::string& context, const char* requested);

/// chooseGpuPath() for the current context and the environment.
GpuPathChoice currentGpuPath();

/**
 * `choice`, a compute path whose programs the driver refused (`error`: the
 * compiler's or linker's message), turned into the fragment path, which runs
 * the same kernels: its warning (one line) names the program and why, its note
 * says the fragment path runs (`context`: GL_VERSION).
 */
void fallBackToFragmentPath(
  GpuPathChoice& choice, const std::string& error, const std::string& context);

/// For tests: while on, every compute program the engine builds fails to
/// compile (an `#error` directive in its source), as a driver's compiler may
/// refuse one, so the fallback to the fragment path can be checked anywhere.
void setComputeCompileFailureForTesting(bool on);
bool computeCompileFailureForTesting();

/// Whether the compute path runs a system's step as one fused dispatch
/// (bp_step.comp), where its elements fit a workgroup, or as a dispatch per
/// kernel.
enum class FusedSteps
{
  Automatic, ///< fused on a GPU, a dispatch per kernel on a software rasterizer
  Always,
  Never
};

/// The environment variable that overrides FusedSteps::Automatic: `on`, `off` or `automatic`.
constexpr const char* FusedStepVariable = "BOUNDPARTICLES_GPU_FUSED_STEP";

/// The environment variable that sets the fused step's elements a workgroup
/// (a whole number from 1 to 1024; fewer where the GPU's limits hold fewer):
/// for tuning on a GPU (the bundle's real_gpu.sh sweeps it). Unset: a SIMD
/// group's worth, at least 128 threads.
constexpr const char* FusedGroupVariable = "BOUNDPARTICLES_FUSED_GROUP";

/// BOUNDPARTICLES_FUSED_GROUP's value: its number, or 0 where it is unset,
/// empty or not a whole number from 1 to 1024.
int fusedGroupValue(const char* value);

/**
 * Whether `choice` fuses the steps on the renderer named `renderer`
 * (GL_RENDERER), `requested` the value of BOUNDPARTICLES_GPU_FUSED_STEP (null
 * or empty: none; a value it does not know is ignored, with a message in
 * `warning` where given). Automatic follows `requested` (`on`, `off`), else fuses
 * them on a GPU, which skips a phase for a SIMD group whose threads all wait
 * (the fused step's per-element phases leave most of a workgroup waiting),
 * and not on a software rasterizer (llvmpipe), which runs every phase for
 * every thread and where the fused step measured about half as fast as a
 * dispatch per kernel.
 */
bool fusesSteps(FusedSteps choice, const std::string& renderer, const char* requested,
  std::string* warning = nullptr);

/// Where the engine's messages go: `warning` tells a warning from a note.
/// The default writes them to standard error; a renderer routes them to its
/// own log (the plugin: VTK's output window).
using GpuMessageSink = void (*)(const std::string& text, bool warning);
void setGpuMessageSink(GpuMessageSink sink);

/// Says the choice's note (and its warnings, one a line) through the sink,
/// unless the same was said before in this process.
void sayGpuPathOnce(const GpuPathChoice& choice);

} // namespace bp

#endif

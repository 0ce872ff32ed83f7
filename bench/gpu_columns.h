// SPDX-License-Identifier: BSD-3-Clause
// The engine bench's GPU columns (bench_engine.cpp): the GPU engine stepped
// each way it can (the fragment path, the compute path with a dispatch per
// kernel, the compute path's fused step), particle-steps per second, and the
// share of the device's memory bandwidth that the state a step must read and
// write once would take at that rate.
#ifndef BoundParticles_bench_gpu_columns_h
#define BoundParticles_bench_gpu_columns_h

#include "Engine.h"
#include "GpuEngine.h"
#include "PassTime.h"

#include <functional>
#include <string>
#include <vector>

namespace bench
{

/// One way the GPU engine steps: a column of every row.
struct GpuVariant
{
  const char* name;      ///< column name
  bp::GpuPath path;      ///< forced through BOUNDPARTICLES_GPU_PATH
  bp::FusedSteps fused;  ///< GpuEngine::setFusedSteps
};

/// Fragment, compute (a dispatch per kernel), fused (the compute path's fused step).
const std::vector<GpuVariant>& gpuVariants();

/// The bytes a step must move per particle, at the least: the particle's
/// texel read and written (2 x 16), and its element's per-element state read
/// and written (State, Centers, Orientations, Poses: 8 x 16; the spins' 16
/// more written with poses tracked) shared by its n particles. The field's
/// samples are left out (neighbouring particles read the same cells, from
/// cache). 40 for a Strip16 without poses.
double bytesPerParticleStep(std::size_t particlesPerElement, bool poses);

/// The device's memory bandwidth in bytes per second: `given` (GB/s) when
/// above 0, else the data sheet's for a GPU this knows by its GL_RENDERER
/// name (NVIDIA H100, H200), else, for a software renderer, this host's
/// memory copy rate on `threads` threads, measured now; 0 when unknown.
/// `source` says which.
double deviceBandwidth(double given, const std::string& renderer, unsigned threads,
  std::string& source);

/// Makes `variant`'s engine for the system (the path forced through
/// BOUNDPARTICLES_GPU_PATH while it configures); false, and released, where it
/// cannot run it as asked (no compute path on this context, no fused step for
/// this system).
bool configureVariant(bp::GpuEngine& engine, const GpuVariant& variant,
  const bp::ElementTemplate& shape, const bp::Parameters& p, const bp::VectorField& field,
  bool generated = false);

/// Steps per second of `variant` on the system, the median of `median`'s
/// runs of `steps` steps (glFinish around each, never inside); 0 where the
/// variant cannot run (no compute path on this context, or no fused step
/// for this system). `generated`: springs as code (setGeneratedSprings).
double gpuStepsPerSecond(const GpuVariant& variant, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double dt, bool generated,
  const std::function<double(const std::function<double()>&)>& median);

/// Each pass's GPU time per step (GL_TIME_ELAPSED; on a software renderer
/// the CPU clock around each finished pass: PassTimer.h) over `steps` steps of
/// `variant`; empty where it cannot run.
std::vector<bp::PassTime> gpuPassTimes(const GpuVariant& variant, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double dt);

} // namespace bench

#endif

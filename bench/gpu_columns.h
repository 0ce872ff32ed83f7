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

/// The bytes one step of a configured and initialised engine moves per
/// particle, at the least: what its passes tell (PassObserver::traffic: every
/// 2D texture a pass binds read once, every target written once; the
/// field's samples left out), each path its own. Steps the engine once, from
/// `t` by `dt`.
double bytesPerParticleStep(bp::GpuEngine& engine, double t, double dt, std::size_t particles);

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

/// One variant's speed on a system: steps per second, and its bytes a
/// particle-step (bytesPerParticleStep); 0 where it cannot run.
struct GpuRate
{
  double stepsPerSecond = 0.0;
  double bytesPerParticleStep = 0.0;
};

/// `variant` on the system: the median of `median`'s runs of `steps` steps
/// (glFinish around each, never inside), then one step's traffic; nothing
/// where the variant cannot run (no compute path on this context, or no
/// fused step for this system). `generated`: springs as code
/// (setGeneratedSprings).
GpuRate gpuRate(const GpuVariant& variant, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double dt, bool generated,
  const std::function<double(const std::function<double()>&)>& median);

/// Each pass's GPU time per step (GL_TIME_ELAPSED; on a software renderer
/// the CPU clock around each finished pass: PassTimer.h) over `steps` steps of
/// `variant`; empty where it cannot run.
std::vector<bp::PassTime> gpuPassTimes(const GpuVariant& variant, const bp::ElementTemplate& shape,
  const bp::Parameters& p, const bp::VectorField& field, int steps, double dt);

} // namespace bench

#endif

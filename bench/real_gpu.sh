#!/usr/bin/env bash
# The GPU engine's rows on a real GPU (an NVIDIA H100 or H200), in one run,
# side by side (issue 39; docs/performance.md, "The GPU engine's paths"):
#  1. BoundParticlesBench on Strip16 at 1 M, 4 M and 16 M particles (65,536,
#     262,144 and 1,048,576 elements), steady and unsteady: the fragment path,
#     the compute path (a dispatch per kernel), its fused step, and the CPU
#     engine on all the host's cores; steps/s, particle-steps/s and the share
#     of the GPU's memory bandwidth; then each pass's GPU time per step;
#  2. step plus draw of 1 M particles in ParaView (pvpython, offscreen), in
#     frames per second, on each path (bench/step_draw.py);
#  3. the CPU engine on 1, 2, 4, 8 and 16 threads, those the host has, with
#     the parallel efficiency and the bandwidth against a triad (issue 40);
#  4. heavy particles against massless on both engines, the CPU engine on
#     every core stepped alternately with the massless one (issue 44).
# Writes everything into ${1:-real-gpu}/ and prints it. Needs this project's
# build and its packages there: on a lent GPU machine with nothing installed
# (no network, no ParaView) run the bundle instead (bench/gpu-bundle.sh DIR,
# then bash DIR/real_gpu.sh OUTDIR; docs/performance.md says how).
#
#   bash bench/real_gpu.sh [OUTDIR] [--bandwidth GB/s]
#
# The bench finds the GPU's bandwidth by its name (H100, H200); give it for
# another. The ParaView rows need a ParaView that renders on the GPU: with
# ParaView 5.11 or 5.13 from Debian (GLX) an X server on the GPU, with 6.x
# EGL; step_draw.py prints the renderer it got, so a software one shows.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-real-gpu}")"
shift || true
mkdir -p "$out"
build="${BOUNDPARTICLES_BUILD_DIR:-$root/build}"
if [ ! -x "$build/bin/BoundParticlesBench" ]; then
  build="$(bash "$root/scripts/build.sh" | tail -n 1)"
fi
{
  echo "host: $(nproc) cores, $(uname -m); $(date -u +%Y-%m-%dT%H:%MZ)"
  nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>/dev/null || true
} | tee "$out/host.txt"

# 1. The engine bench, every GPU column and the CPU engine on all cores.
"$build/bin/BoundParticlesBench" --only Strip16x65536 --only Strip16x262144 \
  --only Strip16x1048576 --pass-times --threads "$(nproc)" --csv "$out/engines.csv" "$@" \
  | tee "$out/engines.txt"

# 2. Step plus draw in ParaView, on each path.
plugin="$build/plugin-path.txt"
if [ -f "$plugin" ] && command -v pvpython >/dev/null; then
  for path in compute fragment; do
    BOUNDPARTICLES_GPU_PATH=$path pvpython --force-offscreen-rendering \
      "$root/bench/step_draw.py" --plugin "$(cat "$plugin")" 2>&1 \
      | grep -v "^$" | tee -a "$out/step_draw.txt" || true
  done
else
  echo "step+draw: no ParaView plugin or pvpython here; skipped" | tee "$out/step_draw.txt"
fi

# 3. The CPU engine on more threads.
"$build/bin/BoundParticlesThreadsBench" | tee "$out/threads.txt"

# 4. Heavy particles on both engines.
"$build/bin/BoundParticlesInertiaBench" --interleaved 60 | tee "$out/inertia.txt"

echo "real_gpu: wrote $out/host.txt, $out/engines.txt, $out/engines.csv, $out/step_draw.txt," \
  "$out/threads.txt, $out/inertia.txt"

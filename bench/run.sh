#!/usr/bin/env bash
# Builds in Release and measures the engines side by side: prints the table,
# writes it as CSV and plots it (PNG) into ${1:-bench-output}/, then times
# ParaView's Particle Tracer against the Bound Particle Tracer on one job, and
# what a frame of Play costs inside ParaView (both engines and displays), the
# first frame and Play on a ~1 M-cell unstructured mesh, and steps per second
# under pvbatch with 1, 2 and 4 MPI ranks, the defaults on the shared real data
# and ParaView's mesh readers, GPU streaming and the SMP loops: every table
# docs/performance.md quotes but the real GPU's (bench/real_gpu.sh, on a GPU
# machine) and the state digests (bench/state_digest.cpp: a check, not a timing).
# Options after the folder go to the benchmark (--quick, --no-gpu, --resolution N).
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="$(realpath -m "${1:-$root/bench-output}")"
shift || true
build="$(bash "$root/scripts/build.sh" | tail -n 1)"
mkdir -p "$out"
plugin="$(cat "$build/plugin-path.txt")"
"$build/bin/BoundParticlesBench" --csv "$out/engines.csv" "$@" | tee "$out/engines.txt"
/usr/bin/python3 "$root/bench/plot.py" "$out/engines.csv" "$out/engines.png"
# ParaView's own Particle Tracer on the same job, side by side.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/vs_paraview.py" \
  --plugin "$plugin" | tee "$out/vs_paraview.txt"
# What one frame of Play costs (frame, update, step, draw), both engines and displays.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/play_frames.py" \
  --plugin "$plugin" \
  --csv "$out/play_frames.csv" | tee "$out/play_frames.txt"
/usr/bin/python3 "$root/bench/plot_play.py" "$out/play_frames.csv" "$out/play_frames.png"
# Going back in time: Previous Frame and drags back with and without checkpoints.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/step_back.py" \
  --plugin "$plugin" | tee "$out/step_back.txt"
# Saving a trace's state and resuming from it, against a straight trace.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/save_resume.py" \
  --plugin "$plugin" | tee "$out/save_resume.txt"
# The CPU output against the engine's step, array by array; the engine on 1 to 16
# threads (those this machine has); the mesh resampler's first and kept resample.
"$build/bin/BoundParticlesOutputBench" | tee "$out/output.txt"
"$build/bin/BoundParticlesThreadsBench" | tee "$out/threads.txt"
"$build/bin/BoundParticlesResampleBench" | tee "$out/resample.txt"
# Heavy particles (Inertia = Maxey-Riley) against massless tracers, the same jobs.
"$build/bin/BoundParticlesInertiaBench" | tee "$out/inertia.txt"
# ... and as Play meets them: the tracer's one-step update with the default arrays.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/inertia_update.py" \
  --plugin "$plugin" | tee "$out/inertia_update.txt"
# An unstructured mesh of ~1 M tetrahedra: first frame (resample included) and Play,
# beside an image of the same size and ParaView's Particle Tracer on the mesh; then
# hexahedra cut in five, and a mesh whose points move at every step.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/unstructured.py" \
  --plugin "$plugin" | tee "$out/unstructured.txt"
for mesh in "--cut 5" "--moving"; do
  # shellcheck disable=SC2086 # two words: an option and its value
  bash "$root/scripts/with-display.sh" pvpython "$root/bench/unstructured.py" \
    --plugin "$plugin" $mesh | tee -a "$out/unstructured.txt"
done
# Steps per second under pvbatch with 1, 2 and 4 MPI ranks (and 1 rank of 2 threads).
bash "$root/scripts/with-display.sh" /usr/bin/python3 "$root/bench/parallel_scaling.py" \
  --plugin "$plugin" | tee "$out/parallel_scaling.txt"
# How evenly 2 and 4 ranks share the elements over a hurricane run.
bash "$root/scripts/with-display.sh" /usr/bin/python3 "$root/bench/parallel_balance.py" \
  --plugin "$plugin" | tee "$out/parallel_balance.txt"
# What the defaults show on the shared real data (table and one picture each).
bash "$root/scripts/with-display.sh" pvpython "$root/bench/real_data.py" \
  --plugin "$plugin" \
  --data "$root/../shared/data" --pictures "$out/real-data" | tee "$out/real_data.txt"
# The defaults before and after issue 29, a picture per data set.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/first_minutes.py" \
  --plugin "$plugin" --data "$root/../shared/data" --pictures "$out/first-minutes"
# In situ (a step at a time through a trivial producer) against post hoc.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/insitu_steps.py" \
  --plugin "$plugin" | tee "$out/insitu_steps.txt"
# Play with the defaults through the real ParaView GUI, beside pvpython.
bash "$root/bench/gui_play.sh" --plugin "$plugin" | tee "$out/gui_play.txt"
# The defaults straight on ParaView's mesh readers (times and element counts).
bash "$root/scripts/with-display.sh" pvpython "$root/bench/mesh_data.py" \
  --plugin "$plugin" --data "$root/../shared/data" | tee "$out/mesh_data.txt"
# An unsteady field's time steps going by on the GPU engine: uploaded whole or
# streamed in slabs, in the engine alone and in the Bound Particles display.
"$build/bin/BoundParticlesStreamingBench" --resolution 160 | tee "$out/streaming.txt"
bash "$root/scripts/with-display.sh" pvpython "$root/bench/stream_frames.py" \
  --plugin "$plugin" | tee "$out/stream_frames.txt"
# The tracer's loops on the plugin's thread pool against vtkSMPTools.
bash "$root/scripts/with-display.sh" pvpython "$root/bench/smp_loops.py" \
  --plugin "$plugin" | tee "$out/smp_loops.txt"
echo "bench: wrote $out/output.txt, $out/threads.txt, $out/resample.txt, $out/inertia.txt, $out/real_data.txt, $out/real-data/*.png, $out/first-minutes/, $out/engines.txt, $out/engines.csv, $out/engines.png, $out/vs_paraview.txt, $out/play_frames.txt, $out/play_frames.png, $out/step_back.txt, $out/save_resume.txt, $out/unstructured.txt, $out/parallel_scaling.txt, $out/parallel_balance.txt, $out/gui_play.txt, $out/mesh_data.txt, $out/streaming.txt, $out/stream_frames.txt, $out/smp_loops.txt, $out/insitu_steps.txt"

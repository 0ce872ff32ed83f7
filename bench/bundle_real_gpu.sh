#!/usr/bin/env bash
# The GPU figures in one run on a lent GPU machine (issue 55): the top of the
# bundle that bench/gpu-bundle.sh makes, copied there as real_gpu.sh. Needs
# nothing but bash, coreutils and a GPU driver's EGL; no ParaView, no X, no
# compiler, no package manager.
#
#   bash real_gpu.sh OUTDIR      (on the lent machine: bash real_gpu.sh "$OUT")
#
# Sections, the GPU ones first, each under its own timeout; a failing section is
# reported and the rest go on:
#   gpu      the EGL devices, the display taken, GL's vendor, renderer, version
#            and limits (BoundParticlesGpuInfo); a software renderer (llvmpipe,
#            softpipe) is refused here, before any minute is spent, unless
#            BOUNDPARTICLES_ALLOW_SOFTWARE_GPU=1 (the rehearsal)
#   tests    the engine-level GPU tests (parity with the CPU engine, physics,
#            heavy particles, deformation, the paths) on each path: fused,
#            compute (a dispatch per kernel), fragment; a budget under 420 s
#            runs one shard of 4 (under 200 s, of 8) of each binary's tests
#   rows     Strip16 and Point at 1 M, 4 M and 16 M particles, steady Euler and
#            unsteady RK4, each GPU path and the CPU engine on every core
#            (BoundParticlesGpuRows: warmed up, >= 0.3 s or 100 steps, median of 3)
#   fused-group  the fused step at 8, 16 and 32 elements a workgroup
#            (BOUNDPARTICLES_FUSED_GROUP), Strip16, the first rows' size (under
#            100 s, 16,384 particles, steady, 64^3)
#   step-draw  the display's step plus draw without ParaView, frames per
#            second for the step, the draw and both on each path (fused
#            first): 1 M Strip16 particles into 1920x1080 with the display's
#            draw shaders (BoundParticlesStepDrawBench; under 200 s of budget
#            256 K particles, under 100 s 1,024 on a 32^3 field)
#   threads  the CPU engine on 1, 2, 4, 8 and 16 threads, 1 M particles (issue 40)
#   inertia  heavy particles against massless on both engines (issue 44); a
#            budget under 200 s runs the GPU's fused path alone
# BOUNDPARTICLES_BENCH_BUDGET=SECONDS (default 480, 8 minutes) is the whole
# run's budget: every section's time, its rows and its sizes scale with it.
# BOUNDPARTICLES_EGL_DEVICE=N takes EGL device N (as the gpu section lists them).
# The driver's EGL vendor file is looked for in GLVND's places and the
# driver's own (/usr/local/nvidia/share/glvnd/egl_vendor.d, ...) unless
# __EGL_VENDOR_LIBRARY_FILENAMES names it.
#
# Writes at most 8 files into OUTDIR: summary.txt (one line per section, last),
# host.txt, tests.txt, rows.txt, rows.csv, step-draw.txt, threads.txt, inertia.txt.
# Exits 0 when every section is ok.
set -uo pipefail # no -e: a failing section must not stop the others

here="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
bin="$here/bin"
out="${1:?usage: real_gpu.sh OUTDIR}"
mkdir -p "$out" || exit 2
out="$(cd "$out" && pwd)"
budget="${BOUNDPARTICLES_BENCH_BUDGET:-480}"
[[ "$budget" =~ ^[0-9]+$ ]] && [ "$budget" -ge 30 ] || {
  echo "real_gpu: BOUNDPARTICLES_BENCH_BUDGET=$budget: give whole seconds, at least 30" >&2
  exit 2
}
start=$SECONDS
summary="$out/summary.txt"
: >"$summary"
results=()
note() { echo "real_gpu: $*" | tee -a "$summary"; }
result() { # result NAME WHAT
  results+=("section $1: $2")
  echo "real_gpu: section $1: $2"
}
# Seconds for a section: its WEIGHT's part of what is left of the budget, the
# sections after it (WEIGHTS_AFTER together) sharing the rest; what a section
# leaves unused goes to those after it.
share() {
  local left=$((budget - (SECONDS - start) - 3)) want
  want=$((left * $1 / ($1 + $2)))
  [ "$want" -lt 5 ] && want=5
  echo "$want"
}
# run SECONDS LOG COMMAND...: the command under its timeout, output to LOG;
# prints why it failed (empty when it did not).
run() {
  local secs=$1 log=$2 rc
  shift 2
  timeout -k 10 "$secs" "$@" >>"$log" 2>&1
  rc=$?
  case $rc in
    0) ;;
    124 | 137) echo "timed out after $secs s" ;;
    *) echo "exit $rc" ;;
  esac
}

# --- gpu: the driver's EGL vendor file, the EGL devices, the renderer --------
host="$out/host.txt"
{
  echo "real_gpu.sh: budget $budget s; $(date -u +%Y-%m-%dT%H:%M:%SZ)"
  echo "host: $(nproc) cores, $(uname -m), kernel $(uname -r)," \
    "$(awk '/MemTotal/ { printf "%.0f GiB", $2 / 1048576 }' /proc/meminfo 2>/dev/null) memory"
  command -v nvidia-smi >/dev/null \
    && nvidia-smi --query-gpu=name,driver_version,memory.total --format=csv,noheader 2>&1
  sed -n '1,3p' "$here/MANIFEST.txt" 2>/dev/null
} >"$host"
defaults=(/etc/glvnd/egl_vendor.d /usr/share/glvnd/egl_vendor.d)
others=(/usr/local/nvidia/share/glvnd/egl_vendor.d /usr/local/share/glvnd/egl_vendor.d
  /usr/local/nvidia/glvnd/egl_vendor.d /usr/lib/x86_64-linux-gnu/nvidia/current/glvnd/egl_vendor.d)
if [ -n "${__EGL_VENDOR_LIBRARY_FILENAMES:-}" ]; then
  IFS=: read -r -a vendors <<<"$__EGL_VENDOR_LIBRARY_FILENAMES"
  echo "EGL vendor files: as __EGL_VENDOR_LIBRARY_FILENAMES names them" >>"$host"
else
  vendors=()
  outside=0
  for d in "${defaults[@]}" "${others[@]}"; do
    for f in "$d"/*.json; do
      [ -f "$f" ] || continue
      vendors+=("$f")
      case " ${defaults[*]} " in *" $d "*) ;; *) outside=1 ;; esac
    done
  done
  if [ "$outside" = 1 ]; then
    # GLVND reads only its default folders: name every file found, in GLVND's
    # order (by file name: 10_nvidia before 50_mesa).
    __EGL_VENDOR_LIBRARY_FILENAMES="$(for f in "${vendors[@]}"; do echo "$(basename "$f") $f"; done \
      | sort | cut -d' ' -f2 | paste -sd:)"
    export __EGL_VENDOR_LIBRARY_FILENAMES
    echo "EGL vendor files: some outside GLVND's folders; __EGL_VENDOR_LIBRARY_FILENAMES=$__EGL_VENDOR_LIBRARY_FILENAMES" >>"$host"
  else
    echo "EGL vendor files: in GLVND's folders" >>"$host"
  fi
fi
for f in "${vendors[@]}"; do
  if [ ! -f "$f" ]; then
    echo "  $f: missing" >>"$host"
    continue
  fi
  lib="$(sed -n 's/.*"library_path" *: *"\([^"]*\)".*/\1/p' "$f" | head -n 1)"
  where=""
  if [ "${lib#/}" != "$lib" ]; then
    [ -f "$lib" ] && where="$lib"
  elif ldconfig -p 2>/dev/null | grep -q "^[[:space:]]*$lib "; then
    where="in the loader's cache"
  else
    # A driver outside the loader's cache: its folder on LD_LIBRARY_PATH (the
    # bundle's own libraries still come first, through the binaries' RPATH).
    for d in "$(dirname "$f")/../../../lib64" "$(dirname "$f")/../../../lib" \
      /usr/local/nvidia/lib64 /usr/local/nvidia/lib /usr/lib64/nvidia \
      /usr/lib/x86_64-linux-gnu/nvidia/current; do
      if [ -f "$d/$lib" ]; then
        d="$(cd "$d" && pwd)"
        export LD_LIBRARY_PATH="$d${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}"
        where="$d (added to LD_LIBRARY_PATH)"
        break
      fi
    done
  fi
  echo "  $f: $lib, ${where:-NOT FOUND}" >>"$host"
done
[ "${#vendors[@]}" -gt 0 ] || echo "  none found: no GPU driver's EGL here" >>"$host"

gpu_ok=0
why="$(run 30 "$host" "$bin/BoundParticlesGpuInfo")"
renderer="$(sed -n 's/^GL renderer: //p' "$host" | head -n 1)"
if [ -n "$why" ]; then
  result gpu "failed (no OpenGL context: $(grep -m1 '^context: none' "$host" | cut -d: -f3- | sed 's/^ //')${why:+; $why})"
elif echo "$renderer" | grep -qiE 'llvmpipe|softpipe|swrast|swiftshader|software'; then
  if [ "${BOUNDPARTICLES_ALLOW_SOFTWARE_GPU:-}" = 1 ]; then
    gpu_ok=1
    result gpu "ok (software renderer $renderer, allowed by BOUNDPARTICLES_ALLOW_SOFTWARE_GPU=1)"
  else
    result gpu "failed (a software renderer, $renderer: no GPU figures; check the EGL vendor files in host.txt, or BOUNDPARTICLES_ALLOW_SOFTWARE_GPU=1 to run on it)"
    cat "$host"
    for s in tests rows fused-group step-draw threads inertia; do
      result "$s" "skipped (no hardware GPU)"
    done
    printf '%s\n' "${results[@]}" | tee -a "$summary"
    exit 3
  fi
else
  gpu_ok=1
  result gpu "ok ($renderer)"
fi
cat "$host"

# --- tests: the engine-level GPU tests on each path -------------------------
log="$out/tests.txt"
: >"$log"
if [ "$gpu_ok" = 1 ]; then
  secs=$(share 30 90)
  until=$((SECONDS + secs))
  passed=0 failed=() cut=()
  # The default path on a GPU (fused) on every binary first, then the others.
  # A shortened budget runs one shard of each binary's tests (GoogleTest's
  # sharding: every K-th test), so every binary and path still runs some.
  shards=1
  [ "$budget" -lt 420 ] && shards=4
  [ "$budget" -lt 200 ] && shards=8
  binaries=(BoundParticlesDeformationTests BoundParticlesInertiaTests BoundParticlesPhysicsTests
    BoundParticlesGpuTests BoundParticlesBoundaryTests BoundParticlesWallTests
    BoundParticlesGpuProgramTests BoundParticlesGpuStateTests)
  jobs=("BoundParticlesGpuPathTests any")
  for path in fused compute fragment; do
    for b in "${binaries[@]}"; do
      jobs+=("$b $path")
    done
  done
  # Every binary starts here (its libraries found, its tests listed), whatever
  # the budget lets run.
  unstarted=()
  for b in BoundParticlesGpuPathTests "${binaries[@]}"; do
    "$bin/$b" --gtest_list_tests >/dev/null 2>>"$log" || unstarted+=("$b")
  done
  for job in "${jobs[@]}"; do
    read -r b path <<<"$job"
    left=$((until - SECONDS))
    if [ "$left" -lt 3 ]; then
      cut+=("$b/$path")
      continue
    fi
    filter="-GpuPath.ForcedComputeFallsBackBelow43" # needs Mesa made to offer OpenGL 4.1
    env=()
    case $path in
      fused) env=(BOUNDPARTICLES_GPU_PATH=compute BOUNDPARTICLES_GPU_FUSED_STEP=on) filter="-*/CPU" ;;
      compute) env=(BOUNDPARTICLES_GPU_PATH=compute BOUNDPARTICLES_GPU_FUSED_STEP=off) filter="-*/CPU" ;;
      fragment) env=(BOUNDPARTICLES_GPU_PATH=fragment) filter="*" ;;
    esac
    echo "=== $b, path $path" >>"$log"
    t=$SECONDS
    [ "$shards" -gt 1 ] && env+=(GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=0)
    why="$(run "$left" "$log" env "${env[@]}" "$bin/$b" --gtest_brief=1 "--gtest_filter=$filter")"
    n="$(sed -n 's/^\[  PASSED  \] \([0-9]*\) test.*/\1/p' "$log" | tail -n 1)"
    echo "=== $b, path $path: ${why:-passed} in $((SECONDS - t)) s" >>"$log"
    if [ -z "$why" ]; then
      passed=$((passed + 1))
    elif [ "$why" = "timed out after $left s" ] && [ "$budget" -lt 480 ]; then
      cut+=("$b/$path") # the shortened budget ran out inside it
    else
      failed+=("$b/$path: $why")
    fi
  done
  detail="$passed of ${#jobs[@]} test runs passed"
  [ "${#unstarted[@]}" -eq 0 ] && detail+=", all $((${#binaries[@]} + 1)) binaries started"
  [ "$shards" -gt 1 ] && detail+=", each one shard of $shards (the budget)"
  [ "${#cut[@]}" -gt 0 ] && detail+="; not run or cut by the budget: ${cut[*]}"
  [ "${#unstarted[@]}" -gt 0 ] && failed+=("${unstarted[*]}: did not start")
  if [ "${#failed[@]}" -gt 0 ]; then
    result tests "failed (${failed[*]}; $detail; see tests.txt)"
  elif [ "$passed" -eq 0 ]; then
    result tests "failed (no test run finished within $secs s)"
  else
    result tests "ok ($detail)"
  fi
else
  result tests "skipped (no OpenGL context)"
fi

# --- rows: the engines' rates ------------------------------------------------
# The row set scales down with the budget: 1 M, 4 M and 16 M particles in
# 8 minutes; the timing too (0.3 s or 100 steps at 8 minutes).
cores=$(nproc)
if [ "$budget" -ge 420 ]; then particles=1048576,4194304,16777216
elif [ "$budget" -ge 200 ]; then particles=1048576,4194304
elif [ "$budget" -ge 100 ]; then particles=1048576
else particles=65536
fi
scale() { awk -v v="$1" -v b="$budget" 'BEGIN { f = b / 480; if (f > 1) f = 1; printf "%g", v * f }'; }
minsteps="$(scale 100)"
minsteps="${minsteps%.*}"
[ "${minsteps:-0}" -ge 1 ] || minsteps=1
if [ "$gpu_ok" = 1 ]; then
  secs=$(share 35 55)
  why="$(run $((secs + 20)) "$out/rows.txt" "$bin/BoundParticlesGpuRows" --particles "$particles" \
    --min-time "$(scale 0.3)" --min-steps "$minsteps" --repeats 3 --threads "$cores" \
    --budget "$secs" --csv "$out/rows.csv")"
  rows="$(sed -n 's/^rows: //p' "$out/rows.txt")"
  result rows "$([ -z "$why" ] && echo "ok ($rows)" || echo "failed ($why; see rows.txt)")"
else
  result rows "skipped (no OpenGL context)"
fi

# --- fused-group: the fused step's elements a workgroup, swept --------------
# BOUNDPARTICLES_FUSED_GROUP at 8, 16 and 32 Strip16 elements (128 to 512
# threads) on the first rows' size, steady and unsteady, the fused column
# alone; appended to rows.txt.
if [ "$gpu_ok" = 1 ]; then
  secs=$(share 15 40)
  # At least one group size's compile and run, also on a cold shader cache.
  [ "$secs" -lt 15 ] && secs=15
  until=$((SECONDS + secs))
  done_groups=() cut_groups=() why=""
  # Under 100 s: the steady rows of 16,384 particles on 64^3 fields.
  sweep=(--particles "${particles%%,*}")
  [ "$budget" -lt 100 ] && sweep=(--particles 16384 --fields steady --resolution 64)
  for g in 8 16 32; do
    left=$((until - SECONDS))
    if [ "$left" -lt 3 ] || [ -n "$why" ]; then
      cut_groups+=("$g")
      continue
    fi
    echo "=== BOUNDPARTICLES_FUSED_GROUP=$g" >>"$out/rows.txt"
    w="$(run "$left" "$out/rows.txt" env BOUNDPARTICLES_FUSED_GROUP=$g "$bin/BoundParticlesGpuRows" \
      "${sweep[@]}" --shapes Strip16 --paths fused --no-cpu \
      --min-time "$(scale 0.3)" --min-steps "$minsteps" --repeats 3 --budget "$left")"
    if [ -z "$w" ]; then
      done_groups+=("$g")
    elif [ "$w" = "timed out after $left s" ] && [ "$budget" -lt 480 ]; then
      cut_groups+=("$g") # the shortened budget ran out inside it
    else
      why="$g: $w"
    fi
  done
  detail="${done_groups[*]:-none} elements a workgroup, in rows.txt"
  [ "${#cut_groups[@]}" -gt 0 ] && detail+="; not run or cut by the budget: ${cut_groups[*]}"
  if [ -n "$why" ]; then
    result fused-group "failed ($why; $detail)"
  elif [ "${#done_groups[@]}" -eq 0 ]; then
    result fused-group "failed (no group size finished within $secs s)"
  else
    result fused-group "ok ($detail)"
  fi
else
  result fused-group "skipped (no OpenGL context)"
fi

# --- step-draw: the display's step plus draw, frames per second, each path ---
# 1 M Strip16 particles (65,536 elements) into a 1920x1080 framebuffer with
# the display's own draw shaders (bench/step_draw.cpp), the fused path first
# (a GPU's default); a path that would end past the section's time is listed
# as skipped. Fewer elements at a shortened budget; the framebuffer stays
# 1920x1080.
if [ "$gpu_ok" = 1 ]; then
  secs=$(share 10 30)
  if [ "$budget" -ge 200 ]; then args=(--elements 65536)
  elif [ "$budget" -ge 100 ]; then args=(--elements 16384)
  else args=(--elements 64 --resolution 32)
  fi
  why="$(run $((secs + 20)) "$out/step-draw.txt" "$bin/BoundParticlesStepDrawBench" "${args[@]}" \
    --paths fused,compute,fragment --min-time "$(scale 0.3)" --min-frames "$minsteps" \
    --repeats 3 --seconds "$secs")"
  fps="$(sed -n 's/^step+draw: //p' "$out/step-draw.txt")"
  result step-draw "$([ -z "$why" ] && echo "ok ($fps)" || echo "failed ($why; see step-draw.txt)")"
else
  result step-draw "skipped (no OpenGL context)"
fi

# --- threads: the CPU engine on 1 to 16 threads, 1 M particles ---------------
secs=$(share 10 20)
if [ "$budget" -ge 400 ]; then args=(--repeats 3)
else args=(--quick --repeats 1 --divide $((budget >= 200 ? 4 : 64)))
fi
why="$(run "$secs" "$out/threads.txt" "$bin/BoundParticlesThreadsBench" --threads 1,2,4,8,16 "${args[@]}")"
result threads "$([ -z "$why" ] && echo ok || echo "failed ($why; see threads.txt)")"

# --- inertia: heavy particles against massless, both engines ---------------
secs=$(share 20 0)
# At least 60 s whatever is left: its GPU half first compiles the heavy
# particles' programs (their own advect kernel and fused step, BP_INERTIAL),
# seconds each on a software renderer whose shader cache is empty (the
# rehearsal's bare chroot made anew, or the shaders changed: 25 s ran out
# there); a lent GPU's budget never gets this low.
[ "$secs" -lt 60 ] && secs=60
if [ "$budget" -ge 400 ]; then args=(--interleaved 60)
elif [ "$budget" -ge 200 ]; then args=(--quick --repeats 1 --divide 4)
else args=(--quick --repeats 1 --divide 32 --gpu-path fused) # the path a GPU runs by default
fi
[ "$gpu_ok" = 1 ] || args+=(--cpu-only)
why="$(run "$secs" "$out/inertia.txt" "$bin/BoundParticlesInertiaBench" "${args[@]}")"
result inertia "$([ -z "$why" ] && echo ok || echo "failed ($why; see inertia.txt)")"

note "done in $((SECONDS - start)) s of a $budget s budget; files in $out: $(cd "$out" && ls | paste -sd' ')"
printf '%s\n' "${results[@]}" | tee -a "$summary"
for r in "${results[@]}"; do
  case $r in *": ok"*) ;; *) exit 1 ;; esac
done
exit 0

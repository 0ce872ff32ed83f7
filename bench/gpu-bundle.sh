#!/usr/bin/env bash
# Builds, here, everything the GPU figures need into one folder that runs on a
# bare x86-64 Linux with only a GPU driver (issue 55): no ParaView, no X, no
# compiler, no package manager there.
#
#   bash bench/gpu-bundle.sh DIR
#
# DIR/real_gpu.sh    the device script (bench/bundle_real_gpu.sh): bash DIR/real_gpu.sh OUTDIR
# DIR/bin/           the benches, BoundParticlesGpuInfo, and the engine-level
#                    GPU ctest binaries (parity, physics, paths), stripped;
#                    the engine and GPU libraries are static, linked in
# DIR/lib/           the shared libraries a bare machine lacks: libepoxy, the
#                    GLVND loaders (libEGL.so.1, libGLdispatch.so.0,
#                    libOpenGL.so.0), Google Benchmark, and whatever else ldd
#                    shows outside a minimal Debian
# DIR/MANIFEST.txt   what was built from which commit, the libraries and their
#                    sources, the newest glibc symbol version the binaries need
#
# Every binary carries RPATH $ORIGIN/../lib (DT_RPATH, not RUNPATH, so it also
# governs the loaders libepoxy opens with dlopen and their own dependencies):
# nothing the bundle carries is looked up outside it. Builds with the plugin
# off in ${BOUNDPARTICLES_BUNDLE_BUILD_DIR:-build/bundle-build} (ccache). Fails
# if DIR would exceed 48 MiB.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
dir="${1:?usage: gpu-bundle.sh DIR}"
build="${BOUNDPARTICLES_BUNDLE_BUILD_DIR:-$root/build/bundle-build}"
limit_mib=48
t0=$SECONDS
say() { echo "gpu-bundle: $*" >&2; }
fail() {
  say "FAILED: $*"
  exit 1
}

bins=(BoundParticlesGpuInfo BoundParticlesGpuRows BoundParticlesStepDrawBench BoundParticlesBench
  BoundParticlesThreadsBench BoundParticlesInertiaBench BoundParticlesGpuTests BoundParticlesPhysicsTests
  BoundParticlesInertiaTests BoundParticlesDeformationTests BoundParticlesGpuPathTests
  BoundParticlesBoundaryTests BoundParticlesWallTests BoundParticlesGpuProgramTests
  BoundParticlesGpuStateTests)
# The libraries every x86-64 Linux has (glibc and the compiler's runtime):
# never carried. Anything else ldd names is.
base='^(linux-vdso|ld-linux-x86-64|libc|libm|libdl|librt|libpthread|libgcc_s|libstdc\+\+)\.so'
# Loaders libepoxy opens with dlopen (ldd cannot see them): EGL and desktop GL
# through GLVND, without GLX (libGL.so.1 would bring libX11).
dlopened=(libEGL.so.1 libGLdispatch.so.0 libOpenGL.so.0)

mkdir -p "$build"
export CCACHE_BASEDIR="$root"
launcher=()
command -v ccache >/dev/null \
  && launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
# No build RPATH of CMake's own (absolute paths): $ORIGIN/../lib only.
if ! cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" \
  -DBOUNDPARTICLES_BUILD_PLUGIN=OFF -DBOUNDPARTICLES_BUILD_BENCH=ON -DBUILD_TESTING=ON \
  -DCMAKE_SKIP_BUILD_RPATH=ON \
  "-DCMAKE_EXE_LINKER_FLAGS=-Wl,--disable-new-dtags -Wl,-rpath,\$ORIGIN/../lib" \
  >"$build/configure.log" 2>&1; then
  cat "$build/configure.log" >&2
  fail "configure (log above)"
fi
cmake --build "$build" --parallel "$(nproc)" --target "${bins[@]}" -- --no-print-directory \
  >"$build/build.log" 2>&1 || {
  tail -n 60 "$build/build.log" >&2
  fail "build (log above; whole log in $build/build.log)"
}
say "built in $((SECONDS - t0)) s in $build"

rm -rf "$dir"
mkdir -p "$dir/bin" "$dir/lib"
for b in "${bins[@]}"; do
  strip -o "$dir/bin/$b" "$build/bin/$b"
done
# The shared libraries: what ldd finds for each binary, outside the base set,
# then the dlopened loaders and what they need in turn.
libpath() { # the host's file for SONAME
  ldconfig -p | awk -v n="$1" '$1 == n && /x86-64/ { print $NF; exit }'
}
declare -A carried=()
carry() { # carry SONAME PATH
  [ -n "${carried[$1]:-}" ] && return
  [ -f "$2" ] || fail "no $1 on this machine (for the bundle)"
  carried[$1]="$(realpath "$2")"
  strip --strip-unneeded -o "$dir/lib/$1" "$(realpath "$2")"
  local dep path
  while read -r dep path; do
    [[ "$dep" =~ $base ]] || carry "$dep" "$path"
  done < <(ldd "$2" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }')
}
for b in "${bins[@]}"; do
  while read -r dep path; do
    [[ "$dep" =~ $base ]] || carry "$dep" "$path"
  done < <(ldd "$build/bin/$b" | awk '$2 == "=>" && $3 ~ /^\// { print $1, $3 }')
done
for l in "${dlopened[@]}"; do
  carry "$l" "$(libpath "$l")"
done
cp "$root/bench/bundle_real_gpu.sh" "$dir/real_gpu.sh"

# Every binary's RPATH is $ORIGIN/../lib and every library it needs is either
# carried or in the base set.
for b in "${bins[@]}"; do
  rpath="$(readelf -d "$dir/bin/$b" | sed -n 's/.*(RPATH).*\[\(.*\)\]/\1/p')"
  [ "$rpath" = '$ORIGIN/../lib' ] || fail "$b has RPATH '$rpath', not \$ORIGIN/../lib"
  readelf -d "$dir/bin/$b" | grep -q '(RUNPATH)' && fail "$b has a RUNPATH"
  for need in $(readelf -d "$dir/bin/$b" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'); do
    [[ "$need" =~ $base ]] || [ -f "$dir/lib/$need" ] || fail "$b needs $need, not carried"
  done
done
glibc="$(for f in "$dir"/bin/* "$dir"/lib/*; do objdump -T "$f"; done 2>/dev/null \
  | grep -o 'GLIBC_[0-9.]*' | sort -uV | tail -n 1)"
glibcxx="$(for f in "$dir"/bin/* "$dir"/lib/*; do objdump -T "$f"; done 2>/dev/null \
  | grep -o 'GLIBCXX_[0-9.]*' | sort -uV | tail -n 1)"
{
  echo "BoundParticles GPU bundle (bench/gpu-bundle.sh), built $(date -u +%Y-%m-%dT%H:%MZ)"
  echo "commit: $(git -C "$root" describe --always --dirty 2>/dev/null || echo unknown)"
  echo "built on: $(. /etc/os-release && echo "$PRETTY_NAME"), $(uname -m)"
  echo "needs from the system: glibc with $glibc, libstdc++ with $glibcxx, libgcc_s, a GPU driver's EGL"
  echo "run: bash real_gpu.sh OUTDIR   (BOUNDPARTICLES_BENCH_BUDGET=SECONDS, default 480)"
  echo "binaries:"
  for b in "${bins[@]}"; do echo "  bin/$b"; done
  echo "libraries carried (from):"
  for l in $(printf '%s\n' "${!carried[@]}" | sort); do echo "  lib/$l  ${carried[$l]}"; done
} >"$dir/MANIFEST.txt"
size_kib=$(du -sk "$dir" | cut -f1)
[ "$size_kib" -le $((limit_mib * 1024)) ] \
  || fail "the bundle is $((size_kib / 1024)) MiB, over $limit_mib MiB"
say "$dir: $((size_kib / 1024)).$(((size_kib % 1024) * 10 / 1024)) MiB, ${#bins[@]} binaries," \
  "${#carried[@]} libraries, in $((SECONDS - t0)) s"

#!/usr/bin/env bash
# Sourced by scripts/build.sh: build_options ROOT sets the array build_options
# to the CMake options of the build folder, which the test suite and the
# Debian package share (scripts/package.sh makes the package from that build,
# with no second compile):
#
# - Release, through ccache where there is one (CCACHE_BASEDIR: a clone
#   elsewhere, or the same sources built again, compiles only what changed);
# - Debian's build flags (dpkg-buildflags, from dpkg-dev: build-essential
#   brings it) with every hardening feature on (lintian checks the package's
#   libraries for them) and without debug information (-g); Release's own
#   -O3 -DNDEBUG come after them, so -O3 wins over Debian's -O2. They are
#   passed as CMake options, not in CFLAGS and the like, so that a build
#   folder configured before takes them too;
# - the package's documentation folder (share/doc/paraview-boundparticles);
# - BOUNDPARTICLES_CORE_TESTS from the environment where it is set
#   (scripts/chroot-test.sh sets OFF: the engine core's tests cannot differ
#   between ParaView versions and run on the host).
#   The prefix stays CMake's (/usr/local): scripts/package.sh installs with
#   `cmake --install --prefix /usr`, and the login scripts are made for the
#   prefix installed to (cmake/BoundParticlesInstall.cmake).
build_options() {
  local root="$1" cppflags cflags cxxflags ldflags
  build_options=(-DCMAKE_BUILD_TYPE=Release
    -DCMAKE_INSTALL_DOCDIR=share/doc/paraview-boundparticles)
  if [ -n "${BOUNDPARTICLES_CORE_TESTS:-}" ]; then
    build_options+=("-DBOUNDPARTICLES_CORE_TESTS=$BOUNDPARTICLES_CORE_TESTS")
  fi
  if command -v ccache >/dev/null; then
    build_options+=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    export CCACHE_BASEDIR="$root"
  fi
  command -v dpkg-buildflags >/dev/null || return 0
  # From the sources' folder: Debian's -ffile-prefix-map maps the current
  # folder to ".", so the binaries name no clone's path (and ccache, with
  # CCACHE_BASEDIR, shares them between clones).
  cd "$root" || return 1
  export DEB_BUILD_MAINT_OPTIONS=hardening=+all DEB_CFLAGS_MAINT_STRIP=-g DEB_CXXFLAGS_MAINT_STRIP=-g
  cppflags="$(dpkg-buildflags --get CPPFLAGS)"
  cflags="$(dpkg-buildflags --get CFLAGS)"
  cxxflags="$(dpkg-buildflags --get CXXFLAGS)"
  ldflags="$(dpkg-buildflags --get LDFLAGS)"
  cd - >/dev/null || return 1
  build_options+=("-DCMAKE_C_FLAGS=$cppflags $cflags" "-DCMAKE_CXX_FLAGS=$cppflags $cxxflags"
    "-DCMAKE_EXE_LINKER_FLAGS=$ldflags" "-DCMAKE_SHARED_LINKER_FLAGS=$ldflags"
    "-DCMAKE_MODULE_LINKER_FLAGS=$ldflags")
}

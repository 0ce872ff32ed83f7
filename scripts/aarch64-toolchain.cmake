# Cross compiling for aarch64 with Debian's g++-aarch64-linux-gnu
# (scripts/aarch64-core.sh builds the engine core and its tests with it).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
# gtest_discover_tests runs the test binary at build time to list its tests:
# qemu-user runs it, with the cross toolchain's loader and libraries.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /usr/aarch64-linux-gnu)

# SPDX-License-Identifier: Apache-2.0
# Cross build for the glider's arm64 Linux computer on a Debian 12 build
# machine (multiarch): crossbuild-essential-arm64 and the :arm64 -dev
# packages (./glider cross installs them). CTest runs the arm64 test
# programs under qemu-user, with the arm64 libraries from multiarch.
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_LIBRARY_ARCHITECTURE aarch64-linux-gnu)

set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)

# Libraries and pkg-config files of the target only; headers-only packages
# (Eigen, Boost, CLI11, nlohmann-json) are architecture-independent and come
# from /usr/include and /usr/share either way.
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
set(ENV{PKG_CONFIG_SYSROOT_DIR} "")

find_program(GLIDER_QEMU_AARCH64 NAMES qemu-aarch64 qemu-aarch64-static REQUIRED)
# The arm64 loader and libraries from multiarch (/lib/ld-linux-aarch64.so.1,
# libc6:arm64), not "-L /usr/aarch64-linux-gnu": that loader (libc6-arm64-cross)
# finds libc6:arm64's libc through the host's ld.so.cache, and the two builds
# of glibc together hang in the first pthread_create (a program that starts a
# std::thread never got past it).
set(CMAKE_CROSSCOMPILING_EMULATOR ${GLIDER_QEMU_AARCH64} -L /)

# Shared part of the Debian cross toolchain files: the including file sets HIL_CROSS_TRIPLET (the
# GNU triplet, e.g. aarch64-linux-gnu), HIL_CROSS_PROCESSOR and HIL_CROSS_QEMU (the qemu-user
# binary). Compilers are Debian's g++-<triplet>; libraries and headers come from the target's
# sysroot /usr/<triplet> (libc6-dev-<arch>-cross); test executables run under qemu-user with -L
# that sysroot (CMAKE_CROSSCOMPILING_EMULATOR, which ctest and add_test use).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR ${HIL_CROSS_PROCESSOR})
set(HIL_CROSS_SYSROOT /usr/${HIL_CROSS_TRIPLET})
set(CMAKE_C_COMPILER ${HIL_CROSS_TRIPLET}-gcc)
set(CMAKE_CXX_COMPILER ${HIL_CROSS_TRIPLET}-g++)
set(CMAKE_FIND_ROOT_PATH ${HIL_CROSS_SYSROOT})
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE ONLY)
# Eigen is header-only: the host's package (libeigen3-dev) serves every target
set(Eigen3_DIR /usr/share/eigen3/cmake CACHE PATH "Eigen's CMake package (header-only: the host's)")
set(CMAKE_CROSSCOMPILING_EMULATOR ${HIL_CROSS_QEMU} -L ${HIL_CROSS_SYSROOT})

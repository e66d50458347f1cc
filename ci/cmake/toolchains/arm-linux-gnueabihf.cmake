# armhf (32-bit ARMv7, hard float: Debian's default -march=armv7-a+fp -mthumb), e.g. a Raspberry
# Pi 2/3 on 32-bit Debian: g++-arm-linux-gnueabihf, tests under qemu-arm (Debian qemu-user). Used
# by the cross-armhf preset and ci/cross armhf.
set(HIL_CROSS_TRIPLET arm-linux-gnueabihf)
set(HIL_CROSS_PROCESSOR armv7l)
set(HIL_CROSS_QEMU qemu-arm)
set(HIL_DEB_ARCH armhf)
include(${CMAKE_CURRENT_LIST_DIR}/cross-linux-gnu.cmake)

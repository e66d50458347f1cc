# arm64 (aarch64) Linux, e.g. a Raspberry Pi 3/4/5 on 64-bit Debian: g++-aarch64-linux-gnu,
# tests under qemu-aarch64 (Debian qemu-user). Used by the cross-arm64 preset and ci/cross arm64.
set(HIL_CROSS_TRIPLET aarch64-linux-gnu)
set(HIL_CROSS_PROCESSOR aarch64)
set(HIL_CROSS_QEMU qemu-aarch64)
set(HIL_DEB_ARCH arm64)
include(${CMAKE_CURRENT_LIST_DIR}/cross-linux-gnu.cmake)

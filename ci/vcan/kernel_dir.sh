# Sourced by ci/vcan scripts: sets HIL_VCAN_KERNEL_DIR, the cache of the Debian kernel the vcan VM
# boots (vmlinuz + the four CAN modules, decompressed). Build-independent, shared by every checkout.
# Override with the environment variable of the same name.
if [ -z "${HIL_VCAN_KERNEL_DIR:-}" ]; then
  if [ -d /var/cache/hil/vcan-kernel ] || { [ "$(id -u)" -eq 0 ] && [ -w /var/cache ]; }; then
    HIL_VCAN_KERNEL_DIR=/var/cache/hil/vcan-kernel
  else
    HIL_VCAN_KERNEL_DIR="${XDG_CACHE_HOME:-$HOME/.cache}/hil/vcan-kernel"
  fi
fi
export HIL_VCAN_KERNEL_DIR

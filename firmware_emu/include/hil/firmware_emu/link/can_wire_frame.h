#pragma once
/// @file
/// A CAN frame as the bus carries it: identifier, format flags and payload, with no time. The
/// SocketCAN port and the candump log speak this type; devices speak hil::CanFrame (device.h),
/// which carries its emulated send time, and converts with FromDeviceFrame / ToDeviceFrame.

#include <array>
#include <cstdint>

#include "hil/firmware_emu/device.h"

namespace hil::link {

struct CanWireFrame {
  /// 11-bit (standard) or 29-bit (extended) identifier without flag bits; for an error frame, the
  /// error class bits (CAN_ERR_* of <linux/can/error.h>).
  std::uint32_t id = 0;
  bool extended = false;
  bool rtr = false;           ///< remote transmission request (classic frames only)
  bool error = false;         ///< error frame reported by the controller (CAN_ERR_FLAG)
  bool fd = false;            ///< CAN FD frame
  std::uint8_t fd_flags = 0;  ///< CAN FD flags: bit 0 BRS (bit-rate switch), bit 1 ESI
  std::uint8_t len =
      0;  ///< payload length: 0–8 classic (RTR: the requested length), FD 0–8,12,16,20,24,32,48,64
  std::array<std::uint8_t, 64> data{};  ///< payload; bytes past `len` are zero

  bool operator==(const CanWireFrame&) const = default;
};

/// Error-frame class bits and controller status bits of <linux/can/error.h>, repeated here so that
/// code reading a capture needs no Linux header.
inline constexpr std::uint32_t kCanErrTxTimeout = 0x001, kCanErrLostArb = 0x002,
                               kCanErrCrtl = 0x004, kCanErrProt = 0x008, kCanErrTrx = 0x010,
                               kCanErrAck = 0x020, kCanErrBusOff = 0x040, kCanErrBusError = 0x080,
                               kCanErrRestarted = 0x100;
/// data[1] of a kCanErrCrtl frame
inline constexpr std::uint8_t kCanErrCrtlRxOverflow = 0x01, kCanErrCrtlTxOverflow = 0x02;

/// True for the payload lengths a CAN FD frame can have (0–8, 12, 16, 20, 24, 32, 48, 64).
constexpr bool IsValidFdLength(unsigned len) {
  return len <= 8 || len == 12 || len == 16 || len == 20 || len == 24 || len == 32 || len == 48 ||
         len == 64;
}

/// The wire frame of a device's frame (its send time is dropped).
CanWireFrame FromDeviceFrame(const CanFrame& f);
/// The device-level frame at emulated time `t`, flags and all (FromDeviceFrame's inverse).
CanFrame ToDeviceFrame(const CanWireFrame& w, Time t);

}  // namespace hil::link

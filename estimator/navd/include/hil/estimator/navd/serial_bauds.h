#pragma once
/// @file
/// The baud rates navd opens its serial devices at ([input] gnss_baud, imu_baud), each with its
/// termios speed constant; any other rate is a configuration error. The emulators keep their own
/// copy (firmware_emu/.../link/baud_table.h; the dependency rule keeps the two apart), and
/// tests/firmware_emu/link/baud_tables_test.cc checks that both list the same rates and constants.

#include <termios.h>

#include <array>
#include <optional>
#include <string>

namespace hil::navd {

struct SerialBaud {
  int baud;
  speed_t speed;
};

inline constexpr std::array<SerialBaud, 11> kSerialBauds{{
    {1200, B1200},
    {2400, B2400},
    {4800, B4800},
    {9600, B9600},
    {19200, B19200},
    {38400, B38400},
    {57600, B57600},
    {115200, B115200},
    {230400, B230400},
    {460800, B460800},
    {921600, B921600},
}};

/// The termios speed of a baud rate; nullopt when navd does not support it.
constexpr std::optional<speed_t> SerialSpeed(int baud) {
  for (const SerialBaud& b : kSerialBauds) {
    if (b.baud == baud) return b.speed;
  }
  return std::nullopt;
}

/// "1200, 2400, …, 921600" (for error messages).
inline std::string SerialBaudList() {
  std::string s;
  for (const SerialBaud& b : kSerialBauds) s += (s.empty() ? "" : ", ") + std::to_string(b.baud);
  return s;
}

}  // namespace hil::navd

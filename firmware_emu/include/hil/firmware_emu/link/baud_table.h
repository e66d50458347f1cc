#pragma once
/// @file
/// The baud rates the emulators' serial links (pty, tty) support, each with its termios speed
/// constant. navd keeps its own copy (estimator/navd/.../serial_bauds.h: the dependency rule keeps
/// the estimator and the emulators apart); tests/firmware_emu/link/baud_tables_test.cc checks that
/// both list the same rates with the same constants.

#include <termios.h>

#include <array>

namespace hil::link {

struct BaudSpeed {
  int baud;
  speed_t speed;
};

inline constexpr std::array<BaudSpeed, 11> kBaudSpeeds{{
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

/// Maps a baud rate to its termios speed constant; returns 0 when the rate has none.
unsigned BaudToSpeed(int baud);

}  // namespace hil::link

#pragma once
/// @file
/// Message layer of the base's serial protocol (ROSArduinoBridge command set, see
/// vectors/base_serial/README.md): one command letter, then space-separated arguments; replies are
/// lines ending CR LF. Implemented commands: `b` (baud), `e` (encoder counts), `m L R` (target
/// encoder ticks per PID frame), `r` (reset encoders and PID), `u Kp:Kd:Ki:Ko` (PID gains). Any
/// other line is answered `Invalid Command`.

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace hil::actuator {

enum class BaseCommandKind : std::uint8_t {
  kGetBaud,
  kReadEncoders,
  kMotorSpeeds,
  kResetEncoders,
  kUpdatePid,
  kInvalid,
};

struct BaseCommand {
  BaseCommandKind kind = BaseCommandKind::kInvalid;
  std::array<long, 4> args{};  ///< m: left, right ticks per frame; u: Kp, Kd, Ki, Ko
  int arg_count = 0;
};

/// Parses one line (without its CR). The command is the last character before the first space
/// (the firmware overwrites its command byte with each character of the first word). Arguments are
/// read as the firmware's atoi reads them: an optional sign and leading digits, anything else gives
/// 0.
BaseCommand ParseBaseCommand(std::string_view line);

std::string FormatBaseOk();                                             ///< "OK\r\n"
std::string FormatBaseInvalid();                                        ///< "Invalid Command\r\n"
std::string FormatBaseBaud(long baud);                                  ///< "57600\r\n"
std::string FormatBaseEncoders(std::int32_t left, std::int32_t right);  ///< "L R\r\n"

}  // namespace hil::actuator

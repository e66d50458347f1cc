#include "hil/firmware_emu/actuator/base_serial_session.h"

#include <cmath>
#include <numbers>

#include "hil/firmware_emu/actuator/base_serial_codec.h"

namespace hil::actuator {
namespace {

std::int32_t AsFirmwareLong(std::int64_t count) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(count & 0xFFFFFFFF));
}

}  // namespace

BaseSerialSession::BaseSerialSession(const BaseSerialConfig& config, WheelMotors& motors)
    : cfg_(config), motors_(motors) {}

double BaseSerialSession::RadpsFromTicksPerFrame(long ticks) const {
  const int cpr = motors_.config().encoder_counts_per_rev;
  return static_cast<double>(ticks) * cfg_.pid_rate_hz / cpr * 2.0 * std::numbers::pi;
}

long BaseSerialSession::TicksPerFrameFromRadps(double radps) const {
  const int cpr = motors_.config().encoder_counts_per_rev;
  return std::lround(radps / (2.0 * std::numbers::pi) * cpr / cfg_.pid_rate_hz);
}

void BaseSerialSession::OnHostBytes(Time t, std::string_view bytes, DeviceOutput& out) {
  for (char c : bytes) {
    if (!framer_.Feed(c)) continue;
    ++counters_.lines;
    SerialMessage msg;
    msg.t_ready = t;
    msg.port = 0;
    msg.bytes = Execute(t, framer_.line());
    msg.name = "BASE-REPLY";
    out.serial.push_back(std::move(msg));
  }
}

std::string BaseSerialSession::Execute(Time t, const std::string& line) {
  const BaseCommand cmd = ParseBaseCommand(line);
  motors_.AdvanceTo(t);
  switch (cmd.kind) {
    case BaseCommandKind::kGetBaud:
      return FormatBaseBaud(cfg_.baud);
    case BaseCommandKind::kReadEncoders:
      ++counters_.encoder_reads;
      return FormatBaseEncoders(AsFirmwareLong(motors_.encoder_count(kLeftWheel)),
                                AsFirmwareLong(motors_.encoder_count(kRightWheel)));
    case BaseCommandKind::kResetEncoders:
      motors_.ResetEncoders();
      return FormatBaseOk();
    case BaseCommandKind::kMotorSpeeds:
      ++counters_.motor_commands;
      motors_.Command(t, RadpsFromTicksPerFrame(cmd.args[0]), RadpsFromTicksPerFrame(cmd.args[1]));
      return FormatBaseOk();
    case BaseCommandKind::kUpdatePid:
      return FormatBaseOk();  // the emulated speed loop is the configured lag, not a PID
    case BaseCommandKind::kInvalid:
      break;
  }
  ++counters_.invalid;
  return FormatBaseInvalid();
}

}  // namespace hil::actuator

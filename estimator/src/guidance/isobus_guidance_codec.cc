#include "hil/estimator/guidance/isobus_guidance_codec.h"

#include <cmath>

namespace hil::estimator::guidance {
namespace {

constexpr double kLsb_per_km = 0.25;
constexpr double kOffset_per_km = -8032.0;
constexpr std::uint32_t kMaxValid16 = 0xFAFF;
constexpr std::uint32_t kMaxValid32 = 0xFAFFFFFF;

std::uint32_t Le16(const IsobusFrame& f, int at) {
  return static_cast<std::uint32_t>(f.data[at]) | (static_cast<std::uint32_t>(f.data[at + 1]) << 8);
}

std::uint32_t Le32(const IsobusFrame& f, int at) { return Le16(f, at) | (Le16(f, at + 2) << 16); }

}  // namespace

std::uint32_t PgnOfId(std::uint32_t id29) {
  const std::uint32_t pgn = (id29 >> 8) & 0x3FFFF;
  return ((pgn >> 8) & 0xFF) < 240 ? (pgn & 0x3FF00) : pgn;
}

IsobusFrame EncodeSystemCommand(const SystemCommandAddress& address, double curvature_per_km,
                                std::uint8_t status) {
  IsobusFrame f;
  f.id = (static_cast<std::uint32_t>(address.priority & 7) << 26) | (kPgnSystemCommand << 8) |
         (static_cast<std::uint32_t>(address.destination) << 8) | address.source;
  f.len = 8;
  f.data.fill(0xFF);
  double raw = std::round((curvature_per_km - kOffset_per_km) / kLsb_per_km);
  if (!(raw >= 0)) raw = 0;
  if (raw > kMaxValid16) raw = kMaxValid16;
  const auto r = static_cast<std::uint32_t>(raw);
  f.data[0] = static_cast<std::uint8_t>(r & 0xFF);
  f.data[1] = static_cast<std::uint8_t>(r >> 8);
  f.data[2] = static_cast<std::uint8_t>(0xFC | (status & 3));
  return f;
}

IsobusDecodeResult DecodeMachineInfo(const IsobusFrame& frame, MachineInfo& out) {
  if (PgnOfId(frame.id) != kPgnMachineInfo) return IsobusDecodeResult::kOtherPgn;
  if (frame.len != 8) return IsobusDecodeResult::kWrongLength;
  out.source = static_cast<std::uint8_t>(frame.id & 0xFF);
  const std::uint32_t raw = Le16(frame, 0);
  out.curvature_valid = raw <= kMaxValid16;
  out.estimated_curvature_per_km = raw * kLsb_per_km + kOffset_per_km;
  out.mechanical_lockout = frame.data[2] & 3;
  out.readiness = (frame.data[2] >> 2) & 3;
  out.input_position_status = (frame.data[2] >> 4) & 3;
  out.request_reset = (frame.data[2] >> 6) & 3;
  out.limit_status = (frame.data[3] >> 5) & 7;
  out.exit_reason = frame.data[4] & 0x3F;
  out.remote_engage_switch = (frame.data[4] >> 6) & 3;
  return IsobusDecodeResult::kOk;
}

IsobusDecodeResult DecodeWheelSpeedDistance(const IsobusFrame& frame, WheelSpeedDistance& out) {
  if (PgnOfId(frame.id) != kPgnWheelSpeedDistance) return IsobusDecodeResult::kOtherPgn;
  if (frame.len != 8) return IsobusDecodeResult::kWrongLength;
  out.source = static_cast<std::uint8_t>(frame.id & 0xFF);
  const std::uint32_t v = Le16(frame, 0);
  out.speed_valid = v <= kMaxValid16;
  out.speed_mps = v * 1e-3;
  const std::uint32_t d = Le32(frame, 2);
  out.distance_valid = d <= kMaxValid32;
  out.distance_m = d * 1e-3;
  out.max_time_of_tractor_power_min = frame.data[6];
  out.direction = frame.data[7] & 3;
  out.key_switch = (frame.data[7] >> 2) & 3;
  out.implement_start_stop = (frame.data[7] >> 4) & 3;
  out.operator_direction_reversed = (frame.data[7] >> 6) & 3;
  return IsobusDecodeResult::kOk;
}

}  // namespace hil::estimator::guidance

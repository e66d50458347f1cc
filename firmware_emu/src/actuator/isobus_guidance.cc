#include "hil/firmware_emu/actuator/isobus_guidance.h"

#include <cmath>

#include "hil/firmware_emu/little_endian.h"

namespace hil::actuator {
namespace {

constexpr std::uint64_t kDistanceRawModulus = 4211081216ULL;  // valid raw 0 … 4 211 081 215
constexpr std::uint32_t kSpeedRawMax = 64255;

CanFrame Blank(Time t, std::uint32_t id) {
  CanFrame f;
  f.t = t;
  f.id = id;
  f.extended = true;
  f.len = 8;
  for (int i = 0; i < 8; ++i) f.data[i] = 0xFF;
  return f;
}

}  // namespace

std::uint16_t EncodeCurvatureRaw(double curvature_per_km) {
  const double r = std::round((curvature_per_km - kCurvatureOffset_per_km) /
                              kCurvatureResolution_per_km);  // half away from zero
  if (!(r > 0)) return 0;
  if (r > kCurvatureRawMax) return kCurvatureRawMax;
  return static_cast<std::uint16_t>(r);
}

double CurvatureFromRaw(std::uint16_t raw) {
  return raw * kCurvatureResolution_per_km + kCurvatureOffset_per_km;
}

J1939IdFields SplitJ1939Id(std::uint32_t id29) {
  J1939IdFields f;
  f.priority = static_cast<std::uint8_t>((id29 >> 26) & 7);
  f.source = static_cast<std::uint8_t>(id29 & 0xFF);
  const std::uint32_t pf = (id29 >> 16) & 0xFF;
  const std::uint32_t dp = (id29 >> 24) & 3;
  if (pf < 240) {
    f.pgn = (dp << 16) | (pf << 8);
    f.destination = static_cast<std::uint8_t>((id29 >> 8) & 0xFF);
  } else {
    f.pgn = (dp << 16) | (pf << 8) | ((id29 >> 8) & 0xFF);
    f.destination = 0xFF;
  }
  return f;
}

std::uint32_t MakeJ1939Id(std::uint8_t priority, std::uint32_t pgn, std::uint8_t source,
                          std::uint8_t destination) {
  std::uint32_t pgn_field = pgn & 0x3FFFF;
  if (((pgn_field >> 8) & 0xFF) < 240) pgn_field = (pgn_field & 0x3FF00) | destination;
  return (static_cast<std::uint32_t>(priority & 7) << 26) | (pgn_field << 8) | source;
}

CommandFrameError DecodeGuidanceSystemCommand(const CanFrame& frame, GuidanceSystemCommand& out) {
  if (frame.len != 8) return CommandFrameError::kWrongLength;
  out.curvature_raw = LeRead<std::uint16_t>(frame.data.data());
  out.status = static_cast<CurvatureCommandStatus>(frame.data[2] & 3);
  out.curvature_per_km = CurvatureFromRaw(out.curvature_raw);
  if (out.curvature_raw > kCurvatureRawMax) return CommandFrameError::kCurvatureOutOfRange;
  return CommandFrameError::kNone;
}

CanFrame EncodeGuidanceMachineInfo(Time t, std::uint8_t priority, std::uint8_t source,
                                   std::uint8_t destination, const GuidanceMachineInfo& info) {
  CanFrame f = Blank(t, MakeJ1939Id(priority, kPgnGuidanceMachineInfo, source, destination));
  LePut(f.data, 0, EncodeCurvatureRaw(info.estimated_curvature_per_km), 2);
  f.data[2] = static_cast<std::uint8_t>((info.mechanical_system_lockout & 3) |
                                        ((info.steering_system_readiness & 3) << 2) |
                                        ((info.steering_input_position_status & 3) << 4) |
                                        ((info.request_reset_command_status & 3) << 6));
  f.data[3] = static_cast<std::uint8_t>(0x1F | ((info.guidance_limit_status & 7) << 5));
  f.data[4] = static_cast<std::uint8_t>((info.exit_reason_code & 0x3F) |
                                        ((info.remote_engage_switch_status & 3) << 6));
  return f;
}

CanFrame EncodeWheelBasedSpeedDistance(Time t, std::uint8_t priority, std::uint8_t source,
                                       const WheelBasedSpeedDistance& msg) {
  CanFrame f = Blank(t, MakeJ1939Id(priority, kPgnWheelBasedSpeedDistance, source, 0xFF));
  const double speed_raw = std::round(std::fabs(msg.speed_mps) * 1000.0);
  LePut(f.data, 0, speed_raw > kSpeedRawMax ? kSpeedRawMax : static_cast<std::uint32_t>(speed_raw),
        2);
  const double d_raw = std::round(std::fabs(msg.distance_m) * 1000.0);
  const auto d = static_cast<std::uint64_t>(d_raw) % kDistanceRawModulus;
  LePut(f.data, 2, d, 4);
  f.data[6] = msg.max_time_of_tractor_power_min;
  f.data[7] = static_cast<std::uint8_t>((msg.direction & 3) | ((msg.key_switch & 3) << 2) |
                                        ((msg.implement_start_stop & 3) << 4) |
                                        ((msg.operator_direction_reversed & 3) << 6));
  return f;
}

}  // namespace hil::actuator

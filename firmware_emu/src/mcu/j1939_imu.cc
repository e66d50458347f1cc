#include "hil/firmware_emu/mcu/j1939_imu.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/little_endian.h"

namespace hil::mcu {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr std::uint32_t kMax16 = 0xFAFF;  // highest valid value of a 16-bit J1939 parameter
constexpr std::uint32_t kMax24 = 0xFAFFFF;

std::uint32_t Raw(double value, double resolution, double offset, std::uint32_t max_raw) {
  const double r = std::round((value - offset) / resolution);
  if (r < 0) return 0;
  if (r > max_raw) return max_raw;
  return static_cast<std::uint32_t>(r);
}

std::uint8_t LatencyByte(double latency_s) {
  return static_cast<std::uint8_t>(std::clamp(std::lround(latency_s * 1e3 / 0.5), 0L, 250L));
}

CanFrame Base(Time t, const J1939Address& a, std::uint32_t pgn) {
  CanFrame f;
  f.t = t;
  f.id = J1939Id(a, pgn);
  f.extended = true;
  f.len = 8;
  return f;
}

std::uint8_t FomByte(const FiguresOfMerit& fom) {
  return static_cast<std::uint8_t>((fom[0] & 3) | ((fom[1] & 3) << 2) | ((fom[2] & 3) << 4) |
                                   (3 << 6));
}

}  // namespace

std::uint32_t J1939Id(const J1939Address& a, std::uint32_t pgn) {
  return (static_cast<std::uint32_t>(a.priority & 7) << 26) | ((pgn & 0x3FFFF) << 8) |
         a.source_address;
}

CanFrame EncodeAri(Time t, const J1939Address& a, const Eigen::Vector3d& w_I_radps,
                   const FiguresOfMerit& fom, double latency_s) {
  CanFrame f = Base(t, a, kPgnAri);
  const double res = 1.0 / 128.0, off = -250.0;
  LePut(f.data, 0, Raw(-w_I_radps.y() * kRadToDeg, res, off, kMax16), 2);
  LePut(f.data, 2, Raw(w_I_radps.x() * kRadToDeg, res, off, kMax16), 2);
  LePut(f.data, 4, Raw(w_I_radps.z() * kRadToDeg, res, off, kMax16), 2);
  f.data[6] = FomByte(fom);
  f.data[7] = LatencyByte(latency_s);
  return f;
}

CanFrame EncodeAccs(Time t, const J1939Address& a, const Eigen::Vector3d& f_I_mps2,
                    const FiguresOfMerit& fom, double latency_s) {
  CanFrame f = Base(t, a, kPgnAccs);
  const double res = 0.01, off = -320.0;
  LePut(f.data, 0, Raw(f_I_mps2.y(), res, off, kMax16), 2);
  LePut(f.data, 2, Raw(f_I_mps2.x(), res, off, kMax16), 2);
  LePut(f.data, 4, Raw(f_I_mps2.z(), res, off, kMax16), 2);
  f.data[6] = FomByte(fom);
  f.data[7] = LatencyByte(latency_s);
  return f;
}

Eigen::Vector2d PitchRollDegFromSpecificForce(const Eigen::Vector3d& f) {
  const double pitch = std::atan2(f.x(), std::hypot(f.y(), f.z()));
  const double roll = std::atan2(f.y(), f.z());
  return {pitch * kRadToDeg, roll * kRadToDeg};
}

CanFrame EncodeSsi2(Time t, const J1939Address& a, const Eigen::Vector3d& f_I_mps2,
                    std::uint8_t pitch_fom, std::uint8_t roll_fom, double latency_s) {
  CanFrame f = Base(t, a, kPgnSsi2);
  const Eigen::Vector2d pr = PitchRollDegFromSpecificForce(f_I_mps2);
  const double res = 1.0 / 32768.0, off = -250.0;
  LePut(f.data, 0, Raw(pr[0], res, off, kMax24), 3);
  LePut(f.data, 3, Raw(pr[1], res, off, kMax24), 3);
  constexpr std::uint8_t kCompensationNotAvailable = 3;
  f.data[6] = static_cast<std::uint8_t>(kCompensationNotAvailable | ((pitch_fom & 3) << 2) |
                                        (kCompensationNotAvailable << 4) | ((roll_fom & 3) << 6));
  f.data[7] = LatencyByte(latency_s);
  return f;
}

CanFrame EncodeHilTimePulse(Time t, const J1939Address& a, std::uint32_t tick, bool valid,
                            std::uint32_t tow_s, int gps_week) {
  CanFrame f = Base(t, a, kPgnHilTimePulse);
  LePut(f.data, 0, tick, 4);
  const std::uint64_t tow = valid ? (tow_s & 0xFFFFFu) : 0xFFFFFu;
  const std::uint64_t week = static_cast<std::uint64_t>(gps_week) & 0xFFFu;
  const std::uint64_t hi = tow | (week << 20);
  LePut(f.data, 4, hi, 4);
  return f;
}

}  // namespace hil::mcu

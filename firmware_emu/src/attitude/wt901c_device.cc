#include "hil/firmware_emu/attitude/wt901c_device.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/attitude/wit_packet.h"
#include "hil/firmware_emu/little_endian.h"

namespace hil::wit {
namespace {

constexpr double kRadToDeg = 180.0 / std::numbers::pi;
constexpr std::uint16_t kUnlockKey = 0xB588;
constexpr std::uint16_t kRateSingle = 0x0C, kRateNone = 0x0D;
constexpr std::uint16_t kCalZeroYaw = 4;
constexpr Time kNever = Time::max();

bool KnownRate(std::uint16_t code) {
  return RateHzOfCode(code) > 0 || code == kRateSingle || code == kRateNone;
}

}  // namespace

Wt901cDevice::Wt901cDevice(const Wt901cConfig& config, std::uint64_t seed)
    : config_(config), rng_(seed) {
  if (!KnownRate(config_.rrate_code)) throw std::invalid_argument("WT901C: unknown RRATE code");
  if (BaudOfCode(config_.baud_code) == 0) throw std::invalid_argument("WT901C: unknown BAUD code");
  LoadDefaults();
  flash_ = regs_;
  PowerOn(Time{});
}

void Wt901cDevice::LoadDefaults() {
  regs_.fill(0);
  regs_[kRsw] = config_.rsw;
  regs_[kRrate] = config_.rrate_code;
  regs_[kBaud] = config_.baud_code;
  regs_[0x1A] = 0x50;  // IICADDR
  regs_[0x1F] = 4;     // BANDWIDTH 21 Hz
  regs_[kVersion] = config_.version;
}

void Wt901cDevice::PowerOn(Time t) {
  power_on_ = t;
  const Wt901cErrors& e = config_.errors;
  for (int i = 0; i < 3; ++i) gyro_bias_dps_[i] = e.gyro_turn_on_bias_sigma_dps * rng_.Normal();
  yaw_drift_dps_ = e.yaw_drift_sigma_dps * rng_.Normal();
  yaw_offset_deg_ = 0;
  single_pending_ = false;
  Schedule(t);
}

double Wt901cDevice::effective_rate_hz() const {
  const double rate = RateHzOfCode(regs_[kRrate]);
  const int packets = std::popcount(static_cast<unsigned>(regs_[kRsw] & 0x001Eu));
  if (rate <= 0 || packets == 0) return 0;
  // 10 bits per byte (8N1): the module lowers its rate to what the line carries.
  const double max_cycles = BaudOfCode(regs_[kBaud]) / (10.0 * kPacketSize * packets);
  return std::min(rate, max_cycles);
}

void Wt901cDevice::Schedule(Time from) {
  const double rate = effective_rate_hz();
  next_cycle_ = rate > 0 ? from + PeriodFromHz(rate) : kNever;
}

std::array<std::int16_t, 4> Wt901cDevice::AnglesRaw(const TruthSample& truth) {
  const Eigen::Matrix3d r = truth.q_NB.toRotationMatrix();
  const double roll = std::atan2(r(2, 1), r(2, 2)) * kRadToDeg;
  const double pitch = std::asin(std::clamp(-r(2, 0), -1.0, 1.0)) * kRadToDeg;
  const double yaw =
      std::atan2(r(1, 0), r(0, 0)) * kRadToDeg + yaw_drift_dps_ * ToSeconds(truth.t - power_on_);
  last_yaw_deg_ = yaw;
  const double s = config_.errors.angle_noise_sigma_deg;
  cycle_.angle_deg = {roll + s * rng_.Normal(), pitch + s * rng_.Normal(),
                      yaw - yaw_offset_deg_ + s * rng_.Normal()};
  return {AngleToRaw(cycle_.angle_deg[0]), AngleToRaw(cycle_.angle_deg[1]),
          AngleToRaw(cycle_.angle_deg[2]), static_cast<std::int16_t>(regs_[kVersion])};
}

std::array<std::int16_t, 4> Wt901cDevice::Quantise(const Eigen::Vector3d& v, double full_scale,
                                                   std::int16_t d3) {
  return {ScaleToRaw(v[0], full_scale), ScaleToRaw(v[1], full_scale), ScaleToRaw(v[2], full_scale),
          d3};
}

void Wt901cDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  const Wt901cErrors& e = config_.errors;
  const auto temp =
      static_cast<std::int16_t>(std::lround(config_.temperature_c / kTemperatureLsb_c));
  const Eigen::Vector3d noise_a(rng_.Normal(), rng_.Normal(), rng_.Normal());
  cycle_.accel_g = truth.f_B_mps2 / kStandardGravity_mps2 + e.accel_noise_sigma_g * noise_a;
  const Eigen::Vector3d noise_w(rng_.Normal(), rng_.Normal(), rng_.Normal());
  cycle_.rate_dps = truth.w_IB_B_radps * kRadToDeg + gyro_bias_dps_ +
                    e.gyro_noise_density_dps_rthz * std::sqrt(e.gyro_bandwidth_hz) * noise_w;
  const std::array<std::int16_t, 4> angle = AnglesRaw(truth);
  const Eigen::Vector3d noise_h(rng_.Normal(), rng_.Normal(), rng_.Normal());
  cycle_.mag_counts =
      truth.q_NB.conjugate() * config_.mag_N_counts + e.mag_noise_sigma_counts * noise_h;
  const std::array<std::array<std::int16_t, 4>, 4> packets = {
      Quantise(cycle_.accel_g, kAccelFullScale_g, temp),
      Quantise(cycle_.rate_dps, kRateFullScale_dps, temp), angle,
      Quantise(cycle_.mag_counts, 32768.0, temp)};
  static constexpr std::array<std::size_t, 4> kDataRegister = {kAx, kGx, kRoll, kHx};
  for (std::size_t k = 0; k < 4; ++k) {
    std::copy_n(packets[k].begin(), 3,
                regs_.begin() + static_cast<std::ptrdiff_t>(kDataRegister[k]));
    if (regs_[kRsw] & (0x0002u << k))
      SendPacket(t, static_cast<std::uint8_t>(0x51 + k), packets[k], out);
  }
  regs_[kTemp] = static_cast<std::uint16_t>(temp);
  ++stats_.cycles;
  if (single_pending_) {
    single_pending_ = false;
    next_cycle_ = kNever;
  } else {
    const double rate = effective_rate_hz();
    next_cycle_ = rate > 0 ? t + PeriodFromHz(rate) : kNever;
  }
}

void Wt901cDevice::SendPacket(Time t, std::uint8_t type, const std::array<std::int16_t, 4>& d,
                              DeviceOutput& out) {
  static constexpr const char* kNames[] = {"WIT-ACC", "WIT-GYRO", "WIT-ANGLE", "WIT-MAG"};
  const char* name = type >= 0x51 && type <= 0x54 ? kNames[type - 0x51] : "WIT-READ";
  out.serial.push_back({t, 0, EncodePacket(type, d), name});
  ++stats_.packets;
}

void Wt901cDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  (void)port;
  host_buf_.append(bytes);
  std::size_t i = 0;
  while (i + 2 <= host_buf_.size()) {
    if (static_cast<unsigned char>(host_buf_[i]) != 0xFF ||
        static_cast<unsigned char>(host_buf_[i + 1]) != 0xAA) {
      ++stats_.host_garbage_bytes;
      ++i;
      continue;
    }
    if (i + 5 > host_buf_.size()) break;
    const auto b = [&](std::size_t k) { return static_cast<unsigned char>(host_buf_[i + k]); };
    HandleCommand(t, b(2), LeRead<std::uint16_t>(host_buf_, i + 3), out);
    i += 5;
  }
  host_buf_.erase(0, i);
}

void Wt901cDevice::HandleCommand(Time t, std::uint8_t reg, std::uint16_t value, DeviceOutput& out) {
  ++stats_.commands;
  if (reg == kKey) {
    regs_[kKey] = value;
    unlocked_until_ = value == kUnlockKey ? t + config_.unlock_window : Time{};
    return;
  }
  if (reg == kReadAddr) {  // reads need no unlock (the SDK reads without one)
    std::array<std::int16_t, 4> d{};
    for (std::size_t k = 0; k < 4; ++k) {
      const std::size_t a = std::size_t{value} + k;
      d[k] = a < kRegisterCount ? static_cast<std::int16_t>(regs_[a]) : 0;
    }
    SendPacket(t + config_.read_latency, 0x5F, d, out);
    ++stats_.read_replies;
    return;
  }
  if (config_.require_unlock && t > unlocked_until_) {
    ++stats_.writes_rejected_locked;
    return;
  }
  if (reg >= kRegisterCount) return;
  switch (reg) {
    case kSave:
      if (value == 0x0000) {
        flash_ = regs_;
        ++stats_.saves;
      } else if (value == 0x00FF) {
        regs_ = flash_;
        ++stats_.reboots;
        PowerOn(t);
      } else if (value == 0x0001) {
        LoadDefaults();  // factory defaults (in RAM until saved), then a new power-on
        ++stats_.reboots;
        PowerOn(t);
      }
      return;
    case kCalsw:
      regs_[kCalsw] = value;
      if (value == kCalZeroYaw) yaw_offset_deg_ = last_yaw_deg_;
      return;
    case kRrate:
      if (!KnownRate(value)) return;
      regs_[kRrate] = value;
      single_pending_ = value == kRateSingle;
      if (single_pending_)
        next_cycle_ = t + config_.read_latency;
      else
        Schedule(t);
      return;
    case kBaud:  // takes effect at once (UNVERIFIED, vectors/wt901c/README.md)
      if (BaudOfCode(value) == 0) return;
      regs_[kBaud] = value;
      Schedule(t);
      return;
    case kRsw:
      regs_[kRsw] = value;
      Schedule(t);
      return;
    default:
      regs_[reg] = value;
  }
}

}  // namespace hil::wit

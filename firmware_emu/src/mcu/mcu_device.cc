#include "hil/firmware_emu/mcu/mcu_device.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/mcu/imu_kinematics.h"
#include "hil/firmware_emu/mcu/mcu_frame.h"
#include "hil/firmware_emu/mcu/razor_text.h"

namespace hil::mcu {
namespace {

constexpr std::int64_t kNsPerS = 1000000000;
constexpr Duration kPulseSeenWindow = std::chrono::milliseconds(1500);
constexpr std::uint8_t kResetCausePowerOn = 0;
constexpr std::uint8_t kResetCauseExternal = 3;

// splitmix64: independent seeds for the device's random streams
std::uint64_t DeriveSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t z = seed + 0x9E3779B97F4A7C15ULL * (stream + 1);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  return z ^ (z >> 31);
}

const McuConfig& Validated(const McuConfig& c) {
  if (!(c.imu_rate_hz > 0 && c.imu_rate_hz <= 10000))
    throw std::invalid_argument("mcu: imu_rate_hz must be in (0, 10000]");
  if (!(c.mag_rate_hz > 0 && c.mag_rate_hz <= 1000))
    throw std::invalid_argument("mcu: mag_rate_hz must be in (0, 1000]");
  if (std::abs(c.crystal_ppm) > 10000) throw std::invalid_argument("mcu: crystal_ppm out of range");
  if (c.baud <= 0) throw std::invalid_argument("mcu: baud must be positive");
  if (c.rough.front_end_enabled() && c.rough.internal_rate_hz < 4 * c.imu_rate_hz)
    throw std::invalid_argument("mcu: rough.internal_rate_hz must be >= 4 x imu_rate_hz");
  if (c.rough.time_tag.latency_s < 0 || c.rough.time_tag.jitter_s < 0)
    throw std::invalid_argument("mcu: time tag latency and jitter must be >= 0");
  if (c.can.ari_every < 1 || c.can.accs_every < 1 || c.can.ssi2_every < 1)
    throw std::invalid_argument("mcu: CAN dividers must be >= 1");
  return c;
}

TriadSpec GyroSpecFor(const McuConfig& c) {
  TriadSpec g = c.profile.gyro;
  // the stock Razor firmware reads each gyro with one analogRead per sample
  if (c.format != SerialFormat::kBinary) g.counts.oversample = 1;
  return g;
}

FrontEndLimits LimitsFor(const McuConfig& c, const TriadSpec& gyro) {
  FrontEndLimits l;
  l.accel_range_mps2 = c.profile.accel.counts.range;
  l.gyro_range_radps = gyro.counts.range;
  l.accel_aaf_hz =
      c.rough.accel_aaf_hz > 0 ? c.rough.accel_aaf_hz : c.profile.accel.error.bandwidth_hz;
  l.gyro_aaf_hz = c.rough.gyro_aaf_hz > 0 ? c.rough.gyro_aaf_hz : gyro.error.bandwidth_hz;
  return l;
}

std::array<int, 3> Ints(const TriadCounts& c, int add = 0) {
  return {c.counts[0] + add, c.counts[1] + add, c.counts[2] + add};
}

Eigen::Vector3d Engineering(const TriadCounts& c, double lsb) {
  return Eigen::Vector3d(c.counts[0], c.counts[1], c.counts[2]) * lsb;
}

FiguresOfMerit Fom(const TriadCounts& c) {
  return {static_cast<std::uint8_t>(c.saturated[0] ? 1 : 0),
          static_cast<std::uint8_t>(c.saturated[1] ? 1 : 0),
          static_cast<std::uint8_t>(c.saturated[2] ? 1 : 0)};
}

}  // namespace

McuDevice::McuDevice(const McuConfig& config, std::uint64_t seed)
    : config_(Validated(config)),
      timing_rng_(DeriveSeed(seed, 0)),
      fault_rng_(DeriveSeed(seed, 1)),
      accel_(config.profile.accel, std::round(1e6 / config.imu_rate_hz) * 1e-6,
             DeriveSeed(seed, 2)),
      gyro_(GyroSpecFor(config), std::round(1e6 / config.imu_rate_hz) * 1e-6, DeriveSeed(seed, 3)),
      mag_(config.profile.mag, 1.0 / config.mag_rate_hz, DeriveSeed(seed, 4)),
      tick_hz_(kNominalTickHz * (1.0 + config.crystal_ppm * 1e-6)),
      imu_period_ticks_(static_cast<std::uint32_t>(std::lround(1e6 / config.imu_rate_hz))),
      mag_period_(DurationFromSeconds(
          1.0 / (config.mag_rate_hz * (1.0 + config.mag_oscillator_ppm * 1e-6)))),
      tag_rng_(DeriveSeed(seed, 6)) {
  if (config_.rough.front_end_enabled())
    front_end_.emplace(config_.rough, LimitsFor(config_, GyroSpecFor(config_)),
                       DeriveSeed(seed, 5));
  accel_.SetVibration(config_.vibration, true);
  gyro_.SetVibration(config_.vibration, false);
  for (const McuFault& f : config_.faults)
    if (f.kind == FaultKind::kReset) {
      resets_.emplace_back(f.start, f.duration > Duration{0} ? f.duration : config_.reboot);
    }
  std::sort(resets_.begin(), resets_.end());
  jump_applied_.assign(config_.faults.size(), false);
  // first whole GPS second at or after t = 0
  const gnss::GpsWeekTime g0 = gnss::GpsFrom(config_.start_utc);
  const std::int64_t rem = g0.tow_ns % kNsPerS;
  next_pps_ = TimeFromNs(rem == 0 ? 0 : kNsPerS - rem);
  next_mag_ = Time{} + config_.first_sample_delay;
  reset_cause_ = kResetCausePowerOn;
  pending_boot_ = Time{};
  up_ = false;
}

std::uint32_t McuDevice::TickAt(Time t) const {
  const double ticks = std::floor(static_cast<double>(ToNs(t) - ToNs(boot_)) * tick_hz_ * 1e-9);
  const auto n = static_cast<std::int64_t>(ticks);
  return static_cast<std::uint32_t>(static_cast<std::uint64_t>(n) & 0xFFFFFFFFULL);
}

Time McuDevice::next_event_time() const {
  Time t = next_mag_;
  if (up_) t = std::min(t, next_imu_);
  if (config_.time_pulse) t = std::min(t, next_pps_);
  if (pending_boot_) t = std::min(t, *pending_boot_);
  if (!resets_.empty()) t = std::min(t, resets_.front().first);
  if (!pending_imu_.empty()) t = std::min(t, pending_imu_.front().t_tag);
  return t;
}

void McuDevice::Boot(Time t_boot) {
  up_ = true;
  pending_boot_.reset();
  boot_ = t_boot;
  sequence_ = 0;
  last_pulse_.reset();  // RAM is cleared by a reset
  imu_index_ = 0;
  pending_imu_.clear();  // samples read but not yet sent are lost with the RAM
  ScheduleImu();
}

void McuDevice::ScheduleImu() {
  const double first_ticks = std::round(ToSeconds(config_.first_sample_delay) * 1e6);
  const double tick = first_ticks + static_cast<double>(imu_index_) * imu_period_ticks_;
  // the sample timer runs on the MCU's crystal, or on the IMU's own oscillator when it has one
  const double sample_clock_hz =
      config_.rough.time_tag.imu_clock_ppm != 0
          ? kNominalTickHz * (1.0 + config_.rough.time_tag.imu_clock_ppm * 1e-6)
          : tick_hz_;
  const auto offset_ns = static_cast<std::int64_t>(std::llround(tick * 1e9 / sample_clock_hz));
  const auto jitter_ns =
      static_cast<std::int64_t>(std::llround(timing_rng_.Uniform() * config_.jitter_us * 1e3));
  next_imu_ = boot_ + Duration{offset_ns + jitter_ns};
}

void McuDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  if (!resets_.empty() && resets_.front().first == t) {
    pending_boot_ = t + resets_.front().second;
    resets_.erase(resets_.begin());
    up_ = false;
    pending_imu_.clear();
    reset_cause_ = kResetCauseExternal;
    ++reset_count_;
    ++stats_.resets;
  }
  if (pending_boot_ && *pending_boot_ == t) {
    Boot(t);
    SendStatus(t, out);
  }
  if (config_.time_pulse && next_pps_ == t) {
    if (up_) OnTimePulse(t, out);
    next_pps_ += std::chrono::seconds(1);
  }
  while (up_ && !pending_imu_.empty() && pending_imu_.front().t_tag == t) {
    const PendingImu p = pending_imu_.front();
    pending_imu_.pop_front();
    EmitImu(t, p.accel, p.gyro, p.index, out);
  }
  if (up_ && next_imu_ == t) {
    OnImuSample(truth, out);
    ++imu_index_;
    ScheduleImu();
  }
  if (next_mag_ == t) {
    OnMagSample(truth);
    if (up_ && config_.format == SerialFormat::kBinary) {
      MagSamplePayload p;
      p.mag = last_mag_.counts;
      const std::uint16_t seq = NextSequence(t);
      SendSerial(t, EncodeMagSample(seq, TickAt(t), p), "MCU-MAG", out);
    }
    next_mag_ += mag_period_;
  }
}

std::uint16_t McuDevice::NextSequence(Time t) {
  for (std::size_t i = 0; i < config_.faults.size(); ++i) {
    const McuFault& f = config_.faults[i];
    if (f.kind == FaultKind::kSequenceJump && !jump_applied_[i] && f.start <= t) {
      sequence_ = static_cast<std::uint16_t>(sequence_ + f.amount);
      jump_applied_[i] = true;
    }
  }
  return sequence_++;
}

bool McuDevice::ActiveFault(FaultKind kind, Time t, const McuFault** which) const {
  for (const McuFault& f : config_.faults) {
    if (f.kind != kind) continue;
    if (t >= f.start && t < f.start + f.duration) {
      if (which) *which = &f;
      return true;
    }
  }
  return false;
}

bool McuDevice::Stuck(const char* sensor, Time t) const {
  for (const McuFault& f : config_.faults) {
    if (f.kind != FaultKind::kStuckSensor || (f.sensor != "all" && f.sensor != sensor)) continue;
    if (t >= f.start && t < f.start + f.duration) return true;
  }
  return false;
}

void McuDevice::SendSerial(Time t_sample, std::string bytes, const char* what, DeviceOutput& out) {
  const McuFault* f = nullptr;
  if (ActiveFault(FaultKind::kDropFrames, t_sample, &f) && fault_rng_.Uniform() < f->probability) {
    ++stats_.frames_dropped;
    return;
  }
  if (ActiveFault(FaultKind::kCorruptBytes, t_sample, &f) &&
      fault_rng_.Uniform() < f->probability && !bytes.empty()) {
    const auto pos =
        static_cast<std::size_t>(fault_rng_.Uniform() * static_cast<double>(bytes.size()));
    const auto flip =
        static_cast<unsigned char>(1 + static_cast<int>(fault_rng_.Uniform() * 255.0));
    bytes[pos] = static_cast<char>(static_cast<unsigned char>(bytes[pos]) ^ flip);
    ++stats_.frames_corrupted;
  }
  out.serial.push_back({t_sample + config_.output_lag, 0, std::move(bytes), what});
}

double McuDevice::TemperatureAt(double t_s) const {
  return InterpolateProfile(
      config_.rough.temperature_profile, t_s,
      config_.temperature_c + config_.temperature_rate_c_per_h * t_s / 3600.0);
}

void McuDevice::OnImuSample(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  const double temp = TemperatureAt(ToSeconds(t));
  const IdealImu ideal = IdealImuFromTruth(truth, config_.mounting, config_.magnetic);
  const double g_sens = gyro_.spec().error.g_sensitivity_radps_per_mps2;
  TriadCounts a, g;
  if (front_end_) {
    Eigen::Vector3d f_bl, w_bl;
    front_end_->SetGroundSpeed(truth.speed_mps);
    front_end_->Advance(t, ideal.f_I_mps2, ideal.w_I_radps, f_bl, w_bl);
    a = accel_.Quantise(accel_.MeasureBandLimited(f_bl, Eigen::Vector3d::Zero(), temp));
    g = gyro_.Quantise(gyro_.MeasureBandLimited(w_bl, g_sens * f_bl, temp));
  } else {
    a = accel_.Sample(ideal.f_I_mps2, t, temp);
    g = g_sens != 0 ? gyro_.Sample(ideal.w_I_radps + g_sens * ideal.f_I_mps2, t, temp)
                    : gyro_.Sample(ideal.w_I_radps, t, temp);
  }
  if (have_accel_ && Stuck("accel", t)) a = last_accel_;
  if (have_gyro_ && Stuck("gyro", t)) g = last_gyro_;
  last_accel_ = a, last_gyro_ = g;
  have_accel_ = have_gyro_ = true;
  ++stats_.imu_samples;
  const TimeTagSpec& tag = config_.rough.time_tag;
  if (tag.latency_s > 0 || tag.jitter_s > 0) {
    // the sample is read (and tagged) later than it was sensed; tags never go backwards
    Time t_tag = t + DurationFromSeconds(tag.latency_s + tag.jitter_s * tag_rng_.Uniform());
    if (!pending_imu_.empty()) t_tag = std::max(t_tag, pending_imu_.back().t_tag);
    pending_imu_.push_back({t_tag, a, g, imu_index_});
    return;
  }
  EmitImu(t, a, g, imu_index_, out);
}

void McuDevice::EmitImu(Time t, const TriadCounts& a, const TriadCounts& g, std::uint64_t index,
                        DeviceOutput& out) {
  switch (config_.format) {
    case SerialFormat::kBinary: {
      ImuSamplePayload p;
      p.accel = a.counts;
      p.gyro = g.counts;
      const std::uint16_t seq = NextSequence(t);
      SendSerial(t, EncodeImuSample(seq, TickAt(t), p), "MCU-IMU", out);
      break;
    }
    case SerialFormat::kRazorRaw:
    case SerialFormat::kRazorV19: {
      const auto fmt =
          config_.format == SerialFormat::kRazorRaw ? RazorTextFormat::kRaw : RazorTextFormat::kV19;
      SendSerial(t,
                 EncodeRazorLine(fmt, Ints(a), Ints(g, gyro_.spec().counts.nominal_zero_count),
                                 Ints(last_mag_)),
                 "RAZOR-TEXT", out);
      break;
    }
  }

  if (!config_.can.enabled) return;
  const CanOutputConfig& c = config_.can;
  const Time t_bus = t + DurationFromSeconds(c.latency_s);
  const Eigen::Vector3d f = Engineering(a, accel_.output_lsb());
  const Eigen::Vector3d w = Engineering(g, gyro_.output_lsb());
  if (index % static_cast<std::uint64_t>(c.ari_every) == 0)
    out.can.push_back(EncodeAri(t_bus, c.address, w, Fom(g), c.latency_s));
  if (index % static_cast<std::uint64_t>(c.accs_every) == 0)
    out.can.push_back(EncodeAccs(t_bus, c.address, f, Fom(a), c.latency_s));
  if (index % static_cast<std::uint64_t>(c.ssi2_every) == 0) {
    const std::uint8_t fom = (a.saturated[0] || a.saturated[1] || a.saturated[2]) ? 1 : 0;
    out.can.push_back(EncodeSsi2(t_bus, c.address, f, fom, fom, c.latency_s));
  }
}

void McuDevice::OnMagSample(const TruthSample& truth) {
  const Time t = truth.t;
  const double temp = TemperatureAt(ToSeconds(t));
  const IdealImu ideal = IdealImuFromTruth(truth, config_.mounting, config_.magnetic);
  TriadCounts m = mag_.Sample(ideal.mag_I_uT, t, temp);
  if (have_mag_ && Stuck("mag", t)) m = last_mag_;
  last_mag_ = m;
  have_mag_ = true;
  ++stats_.mag_samples;
}

void McuDevice::OnTimePulse(Time t, DeviceOutput& out) {
  const std::uint32_t latched = TickAt(t);
  const gnss::GpsWeekTime g = gnss::GpsFrom(UtcAt(config_.start_utc, t));
  const std::int64_t tow_s = (g.tow_ns + kNsPerS / 2) / kNsPerS;
  last_pulse_ = t;
  ++stats_.time_pulses;
  if (config_.format == SerialFormat::kBinary) {
    TimePulsePayload p;
    p.gps_week = static_cast<std::uint16_t>(g.week);
    p.tow_ms = static_cast<std::uint32_t>(tow_s * 1000);
    p.time_valid = true;
    const std::uint16_t seq = NextSequence(t);
    SendSerial(t, EncodeTimePulse(seq, latched, p), "MCU-TIME-PULSE", out);
    SendStatus(t, out);
  }
  if (config_.can.enabled && config_.can.time_pulse) {
    out.can.push_back(EncodeHilTimePulse(t + DurationFromSeconds(config_.can.latency_s),
                                         config_.can.address, latched, true,
                                         static_cast<std::uint32_t>(tow_s), g.week));
  }
}

void McuDevice::SendStatus(Time t, DeviceOutput& out) {
  if (config_.format != SerialFormat::kBinary) return;
  StatusPayload p;
  p.reset_cause = reset_cause_;
  p.pulse_seen = last_pulse_ && t - *last_pulse_ <= kPulseSeenWindow;
  p.reset_count = reset_count_;
  p.imu_period_ticks = imu_period_ticks_;
  p.accel_scale_mps2_per_lsb = static_cast<float>(accel_.output_lsb());
  p.gyro_scale_radps_per_lsb = static_cast<float>(gyro_.output_lsb());
  p.mag_scale_uT_per_lsb = static_cast<float>(mag_.output_lsb());
  p.profile = static_cast<std::uint8_t>(config_.profile.id);
  ++stats_.status_frames;
  const std::uint16_t seq = NextSequence(t);
  SendSerial(t, EncodeStatus(seq, TickAt(t), p), "MCU-STATUS", out);
}

}  // namespace hil::mcu

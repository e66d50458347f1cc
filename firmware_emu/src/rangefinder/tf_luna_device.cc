#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/angles.h"

namespace hil::rangefinder {
namespace {

constexpr Time kNever = Time::max();
bool ValidRate(std::uint16_t hz) { return hz <= 250; }

}  // namespace

TfLunaDevice::TfLunaDevice(const TfLunaConfig& config, const world::GreenhouseWorld& world,
                           std::uint64_t seed)
    : config_(config),
      world_(&world),
      rng_(seed),
      settings_(config.settings),
      flash_(config.settings),
      reader_([this](const CommandFrame& f) { pending_.push_back(f); }) {
  if (!ValidRate(settings_.frame_rate_hz))
    throw std::invalid_argument(config_.name + ": frame rate above 250 Hz");
  if (!IsSupportedBaud(settings_.baud))
    throw std::invalid_argument(config_.name + ": unsupported baud rate");
  Schedule(Time{});
}

double TfLunaDevice::effective_rate_hz() const {
  if (!settings_.output_enabled || settings_.frame_rate_hz == 0) return 0;
  // 500 internal measurements per second, one output per n of them (n ≥ 2)
  const long n = std::max(2L, std::lround(500.0 / settings_.frame_rate_hz));
  return 500.0 / static_cast<double>(n);
}

void TfLunaDevice::Schedule(Time from) {
  const double rate = effective_rate_hz();
  next_frame_ = trigger_pending_ ? from : rate > 0 ? from + PeriodFromHz(rate) : kNever;
}

Target TfLunaDevice::Sense(const TruthSample& truth) const {
  const Eigen::Matrix3d r = truth.q_NB.toRotationMatrix();
  const double yaw = std::atan2(r(1, 0), r(0, 0));
  const Eigen::Rotation2Dd rot(yaw);
  const RangefinderMount& m = config_.mount;
  world::Ray2 ray;
  ray.origin_m = truth.p_NB_N_m.head<2>() + rot * Eigen::Vector2d(m.x_m, m.y_m);
  const double beam = yaw + m.yaw_deg * kDeg;
  ray.dir = Eigen::Vector2d(std::cos(beam), std::sin(beam));
  const auto hit = world_->Cast(ray, m.z_m, config_.cast_range_m);
  Target t;
  if (!hit) return t;
  t.present = true;
  t.range_m = hit->range_m;
  t.cos_incidence = std::abs(hit->normal.dot(ray.dir));
  t.reflectivity = config_.reflectivity.Of(hit->kind);
  return t;
}

void TfLunaDevice::SendFrame(const TruthSample& truth, DeviceOutput& out) {
  target_ = Sense(truth);
  const double rate = std::max(effective_rate_hz(), 100.0);  // a triggered frame: 100 Hz averaging
  reading_ =
      Measure(config_.model, target_, rate, settings_.format, config_.chip_temperature_c, rng_);
  ++stats_.frames;
  if (!reading_.valid) ++stats_.invalid_frames;
  if (settings_.format == OutputFormat::kPixAscii) {
    out.serial.push_back({truth.t, 0, PixLine(reading_.fields.dist / 100.0), "TF-PIX"});
  } else {
    out.serial.push_back({truth.t, 0, FrameData(EncodeDataFields(reading_.fields)), "TF-DATA"});
  }
}

void TfLunaDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  now_ = truth.t;
  trigger_pending_ = false;
  SendFrame(truth, out);
  Schedule(truth.t);
}

void TfLunaDevice::Reply(std::string bytes, DeviceOutput& out) {
  out.serial.push_back({now_ + config_.reply_latency, 0, std::move(bytes), "TF-REPLY"});
  ++stats_.replies;
}

void TfLunaDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  (void)port;
  now_ = t;
  reader_.Feed(bytes);
  std::vector<CommandFrame> frames;
  frames.swap(pending_);
  for (const CommandFrame& f : frames) Handle(f, out);
}

}  // namespace hil::rangefinder

#include "hil/firmware_emu/lidar/rplidar_device.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/angles.h"

namespace hil::lidar {
namespace {

constexpr Time kNever = Time::max();
constexpr double kWhite = 0.9;

}  // namespace

RplidarDevice::RplidarDevice(const RplidarConfig& config, const world::GreenhouseWorld& world,
                             std::uint64_t seed)
    : config_(config),
      world_(&world),
      rng_(seed),
      reader_([this](const RequestFrame& r) { pending_.push_back(r); }),
      next_event_(kNever) {
  const auto& serial = config_.info.serial;
  if (std::all_of(serial.begin(), serial.end(), [](std::uint8_t b) { return b == 0; })) {
    for (auto& b : config_.info.serial) b = static_cast<std::uint8_t>(rng_.NextSeed() & 0xFFu);
  }
  StartMotor(Time{});  // the motor line is not visible on a pty: it spins from power-on
}

void RplidarDevice::StartMotor(Time t) {
  motor_on_ = true;
  motor_t0_ = t;
}

double RplidarDevice::AngleAt_deg(Time t) const {
  const double turns = config_.rotation_hz * ToSeconds(t - motor_t0_);
  return 360.0 * (turns - std::floor(turns));
}

Duration RplidarDevice::SamplePeriod() const {
  return std::chrono::microseconds(mode_ == Mode::kExpress ? config_.express_sample_us
                                                           : config_.standard_sample_us);
}

std::size_t RplidarDevice::SamplesPerEvent() const {
  return mode_ == Mode::kExpress ? kSamplesPerCapsule
                                 : std::max<std::size_t>(1, config_.nodes_per_message);
}

void RplidarDevice::StartScan(Mode mode, bool force) {
  mode_ = mode;
  const Time stable = motor_t0_ + config_.spin_up;
  const Time descriptor = now_ + config_.reply_latency;
  scan_t0_ = force ? descriptor : std::max(descriptor, stable);
  if (!motor_on_) {
    next_event_ = kNever;  // no samples until the motor turns (SET_MOTOR_PWM)
    return;
  }
  sample_index_ = 0;
  last_angle_deg_ = AngleAt_deg(scan_t0_);
  capsule_new_scan_ = true;
  next_event_ = scan_t0_ + SamplePeriod() * static_cast<std::int64_t>(SamplesPerEvent() - 1);
}

LidarSample RplidarDevice::Sample(const TruthSample& truth, Time t) {
  LidarSample s;
  s.t = t;
  s.angle_deg = AngleAt_deg(t);
  s.start = s.angle_deg < last_angle_deg_;  // the first sample of a new turn
  last_angle_deg_ = s.angle_deg;
  const double dt = ToSeconds(t - truth.t);
  const Eigen::Matrix3d r = truth.q_NB.toRotationMatrix();
  const double yaw = std::atan2(r(1, 0), r(0, 0)) + truth.w_NB_B_radps.z() * dt;
  const Eigen::Vector2d p = truth.p_NB_N_m.head<2>() + truth.v_NB_N_mps.head<2>() * dt;
  const LidarMount& m = config_.mount;
  world::Ray2 ray;
  ray.origin_m = p + Eigen::Rotation2Dd(yaw) * Eigen::Vector2d(m.x_m, m.y_m);
  const double beam = yaw + (m.yaw_deg - s.angle_deg) * kDeg;
  ray.dir = Eigen::Vector2d(std::cos(beam), std::sin(beam));
  const auto hit = world_->Cast(ray, m.z_m, config_.max_range_m);
  const double noise = rng_.Normal();  // one draw per sample, hit or not
  if (!hit) return s;
  s.true_range_m = hit->range_m;
  const double signal = config_.reflectivity.Of(hit->kind) * std::abs(hit->normal.dot(ray.dir)) /
                        std::max(hit->range_m * hit->range_m, 1e-6);
  const double snr = signal * config_.white_range_m * config_.white_range_m / kWhite;
  if (snr < 1 || hit->range_m < config_.min_range_m) return s;
  s.measured_m = std::max(0.0, hit->range_m * (1 + config_.range_sigma_fraction * noise));
  s.quality = static_cast<std::uint8_t>(std::clamp(15 + std::lround(10 * std::log2(snr)), 1L, 47L));
  return s;
}

void RplidarDevice::EmitNodes(const TruthSample& truth, DeviceOutput& out) {
  std::string bytes;
  for (const LidarSample& s : samples_) {
    ScanNode n;
    n.quality = s.quality;
    n.start = s.start;
    n.angle_q6 = static_cast<std::uint16_t>(std::lround(s.angle_deg * 64.0) % (360 * 64));
    n.distance_q2 =
        static_cast<std::uint16_t>(std::min(std::lround(s.measured_m * 4000.0), 65535L));
    bytes += EncodeNode(n);
    ++stats_.nodes;
  }
  out.serial.push_back({truth.t, 0, std::move(bytes), "RPLIDAR-NODES"});
}

void RplidarDevice::EmitCapsule(const TruthSample& truth, DeviceOutput& out) {
  ExpressCapsule c;
  c.start_angle_q6 =
      static_cast<std::uint16_t>(std::lround(samples_.front().angle_deg * 64.0) % (360 * 64));
  c.new_scan = capsule_new_scan_;
  capsule_new_scan_ = false;
  for (std::size_t k = 0; k < kSamplesPerCapsule; ++k)
    c.distance_mm[k] = static_cast<std::uint16_t>(std::lround(samples_[k].measured_m * 1000.0));
  out.serial.push_back({truth.t, 0, EncodeCapsule(c), "RPLIDAR-CAPSULE"});
  ++stats_.capsules;
}

void RplidarDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  now_ = truth.t;
  const std::size_t n = SamplesPerEvent();
  samples_.clear();
  for (std::size_t j = 0; j < n; ++j) {
    const Time t = scan_t0_ + SamplePeriod() * static_cast<std::int64_t>(sample_index_ + j);
    samples_.push_back(Sample(truth, t));
  }
  sample_index_ += n;
  if (mode_ == Mode::kExpress) {
    EmitCapsule(truth, out);
  } else {
    EmitNodes(truth, out);
  }
  next_event_ = scan_t0_ + SamplePeriod() * static_cast<std::int64_t>(sample_index_ + n - 1);
}

void RplidarDevice::Send(std::string bytes, const char* what, DeviceOutput& out) {
  out.serial.push_back({now_ + config_.reply_latency, 0, std::move(bytes), what});
}

void RplidarDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  (void)port;
  now_ = t;
  reader_.Feed(bytes);
  std::vector<RequestFrame> requests;
  requests.swap(pending_);
  for (const RequestFrame& r : requests) Handle(r, out);
}

}  // namespace hil::lidar

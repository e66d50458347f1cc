// navd's gyro + wheel-odometry mode (paper 001). The IMU's samples drive the filter and the
// solution clock; the encoder sentences are stamped with the solution they answer. At each
// solution after the first sentence navd first waits (up to [odometry] wait_s) for the sentence
// answering the solution before the previous one, so that every run applies the same encoder
// intervals before the same solutions whatever order the processes were scheduled in.
#include "odometry_mode.h"

#include <poll.h>
#include <time.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

#include "hil/estimator/angles.h"
#include "hil/estimator/drivers/line_splitter.h"
#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/navd/nav_solution.h"
#include "hil/estimator/odometry/encoder_sentence.h"
#include "hil/estimator/odometry/gyro_odometry_navigator.h"
#include "hil/estimator/outputs/nmea0183_writer.h"

#include "serial_device.h"

namespace hil::navd {
namespace {

namespace est = hil::estimator;
namespace odo = hil::estimator::odometry;
using estimator::kDeg;
constexpr std::int64_t kDayNs = 86400LL * 1'000'000'000LL;

odo::WheelOdometryConfig NavigatorConfig(const est::NavdOdometryConfig& c) {
  odo::WheelOdometryConfig w;
  w.wheel_radius_m = c.wheel_radius_m;
  w.track_m = c.track_m;
  w.counts_per_rev = c.counts_per_rev;
  w.align_s = c.align_s;
  w.initial_p_EN_m = {c.initial_e_m, c.initial_n_m};
  w.initial_yaw_rad = (90.0 - c.initial_heading_deg) * kDeg;
  w.filter.gyro_arw_rad_per_sqrt_s = c.gyro_arw;
  w.filter.gyro_bias_rw_radps_per_sqrt_s = c.gyro_bias_rw;
  w.filter.init_bias_std_radps = c.init_gyro_bias_std;
  w.filter.odo_yaw_std_rad = c.odo_yaw_std_rad;
  w.filter.odo_distance_std_fraction = c.odo_distance_std_fraction;
  w.filter.odo_lateral_std_fraction = c.odo_lateral_std_fraction;
  return w;
}

std::int64_t MonotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}

struct OdometryModeStats {
  std::uint64_t solutions = 0, sentences = 0, bad_sentences = 0, late = 0, unanswered = 0;
};

class OdometryNavd {
 public:
  OdometryNavd(const est::NavdConfig& cfg, std::FILE* out, int nmea_fd)
      : cfg_(cfg),
        out_(out),
        nmea_fd_(nmea_fd),
        origin_{cfg.odometry.origin_lat_deg, cfg.odometry.origin_lon_deg,
                cfg.odometry.origin_height_m},
        frame_(origin_),
        nav_(NavigatorConfig(cfg.odometry)),
        period_(std::llround(1e9 / cfg.output_rate_hz)) {}

  // Each IMU sample; returns true when a solution is due (the caller waits for the encoders).
  bool OnImu(const est::ImuSample& s) {
    nav_.OnImu(s);
    last_imu_t_ = s.t;
    if (!nav_.aligned()) return false;
    return !last_emitted_ ||
           s.t.time_since_epoch() / period_ != last_emitted_->time_since_epoch() / period_;
  }
  // True when the sentence answering the solution before the last is still to come: the
  // controller's request for solution k reaches the base at the harness's next control tick, so
  // its answer comes after solution k + 1 has gone out and before solution k + 2.
  bool AwaitingAnswer() const {
    return encoders_started_ && previous_emitted_ && !previous_answered_;
  }
  void OnOdometryBytes(std::string_view bytes) {
    lines_.Feed(bytes, [&](std::string_view l) { OnSentence(l); });
  }
  void Emit();
  OdometryModeStats& stats() { return stats_; }
  void PrintStats(const est::drivers::McuDecoderStats& mcu) const;

 private:
  void OnSentence(std::string_view line);

  const est::NavdConfig& cfg_;
  std::FILE* out_;
  int nmea_fd_;
  est::Lla origin_;
  est::LocalTangentFrame frame_;
  odo::GyroOdometryNavigator nav_;
  est::Nanoseconds period_;
  est::GpsTime last_imu_t_{};
  std::optional<est::GpsTime> last_emitted_, previous_emitted_;
  bool encoders_started_ = false, answered_ = false, previous_answered_ = false;
  est::drivers::LineSplitter<96> lines_;
  std::array<odo::EncoderSample, 16> queue_{};
  std::size_t queue_first_ = 0, queued_ = 0;
  OdometryModeStats stats_;
};

void OdometryNavd::OnSentence(std::string_view line) {
  const std::optional<odo::EncoderSentence> e = odo::ParseEncoderSentence(line);
  if (!e || !last_emitted_) {
    ++stats_.bad_sentences;
    return;
  }
  ++stats_.sentences;
  // the UTC day of the last solution; a time of day half a day away is the neighbouring day's
  const std::int64_t ref = est::UnixNsFromGpsTime(*last_emitted_, cfg_.leap_seconds);
  std::int64_t unix_ns = ref - ref % kDayNs + e->utc_time_of_day_ns;
  if (unix_ns - ref > kDayNs / 2) unix_ns -= kDayNs;
  if (ref - unix_ns > kDayNs / 2) unix_ns += kDayNs;
  est::GpsTime t = est::GpsTimeFromUnixNs(unix_ns, cfg_.leap_seconds);
  // the solution's time went out truncated to centiseconds: within 10 ms of a solution navd sent
  // it answers that one, and takes that solution's exact time
  const auto near = [&](est::GpsTime s) { return std::llabs((t - s).count()) < 10'000'000; };
  if (near(*last_emitted_)) {
    t = *last_emitted_;
    answered_ = true;
  } else if (previous_emitted_ && near(*previous_emitted_)) {
    t = *previous_emitted_;
    previous_answered_ = true;
  }
  // held until the solution after next (Emit): applied at the same point of every run
  if (queued_ < queue_.size()) {
    queue_[(queue_first_ + queued_) % queue_.size()] = {t, e->left_counts, e->right_counts};
    ++queued_;
  }
  encoders_started_ = true;
}

void OdometryNavd::Emit() {
  // the encoder samples answering the solution before the last (and older ones), never newer:
  // whichever order the processes ran in, each sample enters the filter at the same solution
  while (queued_ > 0 && previous_emitted_ && queue_[queue_first_].t <= *previous_emitted_) {
    nav_.OnEncoders(queue_[queue_first_]);
    queue_first_ = (queue_first_ + 1) % queue_.size();
    --queued_;
  }
  const std::optional<odo::PlanarSolution> p = nav_.Output(last_imu_t_);
  if (!p) return;
  if (AwaitingAnswer()) ++stats_.unanswered;
  est::NavOutput o;
  o.t = p->t;
  o.valid = true;
  const Eigen::Vector3d p_N(p->p_EN_m.x(), p->p_EN_m.y(), 0.0);
  o.p_N_m = p_N;
  o.position = frame_.ToLla(p_N);
  o.v_N_mps = Eigen::Vector3d(std::cos(p->yaw_rad), std::sin(p->yaw_rad), 0.0) * p->speed_mps;
  o.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(p->yaw_rad, Eigen::Vector3d::UnitZ()));
  o.has_attitude = true;
  o.pos_std_enu_m = {p->position_std_m.x(), p->position_std_m.y(), 1.0};
  o.gyro_bias_B = Eigen::Vector3d(0, 0, p->bias_radps);
  est::NavSolution s;
  s.tov_unix_ns = est::UnixNsFromGpsTime(o.t, cfg_.leap_seconds);
  s.lat_deg = o.position.lat_deg;
  s.lon_deg = o.position.lon_deg;
  s.height_m = o.position.height_m;
  s.vel_enu_mps = std::array<double, 3>{o.v_N_mps.x(), o.v_N_mps.y(), 0.0};
  s.speed_mps = std::fabs(p->speed_mps);
  s.yaw_deg = std::fmod(90.0 - p->yaw_rad / kDeg + 720.0, 360.0);
  s.pos_std_enu_m = {o.pos_std_enu_m.x(), o.pos_std_enu_m.y(), 1.0};
  s.mode = "gyro_odometry";
  const std::string line = est::ToJsonLine(s);
  std::fwrite(line.data(), 1, line.size(), out_);
  std::fflush(out_);
  if (nmea_fd_ >= 0) {
    const std::string n = est::outputs::FormatNmea0183(o, s.tov_unix_ns);
    if (write(nmea_fd_, n.data(), n.size()) != static_cast<ssize_t>(n.size())) ++stats_.late;
  }
  previous_emitted_ = last_emitted_;
  previous_answered_ = answered_;
  last_emitted_ = o.t;
  answered_ = false;
  ++stats_.solutions;
}

void OdometryNavd::PrintStats(const est::drivers::McuDecoderStats& mcu) const {
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  const odo::GyroOdometryStats& f = nav_.filter().stats();
  std::fprintf(stderr,
               "navd: stopped (gyro_odometry); solutions=%llu mcu frames=%llu bad_crc=%llu; "
               "encoder sentences=%llu bad=%llu unanswered=%llu out_of_order=%llu "
               "outside_history=%llu; filter gyro=%llu odometry=%llu rejected=%llu "
               "gyro_bias=%.3e rad/s\n",
               u(stats_.solutions), u(mcu.frames_ok), u(mcu.bad_crc), u(stats_.sentences),
               u(stats_.bad_sentences), u(stats_.unanswered), u(nav_.stats().out_of_order),
               u(nav_.stats().outside_history), u(f.gyro_samples), u(f.odometry_updates),
               u(f.odometry_rejected), nav_.filter().bias_radps());
}

// Reads the encoder input until the previous solution is answered or wait_s passes.
void AwaitAnswer(OdometryNavd& nav, SerialDevice& odometry, double wait_s, std::string& buf) {
  const std::int64_t until = MonotonicNs() + static_cast<std::int64_t>(wait_s * 1e9);
  while (nav.AwaitingAnswer()) {
    const std::int64_t left_ms = (until - MonotonicNs()) / 1'000'000;
    if (left_ms <= 0 || odometry.EnsureOpen() < 0) return;
    pollfd p{odometry.fd(), POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left_ms)) <= 0) continue;
    buf.clear();
    const bool alive = odometry.Read(buf);
    nav.OnOdometryBytes(buf);
    if (!alive) return;
  }
}

}  // namespace

int RunOdometryMode(const est::NavdConfig& cfg, std::FILE* out, int nmea_fd,
                    volatile std::sig_atomic_t* stop) {
  OdometryNavd nav(cfg, out, nmea_fd);
  SerialDevice imu_dev(cfg.imu_device, cfg.imu_baud), odo_dev(cfg.odometry.device, 115200);
  std::string odo_buf;
  est::drivers::McuImuAdapter adapter;
  est::drivers::McuFrameDecoder mcu([&](const est::drivers::McuFrame& f) {
    const std::optional<est::ImuSample> s = adapter.Add(f);
    if (!s || !nav.OnImu(*s)) return;
    AwaitAnswer(nav, odo_dev, cfg.odometry.wait_s, odo_buf);
    nav.Emit();
  });
  std::array<SerialDevice*, 2> devs{&imu_dev, &odo_dev};
  std::string buf;
  while (!*stop) {
    std::array<pollfd, 2> p{};
    std::array<std::size_t, 2> which{};
    std::size_t n = 0;
    for (std::size_t k = 0; k < devs.size(); ++k) {
      if (devs[k]->path().empty() || devs[k]->EnsureOpen() < 0) continue;
      p[n] = {devs[k]->fd(), POLLIN, 0};
      which[n++] = k;
    }
    if (n == 0 || poll(p.data(), n, 200) <= 0) {
      if (n == 0) usleep(100000);
      continue;
    }
    for (std::size_t i = 0; i < n; ++i) {
      if (!(p[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      buf.clear();
      const bool alive = devs[which[i]]->Read(buf);
      if (which[i] == 0)
        mcu.Feed(buf);
      else
        nav.OnOdometryBytes(buf);
      if (!alive) usleep(100000);
    }
  }
  nav.PrintStats(mcu.stats());
  if (out != stdout) std::fclose(out);
  return 0;
}

}  // namespace hil::navd

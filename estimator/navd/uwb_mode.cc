// navd's UWB mode: the tag's fixes (HIL-UWB-TDOA0 solved in closed form, eqs. 1–6, or the module's
// Tag_Frame0 position), Table 1's correction (eq. 8), and the WT901C's yaw rate and heading, in
// the planar filter (estimator/uwb/uwb_planar_filter.h). One solution per UWB fix, at the fix's
// epoch (the module's system_time since time_zero_unix_ns).
#include "uwb_mode.h"

#include <poll.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "hil/estimator/angles.h"
#include "hil/estimator/drivers/linktrack_decoder.h"
#include "hil/estimator/drivers/uwb_tdoa_decoder.h"
#include "hil/estimator/drivers/wt901c_decoder.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/navd/nav_solution.h"
#include "hil/estimator/outputs/nmea0183_writer.h"
#include "hil/estimator/uwb/error_field_correction.h"
#include "hil/estimator/uwb/tdoa_solver.h"
#include "hil/estimator/uwb/uwb_planar_filter.h"

#include "serial_device.h"

namespace hil::navd {
namespace {

namespace est = hil::estimator;
using estimator::kDeg;
constexpr std::size_t kStatuses = 5;
constexpr double kFieldHalf_m = 7.5;  // paper 003 §B.5: the error field was fitted on 15 m × 15 m

est::uwb::TdoaSolverConfig SolverConfig(const est::NavdUwbConfig& u) {
  est::uwb::TdoaSolverConfig c;
  for (std::size_t i = 0; i < 4; ++i)
    c.p_W_anchor_m[i] = {u.anchors_m[2 * i], u.anchors_m[2 * i + 1]};
  return c;
}

est::uwb::UwbPlanarFilterParams FilterParams(const est::NavdUwbConfig& u) {
  est::uwb::UwbPlanarFilterParams p;
  p.position_std_m = u.position_std_m;
  p.residual_std_m = u.residual_std_m;
  p.residual_distance_m = u.residual_distance_m;
  p.yaw_std_rad = u.yaw_std_deg * kDeg;
  p.yaw_offset_std_rad = u.yaw_offset_std_deg * kDeg;
  p.yaw_drift_std_radps = u.yaw_drift_std_dps * kDeg;
  return p;
}

// The mode's state between fixes: the latest WT901C values and the filter.
class UwbNavigator {
 public:
  UwbNavigator(const est::NavdUwbConfig& cfg, std::FILE* out, int nmea_fd)
      : cfg_(cfg),
        out_(out),
        nmea_fd_(nmea_fd),
        solver_(SolverConfig(cfg)),
        filter_(FilterParams(cfg)),
        frame_(est::Lla{cfg.origin_lat_deg, cfg.origin_lon_deg, cfg.origin_height_m}) {}

  void OnAttitude(const est::drivers::WitPacket& p) {
    if (p.type == 0x52) {
      rate_sum_radps_ += p.rate_dps.z() * kDeg;
      ++rate_count_;
      last_rate_radps_ = p.rate_dps.z() * kDeg;
    } else if (p.type == 0x53) {
      yaw_rad_ = (p.angle_deg.z() + cfg_.attitude_yaw_offset_deg) * kDeg;
      have_new_yaw_ = true;
    }
  }

  void OnTdoa(const est::drivers::UwbTdoaSample& s) {
    const est::uwb::TdoaFix fix = solver_.Solve(s.r_i1_m);
    ++status_count_[static_cast<std::size_t>(fix.status) % kStatuses];
    if (fix.ok()) OnFix(s.system_time_ms, fix.p_W_m);
  }

  void OnTagFrame(const est::drivers::LinkTrackTagFrame& f) {
    OnFix(f.system_time_ms, f.p_m.head<2>());
  }

  void PrintStats(const est::drivers::UwbTdoaDecoderStats& tdoa,
                  const est::drivers::LinkTrackDecoderStats& tag,
                  const est::drivers::WitDecoderStats& wit) const;

 private:
  void OnFix(std::uint32_t system_time_ms, const Eigen::Vector2d& p_measured_W_m);
  void Emit(std::uint32_t system_time_ms);
  void EmitNmea(std::int64_t tov_unix_ns, const est::Lla& g, double yaw_rad, double speed_mps);

  const est::NavdUwbConfig& cfg_;
  std::FILE* out_;
  int nmea_fd_;
  std::uint64_t nmea_write_errors_ = 0;
  est::uwb::TdoaSolver solver_;
  est::uwb::ErrorFieldCorrection correction_;
  est::uwb::UwbPlanarFilter filter_;
  est::LocalTangentFrame frame_;
  double rate_sum_radps_ = 0, last_rate_radps_ = 0, yaw_rad_ = 0;
  int rate_count_ = 0;
  bool have_new_yaw_ = false, have_last_fix_ = false;
  std::uint32_t last_fix_ms_ = 0;
  std::array<std::uint64_t, kStatuses> status_count_{};
  std::uint64_t solutions_ = 0;
};

void UwbNavigator::OnFix(std::uint32_t system_time_ms, const Eigen::Vector2d& p_measured_W_m) {
  // eq. 8 within the fitted 15 m × 15 m field; beyond it the cubic is evaluated at the nearest
  // point of the field (a cubic extrapolated tens of metres grows without bound)
  const Eigen::Vector2d at = p_measured_W_m.cwiseMax(-kFieldHalf_m).cwiseMin(kFieldHalf_m);
  const Eigen::Vector2d p =
      cfg_.correction ? Eigen::Vector2d(p_measured_W_m + correction_.Error_m(at)) : p_measured_W_m;
  const bool heading = !cfg_.attitude_device.empty();
  if (!filter_.initialized()) {
    if (heading && !have_new_yaw_) return;  // wait for the first heading
    filter_.Initialize(p, heading ? yaw_rad_ : 0.0);
  } else {
    const double dt_s = static_cast<double>(system_time_ms - last_fix_ms_) * 1e-3;
    const double rate = rate_count_ > 0 ? rate_sum_radps_ / rate_count_ : last_rate_radps_;
    filter_.Predict(heading ? rate : 0.0, dt_s);
    if (heading && have_new_yaw_) filter_.UpdateYaw(yaw_rad_);
    filter_.UpdatePosition(p);
  }
  rate_sum_radps_ = 0;
  rate_count_ = 0;
  have_new_yaw_ = false;
  last_fix_ms_ = system_time_ms;
  have_last_fix_ = true;
  Emit(system_time_ms);
}

void UwbNavigator::Emit(std::uint32_t system_time_ms) {
  est::NavSolution s;
  s.tov_unix_ns = cfg_.time_zero_unix_ns + static_cast<std::int64_t>(system_time_ms) * 1000000;
  const Eigen::Vector2d p = filter_.position();
  const est::Lla g = frame_.ToLla(Eigen::Vector3d(p.x(), p.y(), 0.0));
  s.lat_deg = g.lat_deg;
  s.lon_deg = g.lon_deg;
  s.height_m = g.height_m;
  const double psi = filter_.yaw_rad(), v = filter_.speed_mps();
  s.vel_enu_mps = std::array<double, 3>{v * std::cos(psi), v * std::sin(psi), 0.0};
  s.speed_mps = std::fabs(v);
  s.yaw_deg = std::fmod(90.0 - psi / kDeg + 720.0, 360.0);
  const Eigen::Vector2d sd = filter_.position_std_m();
  s.pos_std_enu_m = {sd.x(), sd.y(), 1.0};
  s.mode = "uwb";
  const std::string line = est::ToJsonLine(s);
  std::fwrite(line.data(), 1, line.size(), out_);
  std::fflush(out_);
  if (nmea_fd_ >= 0) EmitNmea(s.tov_unix_ns, g, psi, v);
  ++solutions_;
}

// The solution as NMEA 0183 (RMC, GGA, HDT): a guidance controller's input in a closed loop.
void UwbNavigator::EmitNmea(std::int64_t tov_unix_ns, const est::Lla& g, double yaw_rad,
                            double speed_mps) {
  est::NavOutput o;
  o.valid = true;
  o.position = g;
  o.v_N_mps = Eigen::Vector3d(speed_mps * std::cos(yaw_rad), speed_mps * std::sin(yaw_rad), 0.0);
  o.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()));
  o.has_attitude = true;
  const std::string s = est::outputs::FormatNmea0183(o, tov_unix_ns);
  if (write(nmea_fd_, s.data(), s.size()) != static_cast<ssize_t>(s.size())) ++nmea_write_errors_;
}

void UwbNavigator::PrintStats(const est::drivers::UwbTdoaDecoderStats& tdoa,
                              const est::drivers::LinkTrackDecoderStats& tag,
                              const est::drivers::WitDecoderStats& wit) const {
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  const est::uwb::UwbPlanarFilterStats& f = filter_.stats();
  std::fprintf(stderr,
               "navd: stopped (uwb); solutions=%llu tdoa ok=%llu bad_checksum=%llu garbage=%llu; "
               "tag_frame0 ok=%llu bad_checksum=%llu; solver ok=%llu bad_input=%llu "
               "collinear=%llu on_baseline=%llu no_root=%llu; wit ok=%llu bad_checksum=%llu "
               "garbage=%llu; filter position=%llu rejected=%llu resets=%llu yaw=%llu; "
               "nmea_write_errors=%llu\n",
               u(solutions_), u(tdoa.frames_ok), u(tdoa.bad_checksum), u(tdoa.garbage_bytes),
               u(tag.frames_ok), u(tag.bad_checksum), u(status_count_[0]), u(status_count_[1]),
               u(status_count_[2]), u(status_count_[3]), u(status_count_[4]), u(wit.packets_ok),
               u(wit.bad_checksum), u(wit.garbage_bytes), u(f.position_updates),
               u(f.position_rejected), u(f.resets), u(f.yaw_updates), u(nmea_write_errors_));
}

}  // namespace

int RunUwbMode(const est::NavdConfig& cfg, std::FILE* out, int nmea_fd,
               volatile std::sig_atomic_t* stop) {
  const est::NavdUwbConfig& u = cfg.uwb;
  UwbNavigator nav(u, out, nmea_fd);
  est::drivers::UwbTdoaDecoder tdoa([&](const est::drivers::UwbTdoaSample& s) { nav.OnTdoa(s); });
  est::drivers::LinkTrackDecoder tag(
      [&](const est::drivers::LinkTrackTagFrame& f) { nav.OnTagFrame(f); });
  est::drivers::Wt901cDecoder wit([&](const est::drivers::WitPacket& p) { nav.OnAttitude(p); });
  SerialDevice uwb_dev(u.device, u.baud), wit_dev(u.attitude_device, u.attitude_baud);
  std::array<SerialDevice*, 2> devs{&uwb_dev, &wit_dev};
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
    if (n == 0) {
      usleep(100000);
      continue;
    }
    if (poll(p.data(), n, 200) <= 0) continue;
    for (std::size_t i = 0; i < n; ++i) {
      if (!(p[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      buf.clear();
      const bool alive = devs[which[i]]->Read(buf);
      if (which[i] == 1)
        wit.Feed(buf);
      else if (u.format == "tdoa")
        tdoa.Feed(buf);
      else
        tag.Feed(buf);
      if (!alive) usleep(100000);
    }
  }
  nav.PrintStats(tdoa.stats(), tag.stats(), wit.stats());
  if (out != stdout) std::fclose(out);
  return 0;
}

}  // namespace hil::navd

// guidanced: the guidance controller of a closed-loop run (estimator/guidanced/README.md). Reads
// the estimator's solution as NMEA 0183 (GGA position, RMC speed, HDT heading: navd's
// [output] nmea_device) and the planned path, runs the selected tracker (pure pursuit or paper
// 003's fuzzy controller, --controller) at each solution, and commands a differential-drive base
// over the ROSArduinoBridge serial protocol (`m L R`), or a front-steered vehicle's steering ECU
// over ISO 11783-7 (Guidance System Command, on SocketCAN or a serial SLCAN adapter:
// isobus_link.h). Event-driven: one command per solution, no timers, so that a lockstep harness
// sees the same commands every run. Fixed buffers after start-up; no allocation per solution.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "hil/estimator/drivers/line_splitter.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/guidance/base_serial_client.h"
#include "hil/estimator/guidance/path_file.h"
#include "hil/estimator/guidance/path_tracker.h"
#include "hil/estimator/guidance/row_follower.h"
#include "hil/estimator/guidance/selected_tracker.h"
#include "hil/estimator/guidance/vehicle.h"
#include "hil/estimator/odometry/encoder_sentence.h"

#include "isobus_link.h"
#include "range_inputs.h"

namespace {

namespace est = hil::estimator;
namespace g = hil::estimator::guidance;

// SIGTERM/SIGINT (the run's end): the loop returns and the counters are printed.
volatile sig_atomic_t guidanced_stop_requested = 0;
void OnStopSignal(int) { guidanced_stop_requested = 1; }

struct Options {
  std::string path_file, nav, base, odometry, rangefinders, rangefinder_model = "tf_luna";
  std::string isobus;  // a CAN interface, or the SLCAN adapter's tty (isobus_slcan)
  bool isobus_slcan = false;
  int rangefinder_baud = 115200;
  double rangefinder_rate_hz = 100, p_dist_m = 0.4, d_set_m = 0.5;
  g::DeviationCorrectorConfig corrector;  // the laws the paper does not give (--correction-*)
  std::optional<est::GpsTime> rangefinder_start;  // UTC time of day (ns) of the first period
  bool correction = true;
  est::Lla origin;
  double speed_mps = 0.5, lookahead_m = 1.0;
  g::TrackerKind controller = g::TrackerKind::kPurePursuit;
  g::FuzzyTrackerConfig fuzzy;  // --controller fuzzy
  double track_m = 0.5, wheel_radius_m = 0.1, max_wheel_radps = 20, pid_rate_hz = 30;
  int counts_per_rev = 1200;
  double wheelbase_m = 2.5, max_steer_deg = 35;
  bool steering_given = false;  // --wheelbase: trackers limited to it (a diff base too)
  int guidance_address = 0x80, ecu_address = 0x1C;
};

constexpr const char* kUsage =
    "usage: guidanced --path FILE --origin LAT,LON,H --nav NMEA_IN "
    "(--base TTY | --isobus-can IFACE | --isobus-slcan TTY) [--controller pure_pursuit|fuzzy] "
    "[--speed M/S] [--lookahead M] [--fuzzy-k-alpha-deg DEG] [--fuzzy-heading-preview M] "
    "[--fuzzy-n-max N] [--fuzzy-steer-rate-deg-s DEG/S] "
    "[--track M] [--wheel-radius M] [--counts-per-rev N] [--pid-rate HZ] "
    "[--max-wheel-speed RAD/S] [--wheelbase M] [--max-steer-deg DEG] "
    "[--guidance-address N] [--ecu-address N] [--odometry OUT] "
    "[--rangefinders RF,RR,LF,LR [--rangefinder-model tf_luna|tfmini_s] "
    "[--rangefinder-baud B] [--rangefinder-rate HZ] [--rangefinder-start-tod S] "
    "[--correction on|off] [--correction-taper M] [--correction-gain 1/S] "
    "[--correction-max-rate RAD/S] [--p-dist M] [--d-set M]]\n";

[[noreturn]] void Usage(const char* why) {
  std::fprintf(stderr, "guidanced: %s\n%s", why, kUsage);
  std::exit(2);
}

// --help: what it is, the usage line and where the interface is documented (also the source of
// its manual page, help2man).
[[noreturn]] void Help() {
  std::printf(
      "Usage:%s\n"
      "The guidance controller of a hil closed-loop run. Reads the navigation solution as\n"
      "NMEA 0183 (RMC, GGA, HDT once per solution) from NMEA_IN and the planned path (a\n"
      "hil-path 1 file), runs pure pursuit or paper 003's fuzzy controller at each solution,\n"
      "and commands a differential-drive base over the ROSArduinoBridge serial protocol\n"
      "(--base) or a steering ECU over ISO 11783-7 (--isobus-can, --isobus-slcan). One\n"
      "command per solution, no timers.\n"
      "hil run starts it as a closed-loop scenario's controller ({guidanced}); the interface and\n"
      "every option: estimator/guidanced/README.md in the hil sources.\n\n"
      "Exit status: 0 when the solution input ends or on SIGTERM/SIGINT, 1 when a link cannot\n"
      "be opened or fails, 2 on bad arguments or a bad path file.\n",
      kUsage + 6);  // kUsage without its "usage:", which help2man's "Usage:" replaces
  std::exit(0);
}

double Number(const char* key, const char* v) {
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (end == v || *end != '\0' || !std::isfinite(x))
    Usage((std::string(key) + ": not a number: " + v).c_str());
  return x;
}

int Address(const char* key, const char* v) {
  char* end = nullptr;
  const long a = std::strtol(v, &end, 0);
  if (end == v || *end != '\0' || a < 0 || a > 253)
    Usage((std::string(key) + ": not a source address 0-253: " + v).c_str());
  return static_cast<int>(a);
}

// The ISOBUS channel's options; false for an option that is none of them.
bool ParseIsobusOption(const std::string& k, const char* v, Options& o) {
  if (k == "--isobus-can" || k == "--isobus-slcan") {
    o.isobus = v;
    o.isobus_slcan = k == "--isobus-slcan";
  } else if (k == "--wheelbase") {
    o.wheelbase_m = Number("--wheelbase", v);
    o.steering_given = true;
  } else if (k == "--max-steer-deg") {
    o.max_steer_deg = Number("--max-steer-deg", v);
  } else if (k == "--guidance-address") {
    o.guidance_address = Address("--guidance-address", v);
  } else if (k == "--ecu-address") {
    o.ecu_address = Address("--ecu-address", v);
  } else {
    return false;
  }
  return true;
}

// Paper 001's options (row following, rangefinders, odometry forwarding); false if `k` is none.
bool ParseRowOption(const std::string& k, const char* v, Options& o) {
  if (k == "--odometry") {
    o.odometry = v;
  } else if (k == "--rangefinders") {
    o.rangefinders = v;
  } else if (k == "--rangefinder-model") {
    o.rangefinder_model = v;
    if (o.rangefinder_model != "tf_luna" && o.rangefinder_model != "tfmini_s")
      Usage("--rangefinder-model: tf_luna or tfmini_s");
  } else if (k == "--rangefinder-baud") {
    o.rangefinder_baud = static_cast<int>(Number("--rangefinder-baud", v));
    if (o.rangefinder_baud <= 0) Usage("--rangefinder-baud: must be positive");
  } else if (k == "--rangefinder-rate") {
    o.rangefinder_rate_hz = Number("--rangefinder-rate", v);
    if (!(o.rangefinder_rate_hz > 0)) Usage("--rangefinder-rate: must be positive");
  } else if (k == "--rangefinder-start-tod") {
    const double tod_s = Number("--rangefinder-start-tod", v);
    if (tod_s < 0 || tod_s >= 86400) Usage("--rangefinder-start-tod: seconds of the UTC day");
    o.rangefinder_start = est::GpsTimeFromNs(std::llround(tod_s * 1e9));
  } else if (k == "--correction") {
    if (std::string_view(v) != "on" && std::string_view(v) != "off")
      Usage("--correction: on or off");
    o.correction = std::string_view(v) == "on";
  } else if (k == "--correction-taper") {
    o.corrector.taper_offset_m = Number("--correction-taper", v);
    if (!(o.corrector.taper_offset_m > 0)) Usage("--correction-taper: must be positive");
  } else if (k == "--correction-gain") {
    o.corrector.heading_gain_per_s = Number("--correction-gain", v);
    if (!(o.corrector.heading_gain_per_s > 0)) Usage("--correction-gain: must be positive");
  } else if (k == "--correction-max-rate") {
    o.corrector.max_turn_rate_radps = Number("--correction-max-rate", v);
    if (!(o.corrector.max_turn_rate_radps > 0)) Usage("--correction-max-rate: must be positive");
  } else if (k == "--p-dist") {
    o.p_dist_m = Number("--p-dist", v);
  } else if (k == "--d-set") {
    o.d_set_m = Number("--d-set", v);
  } else {
    return false;
  }
  return true;
}

// "A,B,C,D": the four rangefinder ports.
std::array<std::string, 4> SplitFour(const std::string& s) {
  std::array<std::string, 4> out;
  std::size_t pos = 0;
  for (std::size_t k = 0; k < 4; ++k) {
    const std::size_t comma = s.find(',', pos);
    if ((k < 3) == (comma == std::string::npos)) Usage("--rangefinders: expected RF,RR,LF,LR");
    out[k] = s.substr(pos, comma == std::string::npos ? std::string::npos : comma - pos);
    pos = comma + 1;
  }
  return out;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if (k == "--help" || k == "-h") Help();
    if (i + 1 >= argc) Usage(("missing the value of " + k).c_str());
    const char* v = argv[++i];
    if (k == "--path") {
      o.path_file = v;
    } else if (k == "--nav") {
      o.nav = v;
    } else if (k == "--base") {
      o.base = v;
    } else if (k == "--origin") {
      if (std::sscanf(v, "%lf,%lf,%lf", &o.origin.lat_deg, &o.origin.lon_deg, &o.origin.height_m) !=
          3)
        Usage("--origin: expected LAT,LON,H");
    } else if (k == "--speed") {
      o.speed_mps = Number("--speed", v);
    } else if (k == "--lookahead") {
      o.lookahead_m = Number("--lookahead", v);
    } else if (k == "--controller") {
      const std::optional<g::TrackerKind> kind = g::ParseTrackerKind(v);
      if (!kind) Usage("--controller: expected pure_pursuit or fuzzy");
      o.controller = *kind;
    } else if (k == "--fuzzy-k-alpha-deg") {
      o.fuzzy.k_alpha_deg = Number("--fuzzy-k-alpha-deg", v);
    } else if (k == "--fuzzy-heading-preview") {
      o.fuzzy.heading_preview_m = Number("--fuzzy-heading-preview", v);
    } else if (k == "--fuzzy-n-max") {
      o.fuzzy.weight_n_max = Number("--fuzzy-n-max", v);
    } else if (k == "--fuzzy-steer-rate-deg-s") {
      o.fuzzy.steer_rate_limit_deg_s = Number("--fuzzy-steer-rate-deg-s", v);
    } else if (k == "--track") {
      o.track_m = Number("--track", v);
    } else if (k == "--wheel-radius") {
      o.wheel_radius_m = Number("--wheel-radius", v);
    } else if (k == "--counts-per-rev") {
      o.counts_per_rev = static_cast<int>(Number("--counts-per-rev", v));
    } else if (k == "--pid-rate") {
      o.pid_rate_hz = Number("--pid-rate", v);
    } else if (k == "--max-wheel-speed") {
      o.max_wheel_radps = Number("--max-wheel-speed", v);
    } else if (!ParseIsobusOption(k, v, o) && !ParseRowOption(k, v, o)) {
      Usage(("unknown option " + k).c_str());
    }
  }
  if (o.path_file.empty() || o.nav.empty() || o.base.empty() == o.isobus.empty())
    Usage("--path, --nav and one of --base, --isobus-can, --isobus-slcan are required");
  return o;
}

int OpenBase(const std::string& tty) {
  const int fd = open(tty.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return -1;
  termios t{};
  if (tcgetattr(fd, &t) == 0) {
    cfmakeraw(&t);
    cfsetispeed(&t, B57600);
    cfsetospeed(&t, B57600);
    tcsetattr(fd, TCSANOW, &t);
  }
  return fd;
}

// HDT "$GNHDT,123.45,T*hh": true heading in degrees (checksum verified).
std::optional<double> ParseHdt(std::string_view s) {
  if (s.size() < 12 || s.substr(3, 4) != "HDT,") return std::nullopt;
  const std::size_t star = s.find('*');
  if (star == std::string_view::npos || star + 3 > s.size()) return std::nullopt;
  unsigned x = 0;
  for (std::size_t i = 1; i < star; ++i) x ^= static_cast<unsigned char>(s[i]);
  if (std::strtoul(std::string(s.substr(star + 1, 2)).c_str(), nullptr, 16) != x)
    return std::nullopt;
  char* end = nullptr;
  const std::string field(s.substr(7, star - 7));
  const double h = std::strtod(field.c_str(), &end);
  if (end == field.c_str()) return std::nullopt;
  return h;
}

// The controller's state between solutions.
class Controller {
 public:
  Controller(const Options& o, g::PlannedPath path, int base_fd, hil::guidanced::IsobusLink* isobus,
             int odometry_fd, hil::guidanced::RangeInputs* ranges)
      : o_(o),
        path_(std::move(path)),
        frame_(o.origin),
        tracker_(Config(o)),
        base_fd_(base_fd),
        isobus_(isobus),
        odometry_fd_(odometry_fd),
        ranges_(ranges),
        platform_{o.track_m, o.wheel_radius_m, o.max_wheel_radps},
        steering_{o.wheelbase_m, o.max_steer_deg * std::numbers::pi / 180.0} {
    if (ranges_) row_.emplace(RowConfig(o), path_);
  }

  // One reply line of the base: an encoder reply goes on to navd, stamped with the solution that
  // asked for it (replies come in the order of the requests).
  void OnBaseLine(std::string_view line) {
    std::int32_t left = 0, right = 0;
    if (odometry_fd_ < 0 || !g::ParseEncoderReply(line, left, right) || asked_count_ == 0) return;
    const std::int64_t tod = asked_tod_ns_[asked_first_];
    asked_first_ = (asked_first_ + 1) % asked_tod_ns_.size();
    --asked_count_;
    const hil::estimator::odometry::EncoderSentenceLine l =
        hil::estimator::odometry::FormatEncoderSentence({tod, left, right});
    if (write(odometry_fd_, l.bytes.data(), l.size) == static_cast<ssize_t>(l.size)) ++forwarded_;
  }
  std::uint64_t forwarded() const { return forwarded_; }
  const std::optional<g::RowFollower>& row() const { return row_; }

  // One NMEA sentence of the solution (without CR LF).
  void OnSentence(std::string_view s) {
    if (const std::optional<double> h = ParseHdt(s)) {
      heading_deg_ = *h;
      if (have_fix_) Command();
      return;
    }
    const std::optional<est::drivers::NmeaFix> f =
        est::drivers::NmeaDecoder::ParseSentence(s, &stats_);
    if (!f || !f->valid || !f->lat_deg || !f->lon_deg) return;
    if (f->kind == est::drivers::NmeaFix::Kind::kRmc) {
      speed_mps_ = f->speed_mps.value_or(0.0);
      return;
    }
    fix_tod_ns_ = f->utc_time_of_day_ns;
    tod_ns_ = fix_tod_ns_.value_or(0);
    const double h = f->msl_altitude_m.value_or(0.0) + f->geoid_separation_m.value_or(0.0);
    p_EN_m_ = frame_.ToLocal({*f->lat_deg, *f->lon_deg, h}).head<2>();
    have_fix_ = true;
  }
  std::uint64_t commands() const { return commands_; }

 private:
  static g::SelectedTrackerConfig Config(const Options& o) {
    g::SelectedTrackerConfig c;
    c.kind = o.controller;
    c.pure_pursuit.lookahead_m = o.lookahead_m;
    c.fuzzy = o.fuzzy;
    // a front-steered vehicle's limits (on ISOBUS, or given for a base standing in for one)
    c.wheelbase_m = o.steering_given || !o.isobus.empty() ? o.wheelbase_m : 0.0;
    c.max_steer_deg = o.max_steer_deg;
    return c;
  }
  void Command() {
    g::VehiclePose2d pose;
    pose.p_EN_m = p_EN_m_;
    pose.yaw_rad = (90.0 - heading_deg_) * std::numbers::pi / 180.0;
    pose.speed_mps = speed_mps_;
    pose.t_ns = fix_tod_ns_;  // the fuzzy tracker's steering-rate limit steps by the interval
    if (isobus_) {
      SteerCommand(tracker_.Update(path_, pose));
      return;
    }
    const g::WheelSpeeds w = row_ ? RowCommand(pose) : PursuitCommand(pose);
    const g::BaseCommandLine line =
        g::FormatMotorSpeeds(g::TicksPerFrame(w.left_radps, o_.counts_per_rev, o_.pid_rate_hz),
                             g::TicksPerFrame(w.right_radps, o_.counts_per_rev, o_.pid_rate_hz));
    if (write(base_fd_, line.bytes.data(), line.size) == static_cast<ssize_t>(line.size))
      ++commands_;
    if (odometry_fd_ < 0 || asked_count_ == asked_tod_ns_.size()) return;
    const g::BaseCommandLine e = g::FormatReadEncoders();
    if (write(base_fd_, e.bytes.data(), e.size) != static_cast<ssize_t>(e.size)) return;
    asked_tod_ns_[(asked_first_ + asked_count_) % asked_tod_ns_.size()] = tod_ns_;
    ++asked_count_;
  }
  g::WheelSpeeds PursuitCommand(const g::VehiclePose2d& pose) {
    const g::TrackingCommand c = tracker_.Update(path_, pose);
    const double v = c.end_of_path ? 0.0 : o_.speed_mps;
    return platform_.FromSpeedAndCurvature(v, c.curvature_left_per_m);
  }
  // Paper 001: the base row navigation with the deviation corrector over it (row_follower.h).
  g::WheelSpeeds RowCommand(const g::VehiclePose2d& pose) {
    const est::GpsTime t = est::GpsTimeFromNs(tod_ns_);
    row_->OnEstimate(t, pose);
    ranges_->Drain(t, [&](const g::RangeSet& r) { row_->OnRanges(r); });
    const g::VelocityCommand c = row_->Command();
    return g::WheelSpeedsFromSpeedAndYawRate(platform_, c.v_mps, c.w_radps);
  }
  static g::RowFollowerConfig RowConfig(const Options& o) {
    g::RowFollowerConfig c;
    c.speed_mps = o.speed_mps;
    c.pursuit.lookahead_m = o.lookahead_m;
    c.correction = o.correction;
    c.corrector = o.corrector;
    c.corrector.p_dist_m = o.p_dist_m;
    c.corrector.d_set_m = o.d_set_m;
    return c;
  }

  // ISOBUS: the curvature (the reachable one) to the steering ECU; "not intended to steer" at the
  // path's end, and once when the ECU asks for it after an exit (request reset).
  void SteerCommand(const g::TrackingCommand& c) {
    std::uint8_t status = g::kIntendedToSteer;
    if (c.end_of_path || isobus_->reset_requested()) status = g::kNotIntendedToSteer;
    isobus_->clear_reset_request();
    const double kappa = c.end_of_path ? 0.0 : steering_.Reachable(c.curvature_left_per_m);
    g::SystemCommandAddress a;
    a.source = static_cast<std::uint8_t>(o_.guidance_address);
    a.destination = static_cast<std::uint8_t>(o_.ecu_address);
    if (isobus_->Send(g::EncodeSystemCommand(a, g::IsobusCurvatureFromLeft(kappa), status)))
      ++commands_;
  }

  Options o_;
  g::PlannedPath path_;
  est::LocalTangentFrame frame_;
  g::SelectedTracker tracker_;
  int base_fd_;
  hil::guidanced::IsobusLink* isobus_;
  int odometry_fd_;
  hil::guidanced::RangeInputs* ranges_;
  g::DiffDrivePlatform platform_;
  g::FrontSteeredPlatform steering_;
  std::optional<g::RowFollower> row_;
  std::array<std::int64_t, 8> asked_tod_ns_{};
  std::size_t asked_first_ = 0, asked_count_ = 0;
  std::int64_t tod_ns_ = 0;
  std::optional<std::int64_t> fix_tod_ns_;  // the last GGA's time of day, when it had one
  std::uint64_t forwarded_ = 0;
  Eigen::Vector2d p_EN_m_{0, 0};
  double heading_deg_ = 0, speed_mps_ = 0;
  bool have_fix_ = false;
  est::drivers::NmeaDecoderStats stats_;
  std::uint64_t commands_ = 0;
};

int Loop(Controller& ctl, int nav_fd, int base_fd, hil::guidanced::IsobusLink* isobus,
         hil::guidanced::RangeInputs* ranges) {
  est::drivers::LineSplitter<128> nav;  // the NMEA sentences of the solution
  g::BaseReplyReader replies;
  std::array<char, 4096> buf{};
  std::array<pollfd, 6> fds{};
  fds[0] = {nav_fd, POLLIN, 0};
  fds[1] = {base_fd, POLLIN, 0};
  nfds_t n_fds = 2;
  if (ranges)
    for (const int fd : ranges->fds()) fds[n_fds++] = {fd, POLLIN, 0};
  for (;;) {
    if (guidanced_stop_requested) return 0;
    if (poll(fds.data(), n_fds, -1) < 0) {
      if (errno == EINTR) continue;
      return 1;
    }
    if (fds[0].revents) {
      const ssize_t n = read(nav_fd, buf.data(), buf.size());
      if (n == 0) return 0;  // the estimator's output ended
      if (n > 0)
        nav.Feed(std::string_view(buf.data(), static_cast<std::size_t>(n)),
                 [&](std::string_view s) { ctl.OnSentence(s); });
    }
    if (fds[1].revents && isobus) {
      if (!isobus->OnReadable()) return 0;  // the link ended
    } else if (fds[1].revents) {
      const ssize_t n = read(base_fd, buf.data(), buf.size());
      if (n <= 0 && errno != EINTR && errno != EAGAIN) return 0;  // the base's port closed
      for (ssize_t i = 0; i < n; ++i)
        if (replies.Feed(buf[static_cast<std::size_t>(i)])) ctl.OnBaseLine(replies.line());
    }
    for (nfds_t k = 2; k < n_fds; ++k)
      if (fds[k].revents) ranges->Read(k - 2);
  }
}

// The counters on stderr when the controller stops.
void PrintCounters(const Controller& ctl, const hil::guidanced::IsobusLink* isobus,
                   const hil::guidanced::RangeInputs& ranges) {
  std::fprintf(stderr, "guidanced: stopped; commands=%llu encoder_sentences=%llu\n",
               static_cast<unsigned long long>(ctl.commands()),
               static_cast<unsigned long long>(ctl.forwarded()));
  if (isobus)
    std::fprintf(stderr, "guidanced: machine_infos=%llu refusals=%llu\n",
                 static_cast<unsigned long long>(isobus->machine_infos()),
                 static_cast<unsigned long long>(isobus->refusals()));
  if (const auto& row = ctl.row()) {
    const g::DeviationState& d = row->corrector().state();
    std::fprintf(stderr,
                 "guidanced: row following; lateral_corrections=%llu heading_corrections=%llu "
                 "turns=%llu anchors=%llu range_bad_bytes=%llu range_overflows=%llu\n",
                 static_cast<unsigned long long>(d.lateral_corrections),
                 static_cast<unsigned long long>(d.heading_corrections),
                 static_cast<unsigned long long>(d.turns),
                 static_cast<unsigned long long>(row->state().anchors),
                 static_cast<unsigned long long>(ranges.bad_bytes()),
                 static_cast<unsigned long long>(ranges.overflows()));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
  struct sigaction sa {};
  sa.sa_handler = OnStopSignal;  // no SA_RESTART: poll() returns EINTR
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  g::PlannedPath path;
  try {
    path = g::ReadPathFile(o.path_file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "guidanced: %s\n", e.what());
    return 2;
  }
  hil::guidanced::IsobusLink isobus;
  const bool on_isobus = !o.isobus.empty();
  if (on_isobus &&
      !isobus.Open(o.isobus, o.isobus_slcan, static_cast<std::uint8_t>(o.ecu_address))) {
    std::fprintf(stderr, "guidanced: cannot open the ISOBUS link %s: %s\n", o.isobus.c_str(),
                 std::strerror(errno));
    return 1;
  }
  const int base_fd = on_isobus ? isobus.fd() : OpenBase(o.base);
  if (base_fd < 0) {
    std::fprintf(stderr, "guidanced: cannot open the base %s: %s\n", o.base.c_str(),
                 std::strerror(errno));
    return 1;
  }
  const int nav_fd = open(o.nav.c_str(), O_RDONLY | O_CLOEXEC);
  if (nav_fd < 0) {
    std::fprintf(stderr, "guidanced: cannot open the solution input %s: %s\n", o.nav.c_str(),
                 std::strerror(errno));
    return 1;
  }
  const int odometry_fd = o.odometry.empty() ? -2 : open(o.odometry.c_str(), O_WRONLY | O_CLOEXEC);
  hil::guidanced::RangeInputs ranges;
  const bool with_ranges = !o.rangefinders.empty();
  if (odometry_fd == -1 ||
      (with_ranges && !ranges.Open(SplitFour(o.rangefinders), o.rangefinder_baud,
                                   o.rangefinder_model == "tfmini_s", o.rangefinder_rate_hz,
                                   o.rangefinder_start))) {
    std::fprintf(stderr, "guidanced: cannot open the odometry output or a rangefinder: %s\n",
                 std::strerror(errno));
    return 1;
  }
  Controller ctl(o, std::move(path), base_fd, on_isobus ? &isobus : nullptr,
                 odometry_fd < 0 ? -1 : odometry_fd, with_ranges ? &ranges : nullptr);
  const int rc =
      Loop(ctl, nav_fd, base_fd, on_isobus ? &isobus : nullptr, with_ranges ? &ranges : nullptr);
  PrintCounters(ctl, on_isobus ? &isobus : nullptr, ranges);
  return rc;
}

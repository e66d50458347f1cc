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

#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/geodesy.h"
#include "hil/estimator/guidance/base_serial_client.h"
#include "hil/estimator/guidance/path_file.h"
#include "hil/estimator/guidance/path_tracker.h"
#include "hil/estimator/guidance/selected_tracker.h"
#include "hil/estimator/guidance/vehicle.h"

#include "isobus_link.h"

namespace {

namespace est = hil::estimator;
namespace g = hil::estimator::guidance;

struct Options {
  std::string path_file, nav, base;
  std::string isobus;  // a CAN interface, or the SLCAN adapter's tty (isobus_slcan)
  bool isobus_slcan = false;
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

[[noreturn]] void Usage(const char* why) {
  std::fprintf(
      stderr,
      "guidanced: %s\nusage: guidanced --path FILE --origin LAT,LON,H --nav NMEA_IN "
      "(--base TTY | --isobus-can IFACE | --isobus-slcan TTY) [--controller pure_pursuit|fuzzy] "
      "[--speed M/S] [--lookahead M] [--fuzzy-k-alpha-deg DEG] [--fuzzy-heading-preview M] "
      "[--track M] [--wheel-radius M] [--counts-per-rev N] [--pid-rate HZ] "
      "[--max-wheel-speed RAD/S] [--wheelbase M] [--max-steer-deg DEG] "
      "[--guidance-address N] [--ecu-address N]\n",
      why);
  std::exit(2);
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

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
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
    } else if (!ParseIsobusOption(k, v, o)) {
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
  Controller(const Options& o, g::PlannedPath path, int base_fd, hil::guidanced::IsobusLink* isobus)
      : o_(o),
        path_(std::move(path)),
        frame_(o.origin),
        tracker_(Config(o)),
        base_fd_(base_fd),
        isobus_(isobus),
        platform_{o.track_m, o.wheel_radius_m, o.max_wheel_radps},
        steering_{o.wheelbase_m, o.max_steer_deg * std::numbers::pi / 180.0} {}

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
    const g::TrackingCommand c = tracker_.Update(path_, pose);
    if (isobus_) {
      SteerCommand(c);
      return;
    }
    const double v = c.end_of_path ? 0.0 : o_.speed_mps;
    const g::WheelSpeeds w = platform_.FromSpeedAndCurvature(v, c.curvature_left_per_m);
    const g::BaseCommandLine line =
        g::FormatMotorSpeeds(g::TicksPerFrame(w.left_radps, o_.counts_per_rev, o_.pid_rate_hz),
                             g::TicksPerFrame(w.right_radps, o_.counts_per_rev, o_.pid_rate_hz));
    if (write(base_fd_, line.bytes.data(), line.size) == static_cast<ssize_t>(line.size))
      ++commands_;
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
  g::DiffDrivePlatform platform_;
  g::FrontSteeredPlatform steering_;
  Eigen::Vector2d p_EN_m_{0, 0};
  double heading_deg_ = 0, speed_mps_ = 0;
  bool have_fix_ = false;
  est::drivers::NmeaDecoderStats stats_;
  std::uint64_t commands_ = 0;
};

// Splits the NMEA stream into sentences in a fixed buffer.
class LineSplitter {
 public:
  template <typename F>
  void Feed(const char* p, std::size_t n, F&& on_line) {
    for (std::size_t i = 0; i < n; ++i) {
      const char c = p[i];
      if (c == '\r' || c == '\n') {
        if (size_ > 0 && !overflow_) on_line(std::string_view(buf_.data(), size_));
        size_ = 0;
        overflow_ = false;
      } else if (size_ < buf_.size()) {
        buf_[size_++] = c;
      } else {
        overflow_ = true;
      }
    }
  }

 private:
  std::array<char, 128> buf_{};
  std::size_t size_ = 0;
  bool overflow_ = false;
};

int Loop(Controller& ctl, int nav_fd, int base_fd, hil::guidanced::IsobusLink* isobus) {
  LineSplitter nav;
  g::BaseReplyReader replies;
  std::array<char, 4096> buf{};
  pollfd fds[2] = {{nav_fd, POLLIN, 0}, {base_fd, POLLIN, 0}};
  for (;;) {
    if (poll(fds, 2, -1) < 0) {
      if (errno == EINTR) continue;
      return 1;
    }
    if (fds[0].revents) {
      const ssize_t n = read(nav_fd, buf.data(), buf.size());
      if (n == 0) return 0;  // the estimator's output ended
      if (n > 0)
        nav.Feed(buf.data(), static_cast<std::size_t>(n),
                 [&](std::string_view s) { ctl.OnSentence(s); });
    }
    if (fds[1].revents && isobus) {
      if (!isobus->OnReadable()) return 0;  // the link ended
    } else if (fds[1].revents) {
      const ssize_t n = read(base_fd, buf.data(), buf.size());
      if (n <= 0 && errno != EINTR && errno != EAGAIN) return 0;  // the base's port closed
      for (ssize_t i = 0; i < n; ++i) replies.Feed(buf[static_cast<std::size_t>(i)]);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
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
  Controller ctl(o, std::move(path), base_fd, on_isobus ? &isobus : nullptr);
  const int rc = Loop(ctl, nav_fd, base_fd, on_isobus ? &isobus : nullptr);
  std::fprintf(stderr, "guidanced: stopped; commands=%llu\n",
               static_cast<unsigned long long>(ctl.commands()));
  if (on_isobus)
    std::fprintf(stderr, "guidanced: machine_infos=%llu refusals=%llu\n",
                 static_cast<unsigned long long>(isobus.machine_infos()),
                 static_cast<unsigned long long>(isobus.refusals()));
  return rc;
}

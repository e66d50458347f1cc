// Example controller for hil (examples/README.md): pure pursuit of a differential-drive base, the
// C++ twin of examples/python/pursuit_controller.py. Reads the navigation solution as NMEA 0183
// (RMC, GGA, HDT once per solution: navd's [output] nmea_device, the FIFO {nav_nmea}) and a
// planned-path file (ab_line or polyline), and at each solution (its HDT) sends one wheel-speed
// command `m <L> <R>` to the base over the ROSArduinoBridge serial protocol (57600 8N1), reading
// and dropping its replies: the contract of estimator/guidanced/README.md. Standard library and
// POSIX only; not part of the product (built as an example, never installed).
//
// Usage: hil_example_pursuit_controller --path FILE --origin LAT,LON,H --nav NMEA_IN --base TTY
//            [--speed 0.5] [--lookahead 1.0] [--track 0.5] [--wheel-radius 0.1]
//            [--counts-per-rev 1200] [--pid-rate 30]
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <vector>

#include "local_frame.h"
#include "nmea_fields.h"
#include "path_polyline.h"

namespace {

using hil_example::Point;

struct Options {
  std::string path, nav, base;
  std::array<double, 3> origin{};
  double speed_mps = 0.5, lookahead_m = 1.0, track_m = 0.5, wheel_radius_m = 0.1;
  double counts_per_rev = 1200, pid_rate_hz = 30;
};

// Pure pursuit along a polyline; progress only moves forward.
class PurePursuit {
 public:
  PurePursuit(std::vector<Point> v, double lookahead_m) : v_(std::move(v)), l_(lookahead_m) {}

  // Curvature (1/m, positive left), or nothing once the path's end is within half the look-ahead.
  std::optional<double> Update(const Point& p, double yaw_rad) {
    double best = 1e300, f_best = 0;
    for (std::size_t i = seg_; i + 1 < v_.size(); ++i) {
      const double dx = v_[i + 1][0] - v_[i][0], dy = v_[i + 1][1] - v_[i][1];
      const double f = std::clamp(
          ((p[0] - v_[i][0]) * dx + (p[1] - v_[i][1]) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
      const double d = std::hypot(v_[i][0] + f * dx - p[0], v_[i][1] + f * dy - p[1]);
      if (d < best) {
        best = d;
        f_best = f;
        seg_ = i;
      }
    }
    bool beyond = false;
    const Point t = Target(seg_, f_best, beyond);
    const double dist = std::hypot(t[0] - p[0], t[1] - p[1]);
    if (beyond && dist < 0.5 * l_) return std::nullopt;
    const double alpha = std::atan2(t[1] - p[1], t[0] - p[0]) - yaw_rad;
    return 2.0 * std::sin(alpha) / std::max(dist, 1e-6);
  }

 private:
  // The point the look-ahead distance along the path from segment i at fraction f, or its end.
  Point Target(std::size_t i, double f, bool& beyond) const {
    double left = l_;
    for (;; ++i, f = 0.0) {
      const Point &a = v_[i], &b = v_[i + 1];
      const double len = std::hypot(b[0] - a[0], b[1] - a[1]), rest = (1.0 - f) * len;
      if (left <= rest || i + 2 == v_.size()) {
        beyond = left > rest;
        const double g = std::min(1.0, f + left / len);
        return {a[0] + g * (b[0] - a[0]), a[1] + g * (b[1] - a[1])};
      }
      left -= rest;
    }
  }

  std::vector<Point> v_;
  double l_;
  std::size_t seg_ = 0;
};

class Controller {
 public:
  Controller(const Options& o, std::vector<Point> path, int base_fd)
      : o_(o),
        frame_(o.origin[0], o.origin[1], o.origin[2]),
        pursuit_(std::move(path), o.lookahead_m),
        base_fd_(base_fd) {}

  void OnLine(const std::string& line) {
    const auto f = hil_example::NmeaFields(line);
    if (!f || f->empty()) return;
    const std::string_view type = hil_example::SentenceType((*f)[0]);
    if (type == "GGA" && hil_example::GgaHasFix(*f)) {
      const auto enu = frame_.ToEnu(hil_example::NmeaDegrees((*f)[2], (*f)[3], 2),
                                    hil_example::NmeaDegrees((*f)[4], (*f)[5], 3),
                                    hil_example::GgaEllipsoidalHeight(*f));
      p_ = Point{enu[0], enu[1]};
    } else if (type == "HDT" && f->size() >= 2 && !(*f)[1].empty() && p_) {
      Command((90.0 - std::atof((*f)[1].c_str())) * hil_example::kDegToRad);  // compass → ENU yaw
    }
  }
  long commands() const { return commands_; }

 private:
  void Command(double yaw_rad) {
    const std::optional<double> kappa = pursuit_.Update(*p_, yaw_rad);
    const double v = kappa ? o_.speed_mps : 0.0;
    std::array<long, 2> ticks{};
    for (int w = 0; w < 2; ++w) {  // left, right
      const double side = w == 0 ? -1.0 : 1.0;
      const double radps =
          v * (1.0 + side * kappa.value_or(0.0) * o_.track_m / 2.0) / o_.wheel_radius_m;
      ticks[w] =
          std::lround(radps / (2.0 * 3.14159265358979323846) * o_.counts_per_rev / o_.pid_rate_hz);
    }
    char line[48];
    const int n = std::snprintf(line, sizeof line, "m %ld %ld\r", ticks[0], ticks[1]);
    if (write(base_fd_, line, static_cast<std::size_t>(n)) == n) ++commands_;
  }

  Options o_;
  hil_example::LocalFrame frame_;
  PurePursuit pursuit_;
  int base_fd_;
  std::optional<Point> p_;  // east, north of the last GGA
  long commands_ = 0;
};

[[noreturn]] void Usage(const std::string& why) {
  std::fprintf(stderr,
               "hil_example_pursuit_controller: %s\nusage: hil_example_pursuit_controller --path "
               "FILE --origin LAT,LON,H --nav NMEA_IN --base TTY [--speed M/S] [--lookahead M] "
               "[--track M] [--wheel-radius M] [--counts-per-rev N] [--pid-rate HZ]\n",
               why.c_str());
  std::exit(2);
}

double Positive(const std::string& key, const char* v) {
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (end == v || *end != '\0' || !(x > 0)) Usage(key + ": not a positive number: " + v);
  return x;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; i += 2) {
    const std::string k = argv[i];
    if (i + 1 >= argc) Usage("missing the value of " + k);
    const char* v = argv[i + 1];
    if (k == "--path")
      o.path = v;
    else if (k == "--nav")
      o.nav = v;
    else if (k == "--base")
      o.base = v;
    else if (k == "--origin") {
      if (std::sscanf(v, "%lf,%lf,%lf", &o.origin[0], &o.origin[1], &o.origin[2]) != 3)
        Usage("--origin: expected LAT,LON,H");
    } else if (k == "--speed")
      o.speed_mps = Positive(k, v);
    else if (k == "--lookahead")
      o.lookahead_m = Positive(k, v);
    else if (k == "--track")
      o.track_m = Positive(k, v);
    else if (k == "--wheel-radius")
      o.wheel_radius_m = Positive(k, v);
    else if (k == "--counts-per-rev")
      o.counts_per_rev = Positive(k, v);
    else if (k == "--pid-rate")
      o.pid_rate_hz = Positive(k, v);
    else
      Usage("unknown option " + k);
  }
  if (o.path.empty() || o.nav.empty() || o.base.empty())
    Usage("--path, --origin, --nav and --base are required");
  return o;
}

int OpenBase(const std::string& tty) {
  const int fd = open(tty.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (termios t{}; fd >= 0 && tcgetattr(fd, &t) == 0) {
    cfmakeraw(&t);
    cfsetspeed(&t, B57600);
    tcsetattr(fd, TCSANOW, &t);
  }
  return fd;
}

// Reads the solution and the base's replies until either ends.
void Loop(Controller& ctl, int nav_fd, int base_fd) {
  std::array<pollfd, 2> fds{{{nav_fd, POLLIN, 0}, {base_fd, POLLIN, 0}}};
  std::array<char, 4096> buf{};
  std::string pending;
  for (;;) {
    if (poll(fds.data(), fds.size(), -1) < 0) continue;                        // EINTR
    if (fds[1].revents && read(base_fd, buf.data(), buf.size()) <= 0) return;  // "OK": dropped
    if (!fds[0].revents) continue;
    const ssize_t n = read(nav_fd, buf.data(), buf.size());
    if (n <= 0) return;  // the estimator's output ended
    pending.append(buf.data(), static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos; pending.erase(0, nl + 1))
      ctl.OnLine(pending.substr(0, nl));
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
  std::vector<Point> path;
  try {
    path = hil_example::ReadPathPolyline(o.path);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "hil_example_pursuit_controller: %s\n", e.what());
    return 2;
  }
  const int base_fd = OpenBase(o.base);
  const int nav_fd = base_fd < 0 ? -1 : open(o.nav.c_str(), O_RDONLY | O_CLOEXEC);
  if (nav_fd < 0) {
    std::perror("hil_example_pursuit_controller: cannot open the base or the solution input");
    return 1;
  }
  Controller ctl(o, std::move(path), base_fd);
  Loop(ctl, nav_fd, base_fd);
  std::fprintf(stderr, "hil_example_pursuit_controller: stopped; commands=%ld\n", ctl.commands());
  return 0;
}

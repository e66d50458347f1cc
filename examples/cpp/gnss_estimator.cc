// Example estimator for hil (examples/README.md): a GNSS-only constant-velocity Kalman filter, the
// C++ twin of examples/python/gnss_estimator.py. Reads the emulated receiver's NMEA 0183 (RMC for
// the date, GGA for the fix) from its serial link, filters east, north and up apart, and writes
// one JSON object a line on stdout: hil's `json_stdout` contract (vectors/scenarios/README.md).
// The estimate describes the antenna (estimator.reference_point: antenna). Standard library and
// POSIX only; not part of the product (built as an example, never installed).
//
// Usage: hil_example_gnss_estimator --gnss TTY [--baud 9600] [--accel-psd M2/S3] [--fix-std-m M]
//                                   [--fix-vertical-std-m M]
#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <optional>
#include <string>

#include "local_frame.h"
#include "nmea_fields.h"

namespace {

using hil_example::LocalFrame;

struct Options {
  std::string gnss;
  int baud = 9600;
  double accel_psd = 0.01;  // m²/s³ per axis: our choice, a vehicle at a steady field speed
  double fix_std_m = 0.5;   // per axis at HDOP 1: our choice, a standalone u-blox 5 class
  double fix_vertical_std_m = 1.5;  // at HDOP 1: our choice
};

// Constant-velocity Kalman filter of one axis: state (position, velocity).
struct AxisFilter {
  double q = 0, x0 = 0, x1 = 0, p00 = 0, p01 = 0, p11 = 4.0;  // velocity: 2 m/s (1σ) at first

  void Predict(double dt) {
    x0 += dt * x1;
    p00 += dt * 2.0 * p01 + dt * dt * p11 + q * dt * dt * dt / 3.0;
    p01 += dt * p11 + q * dt * dt / 2.0;
    p11 += q * dt;
  }
  void Update(double z, double r) {
    const double s = p00 + r, k0 = p00 / s, k1 = p01 / s, y = z - x0;
    x0 += k0 * y;
    x1 += k1 * y;
    const double n00 = (1 - k0) * p00, n01 = (1 - k0) * p01, n11 = p11 - k1 * p01;
    p00 = n00;
    p01 = n01;
    p11 = n11;
  }
};

class Estimator {
 public:
  explicit Estimator(const Options& o) : o_(o) {}

  void OnLine(const std::string& line) {
    const auto f = hil_example::NmeaFields(line);
    if (!f || f->empty()) return;
    const std::string_view type = hil_example::SentenceType((*f)[0]);
    if (type == "RMC" && f->size() >= 10 && (*f)[9].size() == 6) {
      const std::string& d = (*f)[9];
      std::tm tm{};
      tm.tm_mday = std::atoi(d.substr(0, 2).c_str());
      tm.tm_mon = std::atoi(d.substr(2, 2).c_str()) - 1;
      tm.tm_year = 100 + std::atoi(d.substr(4, 2).c_str());
      date_unix_s_ = static_cast<double>(timegm(&tm));
    } else if (type == "GGA" && hil_example::GgaHasFix(*f) && date_unix_s_) {
      const double hdop = (*f)[8].empty() ? 1.0 : std::atof((*f)[8].c_str());
      OnFix(*date_unix_s_ + hil_example::SecondsOfDay((*f)[1]),
            hil_example::NmeaDegrees((*f)[2], (*f)[3], 2),
            hil_example::NmeaDegrees((*f)[4], (*f)[5], 3), hil_example::GgaEllipsoidalHeight(*f),
            hdop);
    }
  }

 private:
  void OnFix(double t_s, double lat, double lon, double h, double hdop) {
    const double r_h = std::pow(o_.fix_std_m * hdop, 2),
                 r_v = std::pow(o_.fix_vertical_std_m * hdop, 2);
    if (!frame_) {
      frame_.emplace(lat, lon, h);
      for (int k = 0; k < 3; ++k) axes_[k] = {o_.accel_psd, 0, 0, k == 2 ? r_v : r_h, 0, 4.0};
    } else {
      const double dt = t_s - t_s_;
      if (dt <= 0) return;  // a repeated or older epoch
      const std::array<double, 3> z = frame_->ToEnu(lat, lon, h);
      for (int k = 0; k < 3; ++k) {
        axes_[k].Predict(dt);
        axes_[k].Update(z[k], k == 2 ? r_v : r_h);
      }
    }
    t_s_ = t_s;
    Write();
  }
  void Write() const {
    const std::array<double, 3> lla = frame_->ToLla({axes_[0].x0, axes_[1].x0, axes_[2].x0});
    std::printf(
        "{\"tov_unix_ns\": %lld, \"lat_deg\": %.9f, \"lon_deg\": %.9f, \"height_m\": %.4f, "
        "\"vel_enu_mps\": [%.4f, %.4f, %.4f], \"pos_std_enu_m\": [%.4f, %.4f, %.4f]}\n",
        std::llround(t_s_ * 1e9), lla[0], lla[1], lla[2], axes_[0].x1, axes_[1].x1, axes_[2].x1,
        std::sqrt(axes_[0].p00), std::sqrt(axes_[1].p00), std::sqrt(axes_[2].p00));
    std::fflush(stdout);
  }

  Options o_;
  std::optional<double> date_unix_s_;  // midnight UTC of the RMC's date
  std::optional<LocalFrame> frame_;    // about the first fix
  std::array<AxisFilter, 3> axes_{};
  double t_s_ = 0;
};

[[noreturn]] void Usage(const char* why) {
  std::fprintf(stderr,
               "hil_example_gnss_estimator: %s\nusage: hil_example_gnss_estimator --gnss TTY "
               "[--baud 9600] [--accel-psd M2/S3] [--fix-std-m M] [--fix-vertical-std-m M]\n",
               why);
  std::exit(2);
}

double Positive(const std::string& key, const char* v) {
  char* end = nullptr;
  const double x = std::strtod(v, &end);
  if (end == v || *end != '\0' || !(x > 0)) Usage((key + ": not a positive number: " + v).c_str());
  return x;
}

Options Parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; i += 2) {
    const std::string k = argv[i];
    if (i + 1 >= argc) Usage(("missing the value of " + k).c_str());
    const char* v = argv[i + 1];
    if (k == "--gnss") {
      o.gnss = v;
    } else if (k == "--baud") {
      o.baud = static_cast<int>(Positive(k, v));
    } else if (k == "--accel-psd") {
      o.accel_psd = Positive(k, v);
    } else if (k == "--fix-std-m") {
      o.fix_std_m = Positive(k, v);
    } else if (k == "--fix-vertical-std-m") {
      o.fix_vertical_std_m = Positive(k, v);
    } else {
      Usage(("unknown option " + k).c_str());
    }
  }
  if (o.gnss.empty()) Usage("--gnss is required");
  return o;
}

speed_t Speed(int baud) {
  switch (baud) {
    case 4800:
      return B4800;
    case 9600:
      return B9600;
    case 19200:
      return B19200;
    case 38400:
      return B38400;
    case 57600:
      return B57600;
    case 115200:
      return B115200;
    case 230400:
      return B230400;
    default:
      Usage("--baud: 4800, 9600, 19200, 38400, 57600, 115200 or 230400");
  }
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = Parse(argc, argv);
  const speed_t speed = Speed(o.baud);
  const int fd = open(o.gnss.c_str(), O_RDONLY | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) {
    std::perror(("hil_example_gnss_estimator: " + o.gnss).c_str());
    return 1;
  }
  if (termios t{}; tcgetattr(fd, &t) == 0) {  // not a terminal (a file): read it as it is
    cfmakeraw(&t);
    cfsetspeed(&t, speed);
    tcsetattr(fd, TCSANOW, &t);
  }
  Estimator est(o);
  std::string pending;
  std::array<char, 4096> buf{};
  for (;;) {
    const ssize_t n = read(fd, buf.data(), buf.size());
    if (n <= 0) return 0;  // end of input, or EIO: the pty's other side closed (the run ended)
    pending.append(buf.data(), static_cast<std::size_t>(n));
    for (std::size_t nl; (nl = pending.find('\n')) != std::string::npos; pending.erase(0, nl + 1))
      est.OnLine(pending.substr(0, nl));
  }
}

// navd — the production GNSS/INS estimator daemon.
//
// Reads its devices (see navd.conf.example), feeds the estimator, and writes the solution as JSON
// lines. Runs until SIGTERM/SIGINT; survives devices that close and reopen.

#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <numbers>
#include <string>

#include "hil/estimator/config_file.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/nmea_epoch.h"
#include "hil/estimator/nav_solution.h"
#include "hil/estimator/navd_config.h"
#include "serial_device.h"

namespace {

volatile std::sig_atomic_t g_stop = 0;
void OnSignal(int) { g_stop = 1; }

void PrintUsage() {
  std::printf(
      "usage: navd --config FILE\n"
      "  The production GNSS/INS estimator daemon. Reads the devices named in FILE and writes one\n"
      "  JSON object per solution (time of validity, position, velocity, status) to [output] json.\n"
      "options:\n"
      "  --config FILE   configuration (INI: [input] gnss_device, gnss_baud; [time] leap_seconds;\n"
      "                  [filter] mode; [output] json)\n"
      "  --help          this text\n"
      "example:\n"
      "  navd --config /etc/navd.conf\n");
}

}  // namespace

int main(int argc, char** argv) {
  std::string config_path;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--help" || a == "-h") {
      PrintUsage();
      return 0;
    }
    if (a == "--config" && i + 1 < argc) {
      config_path = argv[++i];
    } else {
      std::fprintf(stderr, "navd: unknown option '%s' (see navd --help)\n", a.c_str());
      return 2;
    }
  }
  if (config_path.empty()) {
    std::fprintf(stderr, "navd: --config FILE is required (see navd --help)\n");
    return 2;
  }
  hil::estimator::NavdConfig cfg;
  try {
    cfg = hil::estimator::NavdConfig::FromFile(hil::estimator::ConfigFile::Load(config_path));
  } catch (const hil::estimator::ConfigError& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return 2;
  }

  FILE* out = stdout;
  if (cfg.json_path != "-") {
    out = std::fopen(cfg.json_path.c_str(), "w");
    if (!out) {
      std::fprintf(stderr, "navd: cannot write %s: %s\n", cfg.json_path.c_str(), std::strerror(errno));
      return 2;
    }
  }
  struct sigaction sa {};
  sa.sa_handler = OnSignal;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  signal(SIGPIPE, SIG_IGN);

  hil::estimator::drivers::NmeaEpochAssembler assembler;
  hil::estimator::drivers::NmeaDecoder decoder([&](const hil::estimator::drivers::NmeaFix& fix) {
    const auto m = assembler.Add(fix);
    if (!m) return;
    hil::estimator::NavSolution s;
    s.tov_unix_ns = m->tov_unix_ns;
    s.lat_deg = m->lat_deg;
    s.lon_deg = m->lon_deg;
    s.height_m = m->height_m;
    if (m->speed_mps) {
      const double course = m->course_deg.value_or(0.0) * std::numbers::pi / 180.0;
      s.vel_enu_mps = {*m->speed_mps * std::sin(course), *m->speed_mps * std::cos(course), 0.0};
      if (m->course_deg) s.yaw_deg = *m->course_deg;
    }
    const double sigma = m->hdop.value_or(5.0) * 2.5 / std::numbers::sqrt2;  // UERE ≈ 2.5 m
    s.pos_std_enu_m = {sigma, sigma, 2.0 * sigma};
    s.mode = "gnss_only";
    const std::string line = hil::estimator::ToJsonLine(s);
    std::fwrite(line.data(), 1, line.size(), out);
    std::fflush(out);
  });

  hil::navd::SerialDevice gnss(cfg.gnss_device, cfg.gnss_baud);
  std::string buf;
  while (!g_stop) {
    if (gnss.EnsureOpen() < 0) {
      usleep(100000);
      continue;
    }
    pollfd p{gnss.fd(), POLLIN, 0};
    const int r = poll(&p, 1, 200);
    if (r <= 0) continue;
    buf.clear();
    const bool alive = gnss.Read(buf);
    decoder.Feed(buf);
    if (!alive) usleep(100000);
  }
  const auto& st = decoder.stats();
  std::fprintf(stderr,
               "navd: stopped; nmea ok=%llu bad_checksum=%llu malformed=%llu unsupported=%llu garbage_bytes=%llu "
               "reopens=%llu\n",
               static_cast<unsigned long long>(st.sentences_ok), static_cast<unsigned long long>(st.bad_checksum),
               static_cast<unsigned long long>(st.malformed), static_cast<unsigned long long>(st.unsupported),
               static_cast<unsigned long long>(st.garbage_bytes), static_cast<unsigned long long>(gnss.reopen_count()));
  if (out != stdout) std::fclose(out);
  return 0;
}

// A u-blox host driver that lives by the wall clock, as PX4's GPS driver does (PX4-GPSDrivers'
// ubx.cpp with PX4's gps.cpp around it; written from their documented behaviour, no code of
// theirs): it configures the receiver one CFG command at a time, waiting for each ACK with a
// 250 ms timeout measured with clock_gettime(CLOCK_MONOTONIC) and resending up to 3 times;
// each read first polls with the time left, then sleeps 20 ms (PX4's GPS_WAIT_BEFORE_READ: more
// bytes per read() call), then reads and stamps what it read with clock_gettime. Without hil's
// clock (libhil_lockstep.so) its dialogue depends on when the machine ran it; with it, on
// emulated time only.
//
//   ubx_timeout_driver DEVICE READS_LOG [--listen]
//
// --listen: the device opened read-only and nothing configured; it only reads and stamps (an
// open loop hil may write ahead for, hil run --lockstep's lookahead).
//
// stdout: one JSON solution line per NAV-POSLLH once NAV-TIMEGPS has given the week (hil's
// json_stdout). READS_LOG: one line per read, "t_monotonic_ns hex-bytes", and one per command,
// "# t_monotonic_ns CMD name result attempts".
#include <fcntl.h>
#include <poll.h>
#include <termios.h>
#include <time.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "hil/estimator/drivers/ubx_configurator.h"
#include "hil/estimator/drivers/ubx_decoder.h"

namespace {

using hil::estimator::drivers::UbxCommand;
using hil::estimator::drivers::UbxDecoder;
using hil::estimator::drivers::UbxMessage;

constexpr std::int64_t kAckTimeoutNs = 250'000'000;  // PX4's UBX_CONFIG_TIMEOUT
constexpr int kAttempts = 3;
constexpr useconds_t kWaitBeforeReadUs = 20'000;  // PX4's GPS_WAIT_BEFORE_READ
constexpr std::uint8_t kAckClass = 0x05, kAckAck = 0x01, kNavClass = 0x01, kNavPosllh = 0x02,
                       kNavTimegps = 0x20;
// GPS time 0 in Unix time (1980-01-06)
constexpr std::int64_t kGpsEpochUnixNs = 315'964'800LL * 1'000'000'000LL;
constexpr std::int64_t kWeekNs = 604'800LL * 1'000'000'000LL;

std::int64_t MonotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000LL + ts.tv_nsec;
}

struct Driver {
  int fd = -1;
  std::FILE* log = nullptr;
  UbxDecoder decoder{[this](const UbxMessage& m) { OnMessage(m); }};
  const UbxCommand* waiting = nullptr;  // the command whose ACK is awaited
  bool acked = false;
  int week = -1, leap_s = 0;

  void OnMessage(const UbxMessage& m) {
    if (waiting && m.cls == kAckClass && m.id == kAckAck && m.ack_cls == waiting->cls &&
        m.ack_id == waiting->id)
      acked = true;
    if (m.cls == kNavClass && m.id == kNavTimegps && m.week > 0) {
      week = m.week;
      leap_s = m.leap_s;
    }
    if (m.cls == kNavClass && m.id == kNavPosllh && week > 0) {
      const std::int64_t tov = kGpsEpochUnixNs + week * kWeekNs +
                               static_cast<std::int64_t>(m.itow_ms) * 1'000'000 -
                               static_cast<std::int64_t>(leap_s) * 1'000'000'000;
      std::printf("{\"tov_unix_ns\":%lld,\"lat_deg\":%.9f,\"lon_deg\":%.9f,\"height_m\":%.3f}\n",
                  static_cast<long long>(tov), m.lat_deg, m.lon_deg, m.height_m);
      std::fflush(stdout);
    }
  }

  // One read as PX4's driver does it: poll with the time left, wait a little for more bytes,
  // read, stamp. False when the device failed.
  bool ReadOnce(int timeout_ms) {
    pollfd p{fd, POLLIN, 0};
    const int ready = poll(&p, 1, timeout_ms);
    if (ready < 0) return false;
    if (ready == 0) return true;
    usleep(kWaitBeforeReadUs);
    char buf[4096];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) return n == 0;
    std::fprintf(log, "%lld ", static_cast<long long>(MonotonicNs()));
    for (ssize_t i = 0; i < n; ++i) std::fprintf(log, "%02x", static_cast<unsigned char>(buf[i]));
    std::fputc('\n', log);
    decoder.Feed(std::string_view(buf, static_cast<std::size_t>(n)));
    return true;
  }

  // Sends `c` and waits for its ACK-ACK, 250 ms per attempt.
  bool Configure(const UbxCommand& c) {
    waiting = &c;
    acked = false;
    int attempt = 0;
    while (!acked && attempt < kAttempts) {
      ++attempt;
      if (write(fd, c.frame.data(), c.frame.size()) != static_cast<ssize_t>(c.frame.size()))
        return false;
      const std::int64_t deadline = MonotonicNs() + kAckTimeoutNs;
      for (std::int64_t left = kAckTimeoutNs; !acked && left > 0; left = deadline - MonotonicNs()) {
        if (!ReadOnce(static_cast<int>((left + 999'999) / 1'000'000))) return false;
      }
    }
    std::fprintf(log, "# %lld CMD %s %s %d\n", static_cast<long long>(MonotonicNs()),
                 c.name.c_str(), acked ? "acked" : "timed-out", attempt);
    waiting = nullptr;
    return true;
  }
};

bool OpenRaw(const char* path, bool read_only, int& fd) {
  fd = open(path, (read_only ? O_RDONLY : O_RDWR) | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return false;
  termios t{};
  if (tcgetattr(fd, &t) != 0) return false;
  cfmakeraw(&t);
  cfsetspeed(&t, B9600);
  t.c_cc[VMIN] = 1;
  t.c_cc[VTIME] = 0;
  return tcsetattr(fd, TCSANOW, &t) == 0;
}

}  // namespace

int main(int argc, char** argv) {
  const bool listen = argc == 4 && std::string(argv[3]) == "--listen";
  if (argc != 3 && !listen) {
    std::fprintf(stderr, "usage: ubx_timeout_driver DEVICE READS_LOG [--listen]\n");
    return 2;
  }
  Driver d;
  if (!OpenRaw(argv[1], listen, d.fd)) {
    std::perror(argv[1]);
    return 1;
  }
  d.log = std::fopen(argv[2], "w");
  if (!d.log) {
    std::perror(argv[2]);
    return 1;
  }
  hil::estimator::drivers::ReceiverSetup want;
  want.ubx_navigation = true;
  want.nmea_off = true;
  const std::vector<UbxCommand> commands = hil::estimator::drivers::UbxSetupCommands(want);
  for (const UbxCommand& c : commands) {
    if (!listen && !d.Configure(c)) return 1;
  }
  std::fflush(d.log);
  for (;;) {
    if (!d.ReadOnce(1000)) return 1;
    std::fflush(d.log);
  }
}

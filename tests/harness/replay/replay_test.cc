// Serial capture round trip over ptys: a real-time SerialEndpoint writes and captures bytes with
// per-byte wall times; `hil replay` (ReplayCaptures) plays that capture into a new pty; what a host
// reads there is identical in bytes and on time within the stated tolerance; the replay's
// re-capture equals the original in bytes and emulated times.
#include "hil/harness/replay/replay.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <thread>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/realtime_pacer.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/links/serial_endpoint.h"

#include "process_temp_dir.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

double Pct(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(p / 100.0 * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(k, v.size() - 1)];
}

// A host reading a pty: every byte with its CLOCK_MONOTONIC arrival time.
class Host {
 public:
  void Start(const std::string& path) {
    thread_ = std::thread([this, path] {
      int fd = -1;
      for (int i = 0; i < 200 && fd < 0; ++i) {
        fd = open(path.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
        if (fd < 0) usleep(5000);
      }
      if (fd < 0) return;
      opened_ = true;
      char buf[256];
      while (!stop_) {
        pollfd p{fd, POLLIN, 0};
        if (poll(&p, 1, 20) <= 0) continue;
        const ssize_t n = read(fd, buf, sizeof buf);
        const WallTime t = WallNow();
        for (ssize_t i = 0; i < n; ++i) {
          bytes_ += buf[i];
          t_wall_.push_back(t);
        }
        if (n > 0) count_ += static_cast<std::size_t>(n);
      }
      close(fd);
    });
  }
  void Stop() {
    usleep(100000);
    stop_ = true;
    thread_.join();
  }
  const std::string& bytes() const { return bytes_; }
  /// Waits (≤ 2 s) until `n` bytes have arrived: closing a pty drops what its host has not read.
  void WaitFor(std::size_t n) const {
    for (int i = 0; i < 400 && count_ < n; ++i) usleep(5000);
  }
  const std::vector<WallTime>& t_wall() const { return t_wall_; }
  /// Waits (<= 1 s) until the host has the link open.
  void WaitOpen() const {
    for (int i = 0; i < 200 && !opened_; ++i) usleep(5000);
  }

 private:
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> opened_{false};
  std::atomic<std::size_t> count_{0};
  std::string bytes_;
  std::vector<WallTime> t_wall_;
};

fs::path TempDir(const char* name) {
  const fs::path d = test::ProcessTempDir(name);
  fs::create_directories(d / "captures");
  return d;
}

std::vector<SerialMessage> Messages(int count) {
  std::vector<SerialMessage> out;
  for (int k = 0; k < count; ++k) {
    SerialMessage m;
    m.t_ready = TimeFromNs(50000000LL + k * 100000000LL);  // 10 Hz
    m.name = "MSG" + std::to_string(k);
    m.bytes =
        "$GPGGA," + std::to_string(k) + ",4807.038,N,01131.000,E,1,08,0.9,545.4,M,46.9,M,,*47\r\n";
    m.bytes += std::string("\xB5\x62\x01\x06\x00\xFF", 6);
    out.push_back(m);
  }
  return out;
}

TEST(ReplayTest, RealtimeCaptureHasPerByteWallTimes) {
  const fs::path dir = TempDir("rt_capture");
  Host host;
  std::size_t total = 0;
  {
    SerialEndpoint ep("ttyGPS", (dir / "ttyGPS").string(), 38400, 4096,
                      (dir / "captures" / "ttyGPS.cap").string());
    host.Start((dir / "ttyGPS").string());
    usleep(50000);
    const link::RealtimePacer pacer(1.0);
    for (const auto& m : Messages(5)) {
      ep.Queue(m);
      total += m.bytes.size();
    }
    while (ep.next_byte_time()) ep.WriteNextByte(pacer);
    EXPECT_EQ(ep.schedule_error_us().count(), total);
    host.WaitFor(total);
  }
  host.Stop();
  EXPECT_EQ(host.bytes().size(), total);
  const Capture c = ReadCapture(dir / "captures" / "ttyGPS.cap");
  EXPECT_EQ(c.header.baud, 38400);
  ASSERT_EQ(c.records.size(), 5u);
  for (const auto& r : c.records) {
    ASSERT_EQ(r.wall_offsets_ns.size(), r.bytes.size());
    EXPECT_EQ(r.byte_period_ns, 260417);  // 10 bits at 38400 baud
    EXPECT_GT(r.t_wall, WallTime{});
    // bytes leave one UART period apart: the last one about (n-1) periods after the first
    const double span = static_cast<double>(r.wall_offsets_ns.back());
    EXPECT_NEAR(span,
                static_cast<double>(r.byte_period_ns) * static_cast<double>(r.bytes.size() - 1),
                20e6);
    EXPECT_TRUE(std::is_sorted(r.wall_offsets_ns.begin(), r.wall_offsets_ns.end()));
  }
}

TEST(ReplayTest, VirtualCaptureRecordsDropsAndEmulatedTimesOnly) {
  const fs::path dir = TempDir("virt_capture");
  Host host;
  {
    SerialEndpoint ep("ttyGPS", (dir / "ttyGPS").string(), 9600, 100,
                      (dir / "captures" / "ttyGPS.cap").string());
    host.Start((dir / "ttyGPS").string());
    usleep(50000);
    auto msgs = Messages(2);
    msgs[1].t_ready = msgs[0].t_ready;  // arrives while the first still fills the 100-byte buffer
    for (const auto& m : msgs) ep.Queue(m);
    ep.WriteAll();
    host.WaitFor(msgs[0].bytes.size());
  }
  host.Stop();
  const Capture c = ReadCapture(dir / "captures" / "ttyGPS.cap");
  // the refused message is captured after the one queued before it (serial_endpoint.h)
  ASSERT_EQ(c.records.size(), 2u);
  EXPECT_EQ(c.records[0].dir, CaptureDir::kTx);
  EXPECT_EQ(c.records[0].name, "MSG0");
  EXPECT_EQ(c.records[0].t_wall, WallTime{});  // virtual mode: deterministic, no wall time
  EXPECT_TRUE(c.records[0].wall_offsets_ns.empty());
  EXPECT_EQ(host.bytes(), c.records[0].bytes);
  EXPECT_EQ(c.records[1].dir, CaptureDir::kDrop);
  EXPECT_EQ(c.records[1].name, "MSG1");
}

TEST(ReplayTest, ReplayedCaptureIsIdenticalInBytesAndOnTime) {
  // GIVEN a capture of 2 s of 10 Hz messages at 38400 baud
  const fs::path dir = TempDir("replay_src");
  {
    Host sink;
    SerialEndpoint ep("ttyGPS", (dir / "ttyGPS").string(), 38400, 4096,
                      (dir / "captures" / "ttyGPS.cap").string());
    sink.Start((dir / "ttyGPS").string());
    sink.WaitOpen();  // virtual mode drops what a link nobody has open would get
    std::size_t n = 0;
    for (const auto& m : Messages(20)) {
      ep.Queue(m);
      n += m.bytes.size();
    }
    ep.WriteAll();  // virtual mode: the capture holds the emulated byte times
    sink.WaitFor(n);
    sink.Stop();
  }
  const Capture original = ReadCapture(dir / "captures" / "ttyGPS.cap");
  ASSERT_EQ(original.records.size(), 20u);
  std::string sent;
  std::vector<Time> t_byte;
  for (const auto& r : original.records) {
    for (std::size_t k = 0; k < r.bytes.size(); ++k) t_byte.push_back(r.t_byte(k));
    sent += r.bytes;
  }

  // WHEN hil replay plays it into a new pty and a host reads it
  const fs::path out = TempDir("replay_out");
  Host host;
  ReplayOptions opt;
  opt.captures = {(dir / "captures" / "ttyGPS.cap").string()};
  opt.out_dir = out.string();
  opt.start_delay_s = 0.3;
  opt.on_links = [&](const auto& links) {
    ASSERT_EQ(links.size(), 1u);
    EXPECT_EQ(links[0].first, "ttyGPS");
    host.Start(links[0].second);
  };
  const ReplayResult r = ReplayCaptures(opt);
  host.Stop();

  // THEN the host got the same bytes, each near its recorded UART time
  ASSERT_EQ(r.bytes, sent.size());
  ASSERT_EQ(host.bytes(), sent);
  std::vector<double> err_us;
  for (std::size_t k = 0; k < sent.size(); ++k) {
    // real time: emulated time since t = 0 is wall time since the replay's start
    const WallTime scheduled = r.wall_start + (t_byte[k] - Time{});
    err_us.push_back(static_cast<double>((host.t_wall()[k] - scheduled).count()) * 1e-3);
  }
  std::printf(
      "HIL-FIGURE pty_replay_arrival_error_us bytes=%zu p50=%.1f p99=%.1f max=%.1f (writer: "
      "p50=%.1f p99=%.1f max=%.1f)\n",
      err_us.size(), Pct(err_us, 50), Pct(err_us, 99), Pct(err_us, 100),
      r.byte_schedule_error_us.Percentile(50), r.byte_schedule_error_us.Percentile(99),
      r.byte_schedule_error_us.Percentile(100));
  // stated tolerance (shared, loaded CI machine): never early beyond the reader's clock, median
  // within 2 ms, 99 % within 20 ms of the recorded time
  EXPECT_GT(Pct(err_us, 0), -100.0);
  EXPECT_LT(Pct(err_us, 50), 2000.0);
  EXPECT_LT(Pct(err_us, 99), 20000.0);

  // AND the replay's re-capture has the original's bytes and emulated times, with wall times
  const Capture again = ReadCapture(out / "captures" / "ttyGPS.cap");
  ASSERT_EQ(again.records.size(), original.records.size());
  for (std::size_t i = 0; i < again.records.size(); ++i) {
    EXPECT_EQ(again.records[i].bytes, original.records[i].bytes);
    EXPECT_EQ(again.records[i].t_emu_ns, original.records[i].t_emu_ns);
    EXPECT_EQ(again.records[i].byte_period_ns, original.records[i].byte_period_ns);
    EXPECT_EQ(again.records[i].wall_offsets_ns.size(), again.records[i].bytes.size());
  }
}

TEST(ReplayTest, UnreadableCaptureIsAClearError) {
  ReplayOptions opt;
  opt.captures = {"/nonexistent/ttyGPS.cap"};
  opt.out_dir = TempDir("replay_bad").string();
  try {
    ReplayCaptures(opt);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/ttyGPS.cap"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hil::harness

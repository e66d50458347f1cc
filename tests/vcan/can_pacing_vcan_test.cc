// The run's CAN link on a real vcan0: CanEndpoint sends device frames at their wall-clock times
// (real-time mode), captures them (candump log + hil capture), and `hil replay` plays that capture
// back frame for frame. Prints the schedule error figures (sent − scheduled; kernel receive time −
// scheduled). HIL_CAN_PACING_S sets the length of the paced run (default 3 s).
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <thread>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/replay/replay.h"

#include "vcan_test_util.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using link::test::Iface;

constexpr std::int64_t kStartUnixNs = 1370851200000000000LL;  // 2013-06-10T08:00:00Z

double Pct(std::vector<double> v, double p) {
  if (v.empty()) return 0;
  std::sort(v.begin(), v.end());
  const auto k = static_cast<std::size_t>(p / 100.0 * static_cast<double>(v.size() - 1) + 0.5);
  return v[std::min(k, v.size() - 1)];
}

std::int64_t ClockNs(clockid_t c) {
  timespec ts{};
  clock_gettime(c, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

// Frames as an IMU/GNSS MCU might send them: 100 Hz J1939 ACCS, 10 Hz NMEA 2000 129025.
std::vector<CanFrame> Schedule(double seconds) {
  std::vector<CanFrame> out;
  for (std::int64_t k = 0; k * 10000000LL < static_cast<std::int64_t>(seconds * 1e9); ++k) {
    CanFrame f;
    f.t = TimeFromNs(k * 10000000LL + 500000);
    f.id = k % 10 == 0 ? 0x09F80180 : 0x0CF02DE2;
    f.extended = true;
    f.len = 8;
    for (std::uint8_t i = 0; i < 8; ++i) f.data[i] = static_cast<std::uint8_t>(k * 7 + i);
    out.push_back(f);
  }
  return out;
}

struct Receiver {
  link::SocketCanPort port{Iface()};
  std::vector<link::ReceivedCanFrame> frames;
  std::atomic<bool> stop{false};
  std::thread thread;
  void Start() {
    thread = std::thread([this] {
      while (!stop) {
        if (auto r = port.Receive(std::chrono::milliseconds(20)); r && !r->frame.error)
          frames.push_back(*r);
      }
    });
  }
  void Finish() {
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    stop = true;
    thread.join();
  }
};

fs::path TempDir(const char* name) {
  const fs::path d =
      fs::temp_directory_path() / (std::string("hil_") + name + "_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

TEST(CanPacingVcanTest, RealtimeFramesLeaveOnScheduleAndAreCaptured) {
  const char* env = std::getenv("HIL_CAN_PACING_S");
  const double seconds = env ? std::atof(env) : 3.0;
  const auto schedule = Schedule(seconds);
  const fs::path dir = TempDir("can_pacing");
  link::RealtimePacer::RequestRealtimeScheduling();
  Receiver rx;
  rx.Start();
  std::vector<double> rx_err_us;
  std::optional<link::RealtimePacer> pacer;
  std::int64_t real_minus_mono = 0;
  {
    CanEndpoint ep(Iface(), dir.string(), UnixTimeFromNs(kStartUnixNs));
    for (const CanFrame& f : schedule) ep.Queue(f);
    // the kernel turns receive stamping on from a work item after the first socket asks for it;
    // frames before that get each socket's own read time (a run's sockets are long open)
    std::this_thread::sleep_for(std::chrono::milliseconds(300));
    pacer.emplace(1.0);
    // CLOCK_REALTIME of emulated t = 0, to compare kernel receive stamps with the schedule
    real_minus_mono = ClockNs(CLOCK_REALTIME) - ClockNs(CLOCK_MONOTONIC);
    while (ep.next_frame_time()) ep.SendNext(*pacer);
    ep.FinishCapture(std::chrono::milliseconds(200));
    EXPECT_TRUE(ep.PollBus(Time{}, &*pacer).empty());  // our own frames are not others' frames
    rx.Finish();
    ASSERT_EQ(ep.stats().frames_sent, schedule.size());
    EXPECT_EQ(ep.stats().own_frames_received, schedule.size());
    ASSERT_EQ(rx.frames.size(), schedule.size());
    for (std::size_t i = 0; i < schedule.size(); ++i) {
      ASSERT_EQ(rx.frames[i].frame, link::FromDeviceFrame(schedule[i])) << i;
      const std::int64_t scheduled_real = ToNs(pacer->WallTimeOf(schedule[i].t)) + real_minus_mono;
      rx_err_us.push_back(static_cast<double>(ToNs(rx.frames[i].t_kernel) - scheduled_real) * 1e-3);
    }
    const auto& e = ep.schedule_error_us();
    ASSERT_EQ(e.count(), schedule.size());
    std::printf(
        "HIL-FIGURE can_send_schedule_error_us frames=%zu span_s=%.1f p50=%.1f p99=%.1f max=%.1f\n",
        static_cast<std::size_t>(e.count()), seconds, e.Percentile(50), e.Percentile(99),
        e.Percentile(100));
    std::printf(
        "HIL-FIGURE can_kernel_rx_schedule_error_us frames=%zu p50=%.1f p99=%.1f max=%.1f\n",
        rx_err_us.size(), Pct(rx_err_us, 50), Pct(rx_err_us, 99), Pct(rx_err_us, 100));
    // never early: a frame leaves at or after its time
    EXPECT_GE(e.min(), 0.0);
  }
  // both captures hold every frame, in bus order, at the time the bus carried it (issue 15.3):
  // the emulated time of its kernel receive stamp, the same stamp another socket (candump) got
  const link::CandumpLog log = link::ReadCandumpLog(dir / (Iface() + ".candump"));
  ASSERT_EQ(log.records.size(), schedule.size());
  const Capture cap = ReadCapture(dir / (Iface() + ".cap"));
  ASSERT_EQ(cap.records.size(), schedule.size());
  EXPECT_EQ(cap.header.kind, "can");
  EXPECT_EQ(cap.header.start_utc, UnixTimeFromNs(kStartUnixNs));
  std::vector<double> stamp_err_us;
  std::size_t worst = 0;
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    EXPECT_EQ(log.records[i].frame, link::FromDeviceFrame(schedule[i]));
    const std::int64_t on_bus_ns =
        ToNs(pacer->SimTimeOfWall(WallTimeFromNs(ToNs(rx.frames[i].t_kernel) - real_minus_mono)));
    stamp_err_us.push_back(
        std::abs(static_cast<double>(ToNs(log.records[i].t) - kStartUnixNs - on_bus_ns)) * 1e-3);
    if (stamp_err_us.back() > stamp_err_us[worst]) worst = i;
    EXPECT_GE(cap.records[i].t_emu_ns, ToNs(schedule[i].t));  // not before it was scheduled
    if (i > 0) {
      EXPECT_GE(ToNs(log.records[i].t), ToNs(log.records[i - 1].t));
    }
    EXPECT_EQ(cap.records[i].dir, CaptureDir::kFrameTx);
    EXPECT_EQ(cap.records[i].t_emu_ns / 1000, (ToNs(log.records[i].t) - kStartUnixNs) / 1000);
    EXPECT_GT(cap.records[i].t_wall, WallTime{});
  }
  std::printf("HIL-FIGURE can_capture_vs_other_socket_us frames=%zu p50=%.1f p99=%.1f max=%.1f\n",
              stamp_err_us.size(), Pct(stamp_err_us, 50), Pct(stamp_err_us, 99),
              Pct(stamp_err_us, 100));
  EXPECT_LT(Pct(stamp_err_us, 100), 1000.0) << "frame " << worst;  // within 1 ms of candump's
}

TEST(CanPacingVcanTest, VirtualModeSendsAtOnceWithEmulatedTimes) {
  const auto schedule = Schedule(2.0);  // two emulated seconds
  const fs::path dir = TempDir("can_virtual");
  Receiver rx;
  rx.Start();
  const std::int64_t t0 = ClockNs(CLOCK_MONOTONIC);
  {
    CanEndpoint ep(Iface(), dir.string(), UnixTimeFromNs(kStartUnixNs));
    for (const CanFrame& f : schedule) ep.Queue(f);
    ep.SendAll();
    EXPECT_FALSE(ep.next_frame_time().has_value());
  }
  const double wall_s = static_cast<double>(ClockNs(CLOCK_MONOTONIC) - t0) * 1e-9;
  rx.Finish();
  ASSERT_EQ(rx.frames.size(), schedule.size());
  EXPECT_LT(wall_s, 1.5);  // far less than the two emulated seconds
  EXPECT_EQ(link::ReadCandumpLog(dir / (Iface() + ".candump")).records.size(), schedule.size());
}

TEST(CanPacingVcanTest, ReplayedCaptureMatchesTheOriginalFrameForFrame) {
  // a candump log of a run (written as a run writes it) ...
  const fs::path dir = TempDir("can_replay");
  const auto schedule = Schedule(1.5);
  {
    link::CandumpLogWriter w(dir / "run.candump");
    for (const CanFrame& f : schedule)
      w.Write({UnixTimeFromNs(kStartUnixNs + ToNs(f.t)), Iface(), link::FromDeviceFrame(f), 0});
  }
  // ... played by hil replay onto the bus and received there
  Receiver rx;
  rx.Start();
  ReplayOptions opt;
  opt.captures = {(dir / "run.candump").string()};
  opt.out_dir = (dir / "replay").string();
  opt.start_delay_s = 0.1;
  const ReplayResult r = ReplayCaptures(opt);
  rx.Finish();
  ASSERT_EQ(r.frames, schedule.size());
  EXPECT_EQ(r.frames_failed, 0u);
  ASSERT_EQ(rx.frames.size(), schedule.size());
  // the replay's own re-capture: same frames, at the times they crossed the bus
  const link::CandumpLog again =
      link::ReadCandumpLog(dir / "replay" / "captures" / (Iface() + ".candump"));
  ASSERT_EQ(again.records.size(), schedule.size());
  std::vector<double> gap_err_us;
  for (std::size_t i = 0; i < schedule.size(); ++i) {
    EXPECT_EQ(rx.frames[i].frame, link::FromDeviceFrame(schedule[i]));
    EXPECT_EQ(again.records[i].frame, link::FromDeviceFrame(schedule[i]));
    // the re-capture holds the frames as the bus saw them (kernel stamps, issue 15.3): the same
    // spacing another socket on the bus received, within 1 ms
    const std::int64_t captured = ToNs(again.records[i].t) - ToNs(again.records[0].t);
    const std::int64_t received = ToNs(rx.frames[i].t_kernel) - ToNs(rx.frames[0].t_kernel);
    EXPECT_NEAR(static_cast<double>(captured), static_cast<double>(received), 1e6) << i;
    // received spacing vs recorded spacing
    const double got =
        static_cast<double>(ToNs(rx.frames[i].t_kernel) - ToNs(rx.frames[0].t_kernel));
    const double want = static_cast<double>(ToNs(schedule[i].t) - ToNs(schedule[0].t));
    gap_err_us.push_back(std::abs(got - want) * 1e-3);
  }
  std::printf("HIL-FIGURE can_replay_timing_error_us frames=%zu p50=%.1f p99=%.1f max=%.1f\n",
              gap_err_us.size(), Pct(gap_err_us, 50), Pct(gap_err_us, 99), Pct(gap_err_us, 100));
  // the timing error itself is a figure (benchmarks and reports, not a timed test): a TCG VM
  // beside busy neighbours gave p99 from 0.3 to over 20 ms; a replay that waited too long shows as
  // a span far beyond the recording's
  const double span_s =
      static_cast<double>(ToNs(rx.frames.back().t_kernel) - ToNs(rx.frames.front().t_kernel)) *
      1e-9;
  const double want_span_s = ToSeconds(schedule.back().t - schedule.front().t);
  EXPECT_LT(span_s, want_span_s * 3 + 2.0) << "the replay stalled";
  // and paced: a replay that sent everything at once would cross the bus in milliseconds
  EXPECT_GT(span_s, want_span_s * 0.5) << "the replay did not wait for the recorded times";
}

}  // namespace
}  // namespace hil::harness

// navd — the production GNSS/INS estimator daemon.
//
// A thin poll loop: reads its devices (see navd.conf.example), decodes them with the tolerant
// drivers, pushes the samples into the transport-free Navigator, and writes the solution as JSON
// lines (and NMEA 0183 when configured). Runs until SIGTERM/SIGINT; survives devices that close
// and reopen.

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/nmea_epoch.h"
#include "hil/estimator/drivers/razor_imu_adapter.h"
#include "hil/estimator/drivers/razor_text_decoder.h"
#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/input_merge.h"
#include "hil/estimator/navd/nav_solution.h"
#include "hil/estimator/navd/navd_config.h"
#include "hil/estimator/navd/navd_health.h"
#include "hil/estimator/navigator.h"
#include "hil/estimator/outputs/nmea0183_writer.h"

#include "can_imu_input.h"
#include "can_output.h"
#include "gnss_receivers.h"
#include "kfgins_mode.h"
#include "odometry_mode.h"
#include "replay_mode.h"
#include "serial_device.h"
#include "uwb_mode.h"

namespace {

namespace est = hil::estimator;
volatile std::sig_atomic_t g_stop = 0;
std::int64_t MonotonicNs() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}
void OnSignal(int) { g_stop = 1; }

void PrintUsage() {
  std::printf(
      "usage: navd --config FILE\n"
      "  The production GNSS/INS estimator daemon. Reads the devices named in FILE (GNSS "
      "receiver:\n"
      "  NMEA 0183 or UBX; IMU microcontroller: binary frame protocol v1), runs the estimator, and "
      "writes\n"
      "  one JSON object per solution (time of validity, position, velocity, attitude, "
      "covariance,\n"
      "  status) to [output] json, and NMEA 0183 (GGA, RMC, HDT) to [output] nmea_device.\n"
      "options:\n"
      "  --config FILE   configuration (INI; every key is documented in navd.conf.example):\n"
      "                  [input] gnss_device, gnss_device_1 … (multi_gnss), gnss_baud, "
      "gnss_protocol\n"
      "                  (nmea|ubx), gnss_configure, gnss_rate_hz, gnss_nav_pvt, imu_device, "
      "imu_baud, "
      "imu_format\n"
      "                  (mcu|razor_text), merge_window_s\n"
      "                  [imu] source (serial|can), can_interface, source_address, "
      "razor_gnss_latency_s\n"
      "                  [time] leap_seconds\n"
      "                  [filter] mode (ekf|planar2d|gnss_only|imu_only|multi_gnss), lever_arm_m,\n"
      "                  accel_noise, gyro_noise, gyro_scale_std, accel_bias_rw, gyro_bias_rw, "
      "init_accel_bias_std,\n"
      "                  init_gyro_bias_std, gnss_error_tau_s, gnss_error_std_m, nhc_std_mps,\n"
      "                  gate_sigma, fusion_horizon_s, use_gnss_velocity, fix_velocity_ripple,\n"
      "                  gnss_max_latency_s,\n"
      "                  nmea_uere_m, nmea_rtk_fixed_std_m, nmea_rtk_float_std_m, "
      "nmea_velocity_std_mps,\n"
      "                  ubx_acc_scale, ubx_pos_std_floor_m, ubx_vel_std_floor_mps,\n"
      "                  ubx_float_up_std_max_m,\n"
      "                  gnss_float_error_from_receiver (true|false),\n"
      "                  gnss_float_error_tau_s, gnss_float_error_std_m, "
      "gnss_error_vertical_std_m,\n"
      "                  gnss_error_vdop_ref, gnss_velocity_noise (true|false),\n"
      "                  speed_rw, speed_dev_std_mps, speed_dev_tau_s, vehicle_lowpass_tau_s,\n"
      "                  mount_angle_estimation\n"
      "                  (true|false), mount_pitch_std_deg, mount_yaw_std_deg, gyro_scale_z_std,\n"
      "                  gyro_scale_xy_std, gyro_scale_xy_rw_rthz,\n"
      "                  gyro_z_coupling_std_deg, gyro_z_coupling_x_std_deg,\n"
      "                  gyro_z_coupling_y_std_deg, imu_time_residual_std_s, accel_y_force_std,\n"
      "                  antenna_0_m … (multi_gnss)\n"
      "                  [output] json, rate_hz, nmea_device, can_interface, can_log,\n"
      "                  can_source_address, can_rate_hz\n"
      "  --kfgins YAML   offline on a KF-GINS dataset (estimator/doc/kfgins.md)\n"
      "  --replay LOG... --out DIR   a recorded log (hil captures, u-blox/NMEA bytes) in virtual\n"
      "                  time, solutions in KF-GINS files, consistency report (kfgins.md)\n"
      "  --help          this text\n"
      "examples:\n"
      "  navd --config /etc/navd.conf\n"
      "  navd --config navd.conf > solution.jsonl\n");
}

est::NavSolution ToSolution(const est::NavOutput& o, const est::Navigator& nav, int leap_s) {
  est::NavSolution s;
  s.tov_unix_ns = est::UnixNsFromGpsTime(o.t, leap_s);
  s.lat_deg = o.position.lat_deg;
  s.lon_deg = o.position.lon_deg;
  s.height_m = o.position.height_m;
  if (o.has_velocity) {
    s.vel_enu_mps = std::array<double, 3>{o.v_N_mps.x(), o.v_N_mps.y(), o.v_N_mps.z()};
  }
  s.speed_mps =
      o.has_velocity ? std::optional<double>(o.v_N_mps.head<2>().norm()) : o.ground_speed_mps;
  s.pos_std_enu_m = {o.pos_std_enu_m.x(), o.pos_std_enu_m.y(), o.pos_std_enu_m.z()};
  if (o.has_attitude) {
    const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX(),
                          y = o.q_NB * Eigen::Vector3d::UnitY();
    s.yaw_deg =
        std::fmod(90.0 - std::atan2(x.y(), x.x()) * 180.0 / std::numbers::pi + 360.0, 360.0);
    const est::NavMode m = nav.params().mode;
    if (m == est::NavMode::kEkf || m == est::NavMode::kImuOnly) {
      s.pitch_deg = std::asin(std::clamp(x.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      s.roll_deg = -std::asin(std::clamp(y.z(), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      s.vel_std_enu_mps = std::array<double, 3>{o.vel_std_enu_mps.x(), o.vel_std_enu_mps.y(),
                                                o.vel_std_enu_mps.z()};
      s.nis_pos = nav.stats().last_nis_pos;
      s.mean_nis_pos = nav.stats().mean_nis_pos;
    }
  }
  s.mode = est::NavModeName(nav.params().mode);
  s.status_flags = o.status;
  return s;
}

// Reads the command line into `config_path`; an exit code when navd is to stop at once
// (--help, or a usage error after its message), nullopt to run.
std::optional<int> ParseArgs(int argc, char** argv, std::string& config_path) {
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
  return std::nullopt;
}

// Where the solutions go: JSON lines, NMEA 0183 ([output] nmea_device) and NMEA 2000 over CAN.
struct SolutionOutputs {
  FILE* out = stdout;
  int nmea_fd = -1;
  std::unique_ptr<hil::navd::CanOutput> can;
  std::uint64_t nmea_write_errors = 0;
  std::optional<est::GpsTime> last_emitted;
  // CLOCK_MONOTONIC time of the oldest JSON line not flushed yet (-1: none). The lines go out in
  // one write when navd is about to wait for input (FlushHeld), or once the oldest has waited
  // kMaxJsonHoldNs: one write per batch of input, not per solution, and never a late line.
  std::int64_t json_held_since_ns = -1;
  static constexpr std::int64_t kMaxJsonHoldNs = 2'000'000;
  static constexpr std::size_t kJsonBufferBytes = 1 << 16;

  // Opens every configured output; false, after a message naming it, when one cannot be opened.
  bool Open(const est::NavdConfig& cfg) {
    if (cfg.json_path != "-") {
      out = std::fopen(cfg.json_path.c_str(), "w");
      if (!out) {
        std::fprintf(stderr, "navd: cannot write %s: %s\n", cfg.json_path.c_str(),
                     std::strerror(errno));
        return false;
      }
    }
    std::setvbuf(out, nullptr, _IOFBF, kJsonBufferBytes);  // before any output (FlushHeld)
    if (!cfg.nmea_device.empty()) {
      nmea_fd = open(cfg.nmea_device.c_str(), O_WRONLY | O_NOCTTY | O_NONBLOCK | O_CREAT | O_APPEND,
                     0644);
      if (nmea_fd < 0) {
        std::fprintf(stderr, "navd: cannot open [output] nmea_device %s: %s\n",
                     cfg.nmea_device.c_str(), std::strerror(errno));
        return false;
      }
    }
    try {
      can = std::make_unique<hil::navd::CanOutput>(
          cfg.can_interface, cfg.can_log, static_cast<std::uint8_t>(cfg.can_source_address),
          cfg.can_rate_hz);
    } catch (const std::runtime_error& e) {
      std::fprintf(stderr, "navd: [output] %s\n", e.what());
      return false;
    }
    return true;
  }

  // One solution to every output.
  void Emit(const est::NavOutput& o, const est::Navigator& nav, est::NavdHealth& health,
            int leap_s) {
    std::string line = est::ToJsonLine(ToSolution(o, nav, leap_s));
    health.AppendTo(line, o.t);
    std::fwrite(line.data(), 1, line.size(), out);
    const std::int64_t now = MonotonicNs();
    if (json_held_since_ns < 0) json_held_since_ns = now;
    if (now - json_held_since_ns >= kMaxJsonHoldNs) FlushHeld();
    if (nmea_fd >= 0) {
      const std::string s = est::outputs::FormatNmea0183(o, est::UnixNsFromGpsTime(o.t, leap_s));
      if (write(nmea_fd, s.data(), s.size()) != static_cast<ssize_t>(s.size())) ++nmea_write_errors;
    }
    can->Publish(o, est::UnixNsFromGpsTime(o.t, leap_s));
    last_emitted = o.t;
  }

  // The JSON lines written since the last flush, out now (navd waits for input next).
  void FlushHeld() {
    if (json_held_since_ns < 0) return;
    std::fflush(out);
    json_held_since_ns = -1;
  }

  void Close() {
    FlushHeld();
    if (out != stdout) std::fclose(out);
    if (nmea_fd >= 0) close(nmea_fd);
  }
};

void InstallSignalHandlers() {
  struct sigaction sa {};
  sa.sa_handler = OnSignal;
  sigaction(SIGTERM, &sa, nullptr);
  sigaction(SIGINT, &sa, nullptr);
  signal(SIGPIPE, SIG_IGN);
}

// The J1939 IMU on CAN when [imu] source is can; false, after a message, when it cannot be opened.
bool OpenCanImu(const est::NavdConfig& cfg, std::unique_ptr<hil::navd::CanImuInput>& can_imu) {
  if (!cfg.imu.from_can()) return true;
  est::drivers::J1939ImuDecoderConfig jc;
  jc.any_source = cfg.imu.source_address < 0;
  jc.source_address =
      static_cast<std::uint8_t>(cfg.imu.source_address < 0 ? 0 : cfg.imu.source_address);
  try {
    can_imu = std::make_unique<hil::navd::CanImuInput>(cfg.imu.can_interface, jc);
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return false;
  }
  return true;
}

// A serial input device with what its bytes are fed to.
using SerialInput = std::pair<hil::navd::SerialDevice*, std::function<void(const std::string&)>>;

// Polls the inputs (and the CAN IMU socket) until SIGTERM/SIGINT, feeding what each one reads;
// `before_wait` runs before every poll() that may wait.
void PollInputs(const std::vector<SerialInput>& inputs, hil::navd::CanImuInput* can_imu,
                hil::navd::GnssReceivers& receivers,
                const std::function<void(const est::ImuSample&)>& on_imu,
                const std::function<void()>& before_wait) {
  std::vector<pollfd> p;
  std::vector<std::size_t> polled;
  std::string buf;
  bool drained = true;  // the last reads took every byte their devices had
  while (!g_stop) {
    receivers.Service(MonotonicNs());  // start-up CFG
    p.clear();
    polled.clear();
    for (std::size_t k = 0; k < inputs.size(); ++k) {
      hil::navd::SerialDevice* d = inputs[k].first;
      if (d->path().empty() || d->EnsureOpen() < 0) continue;
      p.push_back({d->fd(), POLLIN, 0});
      polled.push_back(k);
    }
    if (can_imu) {
      p.push_back({can_imu->fd(), POLLIN, 0});
      polled.push_back(inputs.size());  // past the serial inputs: the CAN socket
    }
    if (p.empty()) {
      before_wait();
      usleep(100000);
      continue;
    }
    // every device read to its last byte: poll() will probably wait (else a look first)
    int ready = drained ? 0 : poll(p.data(), p.size(), 0);
    if (ready == 0) {
      before_wait();
      ready = poll(p.data(), p.size(), 200);
    }
    drained = true;
    if (ready <= 0) continue;
    for (std::size_t i = 0; i < p.size(); ++i) {
      if (!(p[i].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (polled[i] == inputs.size()) {
        can_imu->ReadAll(on_imu);
        continue;
      }
      buf.clear();
      const bool alive = inputs[polled[i]].first->Read(buf);
      drained = drained && inputs[polled[i]].first->drained();
      inputs[polled[i]].second(buf);
      if (!alive) usleep(100000);
    }
  }
}

// The counters navd prints on stderr when it stops.
void PrintStopStats(const hil::navd::GnssReceivers& receivers,
                    const est::drivers::McuFrameDecoder& mcu, const est::Navigator& nav,
                    const SolutionOutputs& outputs) {
  const auto st = receivers.nmea_stats();
  const auto ubx_st = receivers.ubx_stats();
  const auto& ns = nav.stats();
  std::fprintf(
      stderr,
      "navd: stopped; nmea ok=%llu bad_checksum=%llu malformed=%llu unsupported=%llu "
      "garbage_bytes=%llu "
      "reopens=%llu; mcu frames=%llu bad_crc=%llu gaps=%llu; imu=%llu late_gnss=%llu fused=%llu "
      "rejected=%llu resets=%llu ubx ok=%llu bad_checksum=%llu nmea_write_errors=%llu "
      "can_frames=%llu can_errors=%llu\n",
      static_cast<unsigned long long>(st.sentences_ok),
      static_cast<unsigned long long>(st.bad_checksum),
      static_cast<unsigned long long>(st.malformed),
      static_cast<unsigned long long>(st.unsupported),
      static_cast<unsigned long long>(st.garbage_bytes),
      static_cast<unsigned long long>(receivers.reopens()),
      static_cast<unsigned long long>(mcu.stats().frames_ok),
      static_cast<unsigned long long>(mcu.stats().bad_crc),
      static_cast<unsigned long long>(mcu.stats().sequence_gaps),
      static_cast<unsigned long long>(ns.imu_samples),
      static_cast<unsigned long long>(ns.gnss_late), static_cast<unsigned long long>(ns.gnss_fused),
      static_cast<unsigned long long>(ns.gnss_rejected),
      static_cast<unsigned long long>(ns.gnss_resets),
      static_cast<unsigned long long>(ubx_st.frames_ok),
      static_cast<unsigned long long>(ubx_st.bad_checksum),
      static_cast<unsigned long long>(outputs.nmea_write_errors),
      static_cast<unsigned long long>(outputs.can->frames_sent()),
      static_cast<unsigned long long>(outputs.can->send_errors()));
}

// The Razor text decoder's and adapter's counters, printed on stop in razor_text format.
void PrintRazorStats(const est::drivers::RazorTextDecoder& razor,
                     const est::drivers::RazorImuAdapter& razor_adapter) {
  std::fprintf(stderr,
               "navd: razor_text lines=%llu bad_lines=%llu garbage_bytes=%llu imu=%llu "
               "no_time=%llu gaps=%llu\n",
               static_cast<unsigned long long>(razor.stats().lines_ok),
               static_cast<unsigned long long>(razor.stats().bad_lines),
               static_cast<unsigned long long>(razor.stats().garbage_bytes),
               static_cast<unsigned long long>(razor_adapter.stats().imu_out),
               static_cast<unsigned long long>(razor_adapter.stats().imu_no_time),
               static_cast<unsigned long long>(razor_adapter.stats().imu_gap));
}

// Every MCU frame with its IMU sample (if any) and the IMU link's counters, into the merge; the
// time of a frame without a sample is the last sample's.
struct McuInput {
  est::drivers::McuImuAdapter adapter;
  est::GpsTime last_t{};
  est::MergeItem Item(const est::drivers::McuFrame& f, const est::drivers::McuDecoderStats& st) {
    est::MergeItem m;
    m.kind = est::MergeItem::Kind::kImu;
    m.from_mcu = true;
    m.frame = f;
    m.imu = adapter.Add(f);
    if (m.imu) last_t = m.imu->t;
    m.t = last_t;
    m.mcu = st;
    m.mcu_adapter = adapter.stats();
    return m;
  }
};

// A decoded GNSS epoch for the merge, with the receivers' counters when the merge holds it.
est::MergeItem GnssItem(const est::GnssSample& g, const hil::navd::GnssReceivers& receivers,
                        bool with_counters) {
  est::MergeItem m;
  m.kind = est::MergeItem::Kind::kGnss;
  m.t = g.t;
  m.link = g.antenna;
  m.gnss = g;
  if (with_counters) m.nmea = receivers.nmea_stats(), m.ubx = receivers.ubx_stats();
  return m;
}

// A J1939 IMU sample for the merge, with the decoder's counters.
est::MergeItem CanImuItem(const est::ImuSample& s, const hil::navd::CanImuInput& can_imu) {
  est::MergeItem m;
  m.kind = est::MergeItem::Kind::kImu;
  m.t = s.t;
  m.imu = s;
  m.j1939 = can_imu.decoder().stats();
  return m;
}

// The health object's sources: the decoders' live counters, or with the input merge the counters
// of the items it released.
est::HealthSources HealthSourcesOf(const est::InputMerge& merge,
                                   const hil::navd::GnssReceivers& receivers,
                                   const est::drivers::McuFrameDecoder& mcu, const McuInput& mcu_in,
                                   const est::Navigator& nav,
                                   const hil::navd::CanImuInput* can_imu) {
  if (merge.enabled()) {
    const est::MergedCounters& c = merge.counters();
    return {&c.nmea, &c.ubx, &c.mcu, &c.mcu_adapter, &nav.stats(), can_imu ? &c.j1939 : nullptr};
  }
  return {&receivers.nmea_totals(),
          &receivers.ubx_totals(),
          &mcu.stats(),
          &mcu_in.adapter.stats(),
          &nav.stats(),
          can_imu ? &can_imu->decoder().stats() : nullptr};
}

// The daemon proper: the inputs, their decoders and the navigator, until SIGTERM/SIGINT; closes
// the outputs after a clean stop.
int Run(const est::NavdConfig& cfg, SolutionOutputs& outputs) {
  est::Navigator nav(cfg.nav);
  const bool imu_mode = est::UsesImu(cfg.mode());
  est::NavdHealth health;  // fault detection: counters and flags in every JSON line
  const hil::navd::GnssReceivers* gnss = nullptr;  // set once the receivers exist
  const auto emit = [&](const est::NavOutput& o) {
    outputs.Emit(o, nav, health, gnss ? gnss->UtcLeapSeconds(cfg.leap_seconds) : cfg.leap_seconds);
  };

  // the Razor text lines carry no time: stamped on arrival, mapped through the GNSS fixes' arrivals
  const bool razor_text = !cfg.imu.from_can() && cfg.imu_format == "razor_text";
  std::int64_t gnss_read_ns = 0, imu_read_ns = 0;
  est::drivers::RazorImuAdapter razor_adapter;
  // GNSS-only modes, and IMU modes whose IMU fell silent: one solution per fix
  const auto use_gnss = [&](const est::GnssSample& g) {
    health.OnGnss(g);
    outputs.can->OnGnss(g);
    if (razor_text) razor_adapter.AddGnssArrival(gnss_read_ns, g.t, cfg.imu.razor_gnss_latency_s);
    nav.Push(g);
    if (imu_mode && !nav.ImuLost()) return;
    const est::NavOutput o = nav.Output();
    if (o.valid && o.t != outputs.last_emitted) emit(o);
  };
  const est::Nanoseconds period{std::llround(1e9 / cfg.output_rate_hz)};
  const auto on_imu = [&](const est::ImuSample& s) {  // each sample: the filter to the horizon,
    nav.Push(s);                                      // one solution per output period
    if (!imu_mode) return;
    nav.Update();
    if (!nav.aligned()) return;
    const std::optional<est::GpsTime>& last_emitted = outputs.last_emitted;
    if (last_emitted && nav.newest_imu_time().time_since_epoch() / period ==
                            last_emitted->time_since_epoch() / period)
      return;
    const est::NavOutput o = nav.Output();
    if (o.valid && o.t != last_emitted)
      emit(o);  // (a fix stands in for the filter after an IMU loss)
  };
  // every decoded input, in device-time order with [input] merge_window_s, else as it is read
  const auto use = [&](const est::MergeItem& m) {
    if (m.kind == est::MergeItem::Kind::kGnss) return use_gnss(m.gnss);
    if (m.from_mcu) health.OnMcuFrame(m.frame);
    if (m.imu) on_imu(*m.imu);
  };
  est::InputMerge merge(razor_text ? est::Nanoseconds{0} : cfg.merge_window, 2048, use);
  hil::navd::GnssReceivers receivers(
      cfg, [&](const est::GnssSample& g) { merge.Add(GnssItem(g, receivers, merge.enabled())); });
  gnss = &receivers;
  McuInput mcu_in;
  est::drivers::McuFrameDecoder mcu(
      [&](const est::drivers::McuFrame& f) { merge.Add(mcu_in.Item(f, mcu.stats())); });
  est::drivers::RazorTextDecoder razor([&](const est::drivers::RazorTextSample& line) {
    if (const auto s = razor_adapter.Add(line, imu_read_ns)) on_imu(*s);
  });
  std::unique_ptr<hil::navd::CanImuInput> can_imu;
  if (!OpenCanImu(cfg, can_imu)) return 2;
  const auto on_can_imu = [&](const est::ImuSample& s) { merge.Add(CanImuItem(s, *can_imu)); };
  health.set_sources(HealthSourcesOf(merge, receivers, mcu, mcu_in, nav, can_imu.get()));
  // every input device with what its bytes are fed to
  hil::navd::SerialDevice imu(cfg.imu_device, cfg.imu_baud);
  std::vector<SerialInput> inputs;
  for (std::size_t i = 0; i < receivers.size(); ++i) {
    inputs.emplace_back(&receivers.device(i), [&, i](const std::string& b) {
      gnss_read_ns = MonotonicNs();
      receivers.Feed(i, b);
    });
  }
  inputs.emplace_back(&imu, [&](const std::string& b) {
    imu_read_ns = MonotonicNs();
    if (razor_text)
      razor.Feed(b);
    else
      mcu.Feed(b);
  });
  PollInputs(inputs, can_imu.get(), receivers, on_can_imu, [&] { outputs.FlushHeld(); });
  merge.ReleaseAll();  // what the merge still holds goes on (and out) before navd stops
  PrintStopStats(receivers, mcu, nav, outputs);
  if (razor_text) PrintRazorStats(razor, razor_adapter);
  if (can_imu) hil::navd::PrintCanImuStats(*can_imu, stderr);
  outputs.Close();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (hil::navd::WantsKfginsMode(argc, argv)) return hil::navd::KfginsMain(argc, argv);
  if (hil::navd::WantsReplayMode(argc, argv)) return hil::navd::ReplayMain(argc, argv);
  std::string config_path;
  if (const std::optional<int> exit_code = ParseArgs(argc, argv, config_path)) return *exit_code;
  est::NavdConfig cfg;
  try {
    cfg = est::NavdConfig::FromFile(est::ConfigFile::Load(config_path));
  } catch (const est::ConfigError& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return 2;
  }
  SolutionOutputs outputs;
  if (!outputs.Open(cfg)) return 2;
  InstallSignalHandlers();
  if (cfg.uwb.enabled())
    return hil::navd::RunUwbMode(cfg, outputs.out, outputs.nmea_fd, &g_stop);  // paper 003
  if (cfg.odometry.enabled())                                                  // paper 001
    return hil::navd::RunOdometryMode(cfg, outputs.out, outputs.nmea_fd, &g_stop);
  return Run(cfg, outputs);
}

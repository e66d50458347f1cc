#include "replay_mode.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include <sys/stat.h>

#include "hil/estimator/datasets/candump_log.h"
#include "hil/estimator/datasets/kfgins_frames.h"
#include "hil/estimator/datasets/kfgins_output.h"
#include "hil/estimator/drivers/j1939_imu_decoder.h"
#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"
#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/navd_config.h"
#include "hil/estimator/navigator.h"

#include "gnss_receivers.h"

namespace hil::navd {
namespace est = hil::estimator;
namespace ds = hil::estimator::datasets;
namespace drv = hil::estimator::drivers;

bool WantsReplayMode(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--replay") == 0) return true;
  return false;
}

namespace {

// bytes of one link at one recorded time, or one CAN frame of a candump log
struct Chunk {
  std::int64_t t_ns = 0;
  bool imu = false;
  bool can = false;
  std::string bytes;
  drv::CanRxFrame frame;
  bool remote = false;
  std::string interface;
};

// what one log was, for putting every log on one time base
struct LogSpan {
  enum Kind { kCapture, kRaw, kCandump } kind = kRaw;
  std::string path;
  std::int64_t start_unix_ns = 0;  // a capture's `# start_unix_ns` (0: not recorded)
  std::string interface;           // a CAN capture's interface
  std::size_t first = 0, end = 0;  // its chunks
};

std::string FromHex(const std::string& hex) {
  std::string out;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    out += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
  return out;
}

bool EndsWith(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// a hil capture's device-to-host records (times from the run's start)
void ReadCapture(const std::string& text, std::vector<Chunk>& chunks, bool& ubx, LogSpan& span) {
  std::istringstream lines(text);
  long n = 0;
  for (std::string line; std::getline(lines, line);) {
    ++n;
    if (line.rfind("# start_unix_ns ", 0) == 0) span.start_unix_ns = std::stoll(line.substr(16));
    if (line.rfind("# link ", 0) == 0) {  // "# link vcan0 can vcan0": the interface
      std::istringstream h(line.substr(7));
      std::string link, kind;
      h >> link >> kind >> span.interface;
    }
    std::istringstream f(line);
    std::string dir, name, hex;
    std::int64_t t = 0, period = 0, wall = 0;
    if (!(f >> dir >> t >> period >> wall >> name >> hex)) continue;
    if (dir == "ftx") {  // a CAN capture: the frames the emulated devices put on the bus
      ds::CandumpRecord r =
          ds::ParseCandumpLine("(0.0) " + span.interface + " " + hex, span.path, n);
      Chunk c;
      c.t_ns = t;
      c.can = true;
      c.frame = r.frame;
      c.remote = r.remote;
      c.interface = span.interface;
      chunks.push_back(std::move(c));
      continue;
    }
    if (dir != "tx") continue;
    const bool imu = name.rfind("MCU-", 0) == 0;
    if (name.rfind("UBX", 0) == 0) ubx = true;
    Chunk c;
    c.t_ns = t;
    c.imu = imu;
    c.bytes = FromHex(hex);
    chunks.push_back(std::move(c));
  }
}

// a candump log's frames (times: Unix, as recorded)
void ReadCandump(const std::string& path, std::vector<Chunk>& chunks) {
  for (ds::CandumpRecord& r : ds::ReadCandumpLog(path)) {
    Chunk c;
    c.t_ns = r.frame.rx_ns;
    c.can = true;
    c.frame = r.frame;
    c.remote = r.remote;
    c.interface = std::move(r.interface);
    chunks.push_back(std::move(c));
  }
}

// a hil capture, a candump log (by extension or content), or a raw log as one chunk
LogSpan ReadLog(const std::string& path, std::vector<Chunk>& chunks, bool& ubx) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::stringstream all;
  all << in.rdbuf();
  const std::string text = all.str();
  LogSpan span;
  span.path = path;
  span.first = chunks.size();
  if (text.rfind("# hil capture", 0) == 0) {
    span.kind = LogSpan::kCapture;
    ReadCapture(text, chunks, ubx, span);
  } else if (EndsWith(path, ".candump") || ds::LooksLikeCandump(text)) {
    span.kind = LogSpan::kCandump;
    ReadCandump(path, chunks);
  } else {
    std::size_t start = 0;  // gpsd's logs open with '#' comment lines
    while (start < text.size() && text[start] == '#') {
      const std::size_t nl = text.find('\n', start);
      start = nl == std::string::npos ? text.size() : nl + 1;
    }
    if (text.find("\xb5\x62", start) != std::string::npos) ubx = true;
    Chunk c;
    c.bytes = text.substr(start);
    chunks.push_back(std::move(c));
  }
  span.end = chunks.size();
  return span;
}

// a capture's `# start_unix_ns` header line (0: none in its first lines)
std::int64_t HeaderStartUnixNs(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  for (int i = 0; i < 8 && std::getline(in, line); ++i)
    if (line.rfind("# start_unix_ns ", 0) == 0) return std::stoll(line.substr(16));
  return 0;
}

// a run's serial captures carry no start time, its CAN capture does: the start from a capture of
// the set, else from one beside it in its folder (RUN/captures/vcan0.cap); 0 when none knows it
std::int64_t RunStartUnixNs(const std::vector<LogSpan>& spans, const LogSpan& s) {
  for (const LogSpan& o : spans)
    if (o.kind == LogSpan::kCapture && o.start_unix_ns != 0) return o.start_unix_ns;
  std::error_code ec;
  const std::filesystem::path dir = std::filesystem::path(s.path).parent_path();
  for (const auto& e : std::filesystem::directory_iterator(dir.empty() ? "." : dir, ec)) {
    if (e.path().extension() != ".cap") continue;
    if (const std::int64_t t = HeaderStartUnixNs(e.path().string())) return t;
  }
  return 0;
}

// with a candump log, every log goes on Unix time: captures through their run's start time; raw
// logs have no receive times and cannot be merged
void ToUnixTime(const std::vector<LogSpan>& spans, std::vector<Chunk>& chunks) {
  const bool have_candump = std::any_of(
      spans.begin(), spans.end(), [](const LogSpan& s) { return s.kind == LogSpan::kCandump; });
  if (!have_candump) return;
  for (const LogSpan& s : spans) {
    if (s.kind == LogSpan::kRaw)
      throw std::runtime_error(s.path +
                               ": a raw log has no recorded receive times and cannot be merged "
                               "with a candump log (replay the run's capture of that link)");
    if (s.kind != LogSpan::kCapture) continue;
    const std::int64_t start = s.start_unix_ns != 0 ? s.start_unix_ns : RunStartUnixNs(spans, s);
    if (start == 0)
      throw std::runtime_error(s.path +
                               ": no '# start_unix_ns' header (nor in a capture beside it): its "
                               "times cannot be merged with a candump log's Unix times");
    for (std::size_t i = s.first; i < s.end; ++i) chunks[i].t_ns += start;
  }
}

// a CAN capture's frames are received at their recorded times (as the socket's timestamps)
void StampCaptureFrames(std::vector<Chunk>& chunks) {
  for (Chunk& c : chunks)
    if (c.can) c.frame.rx_ns = c.t_ns;
}

// the CAN frames' fate beyond the decoder's own counters
struct CanCounts {
  std::uint64_t frames = 0, remote = 0, other_interface = 0;
};

// what the report says without a truth
struct Consistency {
  std::vector<double> fix_t, imu_t;
  double sigma_h_sum = 0, nis_cv_sum = 0;
  std::uint64_t nis_cv_n = 0;
  std::optional<est::GnssSample> prev_fix;
  std::optional<est::LocalTangentFrame> frame_storage;

  void OnFix(const est::GnssSample& g) {
    if (!frame_storage) frame_storage.emplace(g.position);
    const est::LocalTangentFrame& frame = *frame_storage;
    fix_t.push_back(static_cast<double>(est::ToNs(g.t)) * 1e-9);
    sigma_h_sum += g.pos_std_enu_m.head<2>().norm() / std::sqrt(2.0);
    if (prev_fix && prev_fix->has_velocity) {
      // fix-to-fix innovation: this fix against the last one carried on at its velocity
      const double dt = static_cast<double>((g.t - prev_fix->t).count()) * 1e-9;
      const Eigen::Vector3d d = frame.ToLocal(g.position) - frame.ToLocal(prev_fix->position) -
                                prev_fix->vel_enu_mps * dt;
      const Eigen::Vector2d s2 =
          g.pos_std_enu_m.head<2>().cwiseAbs2() + prev_fix->pos_std_enu_m.head<2>().cwiseAbs2();
      if (dt > 0 && dt < 5 && s2.minCoeff() > 0) {
        nis_cv_sum += d.x() * d.x() / s2.x() + d.y() * d.y() / s2.y();
        ++nis_cv_n;
      }
    }
    prev_fix = g;
  }
};

// rate (from the median interval), gaps (intervals over 1.5 × the median) and the longest
std::string RateLine(const char* what, const std::vector<double>& t) {
  char buf[256];
  if (t.size() < 2) {
    std::snprintf(buf, sizeof buf, "%s: %zu\n", what, t.size());
    return buf;
  }
  std::vector<double> d;
  for (std::size_t i = 1; i < t.size(); ++i) d.push_back(t[i] - t[i - 1]);
  std::vector<double> s = d;
  std::nth_element(s.begin(), s.begin() + static_cast<long>(s.size() / 2), s.end());
  const double med = s[s.size() / 2];
  std::size_t gaps = 0;
  double longest = 0;
  for (double x : d) {
    if (x > 1.5 * med) ++gaps;
    longest = std::max(longest, x);
  }
  std::snprintf(buf, sizeof buf,
                "%s: %zu over %.1f s, %.2f Hz, %zu gaps, longest interval %.3f s\n", what, t.size(),
                t.back() - t.front(), med > 0 ? 1.0 / med : 0.0, gaps, longest);
  return buf;
}

ds::KfginsEpoch EpochOf(const est::NavOutput& o) {
  ds::KfginsEpoch e;
  const std::int64_t ns = est::ToNs(o.t);
  const std::int64_t week_ns = est::kSecondsPerGpsWeek * est::kNsPerSecond;
  e.week = static_cast<int>(ns / week_ns);
  e.sow = static_cast<double>(ns % week_ns) * 1e-9;
  e.lat_deg = o.position.lat_deg;
  e.lon_deg = o.position.lon_deg;
  e.height_m = o.position.height_m;
  e.vel_ned_mps = ds::SwapNedEnu(o.v_N_mps);
  // no attitude (GNSS-only modes without a course): zeros, as the column cannot stay empty
  if (o.has_attitude) e.rpy_deg = ds::EulerNedFromQuatEnuFlu(o.q_NB) * 180.0 / M_PI;
  e.gyro_bias_frd_deg_hr = ds::FlipBody(o.gyro_bias_B) * 180.0 / M_PI * 3600.0;
  e.accel_bias_frd_mgal = ds::FlipBody(o.accel_bias_B) * 1e5;
  e.pos_std_ned_m = ds::SwapStd(o.pos_std_enu_m);
  e.vel_std_ned_mps = ds::SwapStd(o.vel_std_enu_mps);
  e.att_std_deg = ds::SwapStd(o.att_std_rad) * 180.0 / M_PI;
  return e;
}

int Usage(const std::string& problem) {
  std::fprintf(stderr, "navd: %s\nusage: navd --replay LOG [LOG...] --out DIR [--navd-conf FILE]\n",
               problem.c_str());
  return 2;
}

struct ReplayArgs {
  std::vector<std::string> logs;
  std::string out_dir, navd_conf;
};

// the command line; an exit code when it is wrong
std::optional<int> ParseReplayArgs(int argc, char** argv, ReplayArgs& r) {
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--replay") continue;
    if (a == "--out" && i + 1 < argc) {
      r.out_dir = argv[++i];
    } else if (a == "--navd-conf" && i + 1 < argc) {
      r.navd_conf = argv[++i];
    } else if (!a.empty() && a[0] != '-') {
      r.logs.push_back(a);
    } else {
      return Usage("unknown or incomplete option '" + a + "'");
    }
  }
  if (r.logs.empty() || r.out_dir.empty()) return Usage("--replay needs a LOG and --out DIR");
  return std::nullopt;
}

// navd's configuration for the replay: the given navd.conf, or the mode and protocol the logs need
est::NavdConfig ReplayConfig(const ReplayArgs& r, bool have_imu, bool ubx) {
  est::NavdConfig cfg;
  if (!r.navd_conf.empty()) {
    cfg = est::NavdConfig::FromFile(est::ConfigFile::Load(r.navd_conf));
  } else {
    cfg.nav.mode = have_imu ? est::NavMode::kEkf : est::NavMode::kGnssOnly;
    cfg.gnss_protocol = ubx ? "ubx" : "nmea";
  }
  cfg.gnss_device = r.logs.front();  // never opened: the bytes are fed from the logs
  cfg.gnss_receivers = {};
  return cfg;
}

std::string Report(const ReplayArgs& r, const est::NavdConfig& cfg, const Consistency& cons,
                   const est::NavigatorStats& st, std::uint64_t solutions) {
  char buf[512];
  std::string report = "navd replay of " + std::to_string(r.logs.size()) + " log(s), mode " +
                       est::NavModeName(cfg.mode()) + "\n";
  report += RateLine("GNSS fixes", cons.fix_t);
  report += RateLine("IMU samples", cons.imu_t);
  const double n_fix = static_cast<double>(std::max<std::size_t>(cons.fix_t.size(), 1));
  std::snprintf(
      buf, sizeof buf,
      "reported horizontal sigma mean %.3f m; fix-to-fix innovation NIS (2 dof, "
      "constant velocity) mean %.2f over %llu pairs\n"
      "filter: %llu solutions, fused %llu, rejected %llu, resets %llu, mean position "
      "NIS %.2f (3 when consistent), late fixes %llu, IMU gaps %llu\n",
      cons.sigma_h_sum / n_fix,
      cons.nis_cv_n ? cons.nis_cv_sum / static_cast<double>(cons.nis_cv_n) : 0.0,
      static_cast<unsigned long long>(cons.nis_cv_n), static_cast<unsigned long long>(solutions),
      static_cast<unsigned long long>(st.gnss_fused),
      static_cast<unsigned long long>(st.gnss_rejected),
      static_cast<unsigned long long>(st.gnss_resets), st.mean_nis_pos,
      static_cast<unsigned long long>(st.gnss_late), static_cast<unsigned long long>(st.imu_gaps));
  return report + buf;
}

// the J1939 decoder as navd's online CAN input configures it
drv::J1939ImuDecoderConfig CanConfig(const est::NavdConfig& cfg) {
  drv::J1939ImuDecoderConfig jc;
  jc.any_source = cfg.imu.source_address < 0;
  jc.source_address =
      static_cast<std::uint8_t>(cfg.imu.source_address < 0 ? 0 : cfg.imu.source_address);
  return jc;
}

std::string CanReport(const CanCounts& n, const drv::J1939ImuDecoder& dec) {
  const drv::J1939ImuStats& st = dec.stats();
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "CAN frames %llu (remote %llu, other interface %llu): ari %llu accs %llu ssi2 %llu "
                "pulses %llu imu %llu no_time %llu gaps %llu unpaired %llu other_source %llu "
                "unknown_pgn %llu not_extended %llu bad_length %llu not_available %llu "
                "mcu_resets %llu mcu_ppm %.1f\n",
                u(n.frames), u(n.remote), u(n.other_interface), u(st.ari), u(st.accs), u(st.ssi2),
                u(st.pulses), u(st.imu_out), u(st.imu_no_time), u(st.imu_gap), u(st.unpaired),
                u(st.other_source), u(st.unknown_pgn), u(st.not_extended), u(st.bad_length),
                u(st.not_available), u(st.mcu_resets), dec.mcu_clock().offset_ppm());
  return buf;
}

// all logs' chunks on one time base, in recorded order
std::vector<Chunk> ReadLogs(const ReplayArgs& r, bool& ubx) {
  std::vector<Chunk> chunks;
  std::vector<LogSpan> spans;
  for (const std::string& l : r.logs) spans.push_back(ReadLog(l, chunks, ubx));
  ToUnixTime(spans, chunks);
  StampCaptureFrames(chunks);
  std::stable_sort(chunks.begin(), chunks.end(),
                   [](const Chunk& a, const Chunk& b) { return a.t_ns < b.t_ns; });
  return chunks;
}

// feeds the logs' bytes and frames in their recorded order to the decoders and the filter
int Replay(const ReplayArgs& r) {
  bool ubx = false;
  const std::vector<Chunk> chunks = ReadLogs(r, ubx);
  const bool have_can =
      std::any_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.can; });
  const bool have_imu =
      have_can || std::any_of(chunks.begin(), chunks.end(), [](const Chunk& c) { return c.imu; });
  const est::NavdConfig cfg = ReplayConfig(r, have_imu, ubx);
  // a navd.conf reading CAN names its interface: other interfaces' frames are not navd's
  const std::string can_iface = cfg.imu.from_can() ? cfg.imu.can_interface : std::string();
  est::Navigator nav(cfg.nav);
  const bool imu_mode = est::UsesImu(cfg.mode());
  ::mkdir(r.out_dir.c_str(), 0755);
  ds::KfginsOutputWriter out(r.out_dir);
  Consistency cons;
  std::uint64_t solutions = 0;
  const auto emit = [&] {
    const est::NavOutput o = nav.Output();
    if (!o.valid) return;
    out.Write(EpochOf(o));
    ++solutions;
  };
  GnssReceivers receivers(cfg, [&](const est::GnssSample& g) {
    nav.Push(g);
    cons.OnFix(g);
    if (!imu_mode) emit();
  });
  const auto on_imu = [&](const est::ImuSample& s) {
    cons.imu_t.push_back(static_cast<double>(est::ToNs(s.t)) * 1e-9);
    nav.Push(s);
    nav.Update();
    if (nav.aligned()) emit();
  };
  drv::McuImuAdapter adapter;
  drv::McuFrameDecoder mcu([&](const drv::McuFrame& f) {
    if (const auto s = adapter.Add(f)) on_imu(*s);
  });
  drv::J1939ImuDecoder can(CanConfig(cfg));
  CanCounts can_n;
  for (const Chunk& c : chunks) {
    if (c.can) {
      ++can_n.frames;
      // the online socket's kernel filter passes neither remote frames nor other interfaces
      if (c.remote) {
        ++can_n.remote;
      } else if (!can_iface.empty() && c.interface != can_iface) {
        ++can_n.other_interface;
      } else if (const auto s = can.Add(c.frame)) {
        on_imu(*s);
      }
    } else if (c.imu) {
      mcu.Feed(c.bytes);
    } else {
      for (std::size_t k = 0; k < c.bytes.size(); k += 256)
        receivers.Feed(0, c.bytes.substr(k, 256));
    }
  }
  out.Close();
  const std::string report = Report(r, cfg, cons, nav.stats(), solutions) +
                             (have_can ? CanReport(can_n, can) : std::string());
  std::fputs(report.c_str(), stdout);
  std::ofstream(r.out_dir + "/replay_report.txt") << report;
  return 0;
}

}  // namespace

int ReplayMain(int argc, char** argv) {
  ReplayArgs r;
  if (const auto code = ParseReplayArgs(argc, argv, r)) return *code;
  try {
    return Replay(r);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "navd: %s\n", e.what());
    return 2;
  }
}

}  // namespace hil::navd

#include "hil/harness/report/run_outputs.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/core/machine_load.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/report/fixed_text.h"
#include "hil/harness/report/output_file.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

std::vector<Time> TruthCsvTimes(const Scenario& s) {
  std::vector<Time> t;
  const Time t_end = TimeFromSeconds(s.duration_s);
  for (Time ti{}; ti <= t_end; ti += kTruthCsvStep) t.push_back(ti);
  return t;
}

void WriteTruthCsv(const Scenario& s, const std::string& path, std::vector<double>& t_s,
                   std::vector<Eigen::Vector2d>& en_m) {
  WriteTruthCsv(TruthTable(s.truth, TruthCsvTimes(s)), s, path, t_s, en_m);
}

void AppendTruthCsvHeader(std::string& text) {
  text +=
      "t_s,lat_deg,lon_deg,height_m,e_m,n_m,u_m,v_e_mps,v_n_mps,v_u_mps,yaw_deg,speed_mps,"
      "roll_deg,pitch_deg,w_x_radps,w_y_radps,w_z_radps,f_x_mps2,f_y_mps2,f_z_mps2,steer_"
      "deg,cross_track_m\n";
}

void AppendTruthCsvRow(std::string& text, Time t, const TruthSample& x) {
  const Eigen::Matrix3d R = x.q_NB.toRotationMatrix();
  const Eigen::Vector3d fwd = R.col(0);
  // roll and pitch of the body (z-y-x Euler angles of FLU in ENU)
  const double pitch_deg = -std::asin(std::clamp(R(2, 0), -1.0, 1.0)) * 180.0 / M_PI;
  const double roll_deg = std::atan2(R(2, 1), R(2, 2)) * 180.0 / M_PI;
  AppendFixed(text, ToSeconds(t), 3);
  text.push_back(',');
  AppendFixedRow(text, 10, x.lat_deg, x.lon_deg);
  text.push_back(',');
  AppendFixed(text, x.height_m, 4);
  text.push_back(',');
  AppendFixedRow(text, 6, x.p_NB_N_m.x(), x.p_NB_N_m.y(), x.p_NB_N_m.z(), x.v_NB_N_mps.x(),
                 x.v_NB_N_mps.y(), x.v_NB_N_mps.z());
  text.push_back(',');
  AppendFixed(text, std::atan2(fwd.x(), fwd.y()) * 180.0 / M_PI, 5);
  text.push_back(',');
  AppendFixed(text, x.speed_mps, 6);
  text.push_back(',');
  AppendFixedRow(text, 5, roll_deg, pitch_deg);
  text.push_back(',');
  AppendFixedRow(text, 8, x.w_IB_B_radps.x(), x.w_IB_B_radps.y(), x.w_IB_B_radps.z());
  text.push_back(',');
  AppendFixedRow(text, 6, x.f_B_mps2.x(), x.f_B_mps2.y(), x.f_B_mps2.z());
  text.push_back(',');
  AppendFixed(text, x.steer_rad * 180.0 / M_PI, 4);
  text.push_back(',');
  AppendFixed(text, x.cross_track_m, 6);
  text.push_back('\n');
}

void WriteTruthCsv(const TruthTable& truth, const Scenario& s, const std::string& path,
                   std::vector<double>& t_s, std::vector<Eigen::Vector2d>& en_m) {
  OutputFile out(path);
  std::string& text = out.text();
  AppendTruthCsvHeader(text);
  const std::vector<Time> times = TruthCsvTimes(s);
  for (const Time t : times) {
    const TruthSample& x = truth.At(t);
    AppendTruthCsvRow(text, t, x);
    out.Pass();
    t_s.push_back(ToSeconds(t));
    en_m.emplace_back(x.p_NB_N_m.x(), x.p_NB_N_m.y());
  }
  out.Commit();
}

void WriteFixCsvHeader(std::ostream& out) {
  out << "t_s,lat_deg,lon_deg,height_m,vel_n_mps,vel_e_mps,vel_d_mps,num_sv,hdop\n";
}

void WriteFixCsvLine(std::ostream& out, const gnss::GnssFix& fix) {
  std::string line;
  line.reserve(96);
  AppendFixed(line, ToSeconds(fix.t_validity), 3);
  line.push_back(',');
  AppendFixedRow(line, 9, fix.lat_deg, fix.lon_deg);
  line.push_back(',');
  AppendFixedRow(line, 4, fix.height_m, fix.vel_n_mps, fix.vel_e_mps, fix.vel_d_mps);
  line += ',' + std::to_string(fix.num_sv) + ',';
  AppendFixed(line, fix.hdop, 2);
  line.push_back('\n');
  out.write(line.data(), static_cast<std::streamsize>(line.size()));
}

namespace {

// What the machine gave the real-time run (machine_load.h): from the pacing's start to now.
nlohmann::json MachineJson(const ScheduleRecord& record) {
  const MachineFigures m = ReadMachineFigures();
  const auto opt = [](const std::optional<long>& v) {
    return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
  };
  bool fifo_granted = false;
  for (const auto& [name, t] : record.threads) fifo_granted = fifo_granted || t.realtime();
  nlohmann::json j = {{"cpus_online", m.cpus_online},
                      {"load_average", {m.load_1m, m.load_5m, m.load_15m}},
                      {"sched_rt_runtime_us", opt(m.rt_runtime_us)},
                      {"sched_rt_period_us", opt(m.rt_period_us)},
                      {"sched_fifo_granted", fifo_granted},
                      {"kernel", m.kernel},
                      {"preempt", m.preempt.empty() ? "the build's default" : m.preempt}};
  const std::optional<CpuTicks> now = ReadCpuTicks();
  if (record.cpu_at_start && now) {
    const CpuShares s = SharesBetween(*record.cpu_at_start, *now);
    j["since_pacing_start"] = {{"ticks", s.ticks},
                               {"busy_pct", s.busy_pct},
                               {"idle_pct", s.idle_pct},
                               {"steal_pct", s.steal_pct}};
  }
  return j;
}

}  // namespace

nlohmann::json RealtimeThreadsJson(
    const std::vector<std::pair<std::string, link::ThreadSchedule>>& threads) {
  // what each thread of the real-time run really got, read back from the kernel, and the CPU it
  // used while the run paced
  nlohmann::json a = nlohmann::json::array();
  for (const auto& [name, t] : threads) {
    nlohmann::json j = {{"thread", name},
                        {"tid", t.tid},
                        {"policy", t.policy},
                        {"priority", t.priority},
                        {"timer_slack_ns", t.timer_slack_ns}};
    if (!t.refused.empty()) j["realtime_refused"] = t.refused;
    if (t.usage) {
      j["cpu_user_s"] = t.usage->user_s;
      j["cpu_system_s"] = t.usage->system_s;
      j["wall_s"] = t.usage->wall_s;
      j["cpu_pct"] = t.usage->cpu_pct();
    }
    a.push_back(j);
  }
  return a;
}

void WriteScheduleErrors(const ScheduleRecord& record, const std::string& path) {
  static const QuantileSketch kNone;
  nlohmann::json links = nlohmann::json::array();
  for (const ScheduleRecord::Link& l : record.serial) {
    const QuantileSketch& e = l.error_us ? *l.error_us : kNone;
    if (e.count() == 0 && l.bytes_dropped_unread == 0) continue;
    links.push_back({{"link", l.name},
                     {"bytes", e.count()},
                     {"bytes_dropped_unread", l.bytes_dropped_unread},
                     {"p50_us", e.Percentile(50)},
                     {"p99_us", e.Percentile(99)},
                     {"max_us", e.Percentile(100)}});
  }
  if (record.can && record.can->error_us && record.can->error_us->count() > 0) {
    const QuantileSketch& e = *record.can->error_us;
    links.push_back({{"link", record.can->name},
                     {"frames", e.count()},
                     {"p50_us", e.Percentile(50)},
                     {"p99_us", e.Percentile(99)},
                     {"max_us", e.Percentile(100)}});
  }
  if (links.empty() && record.threads.empty()) return;
  nlohmann::json out{{"threads", RealtimeThreadsJson(record.threads)}, {"links", links}};
  if (!record.threads.empty()) out["machine"] = MachineJson(record);
  WriteOutputFile(path, out.dump(2) + "\n");
}

}  // namespace hil::harness

#include "hil/harness/datasets/run_export.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

#include <Eigen/Geometry>
#include <sys/stat.h>

#include "hil/firmware_emu/angles.h"
#include "hil/harness/datasets/capture_imu.h"
#include "hil/harness/datasets/kfgins_text.h"

namespace hil::harness {
namespace {

constexpr double kWeek_s = 604800.0;

// a CSV with a header row: each row's values by column name
struct Csv {
  std::vector<std::map<std::string, double>> rows;
};

Csv ReadCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::string line;
  std::getline(in, line);
  std::vector<std::string> names;
  for (std::stringstream h(line); std::getline(h, line, ',');) names.push_back(line);
  Csv csv;
  long n = 1;
  while (std::getline(in, line)) {
    ++n;
    std::stringstream s(line);
    std::map<std::string, double> row;
    std::string cell;
    for (std::size_t i = 0; i < names.size() && std::getline(s, cell, ','); ++i) {
      char* end = nullptr;
      row[names[i]] = std::strtod(cell.c_str(), &end);
      if (end == cell.c_str())
        throw std::runtime_error(path + ":" + std::to_string(n) + ": " + names[i] +
                                 ": not a number");
    }
    csv.rows.push_back(std::move(row));
  }
  return csv;
}

double At(const std::map<std::string, double>& row, const std::string& key) {
  const auto it = row.find(key);
  if (it == row.end()) throw std::runtime_error("column " + key + " missing");
  return it->second;
}

// [section] key = value of the run's navd.conf (no validation: navd validated it)
std::map<std::string, std::string> ReadNavdConf(const std::string& path) {
  std::map<std::string, std::string> kv;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    const std::size_t eq = line.find('=');
    if (line.empty() || line[0] == '#' || line[0] == '[' || eq == std::string::npos) continue;
    const auto trim = [](std::string x) {
      x.erase(0, x.find_first_not_of(" \t"));
      x.erase(x.find_last_not_of(" \t\r") + 1);
      return x;
    };
    kv[trim(line.substr(0, eq))] = trim(line.substr(eq + 1));
  }
  return kv;
}

double Number(const std::map<std::string, std::string>& kv, const std::string& key,
              double fallback) {
  const auto it = kv.find(key);
  return it == kv.end() ? fallback : std::strtod(it->second.c_str(), nullptr);
}

std::string FindImuCapture(const std::string& run_dir) {
  const std::string dir = run_dir + "/captures";
  if (!std::filesystem::is_directory(dir)) throw std::runtime_error(dir + ": no captures");
  std::vector<std::string> caps;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.path().extension() == ".cap") caps.push_back(e.path().string());
  std::sort(caps.begin(), caps.end());
  for (const std::string& c : caps) {
    std::ifstream in(c);
    for (std::string line; std::getline(in, line);) {
      if (line.empty() || line[0] == '#') continue;
      if (line.find(" MCU-") != std::string::npos) return c;
      break;
    }
  }
  throw std::runtime_error(dir + ": no capture of the MCU frame protocol (IMU)");
}

// the truth row's attitude: yaw clockwise from north, pitch and roll of body FLU in ENU
Eigen::Quaterniond TruthAttitude(const std::map<std::string, double>& r) {
  const double yaw_enu = (90.0 - At(r, "yaw_deg")) * kDeg;
  return Eigen::AngleAxisd(yaw_enu, Eigen::Vector3d::UnitZ()) *
         Eigen::AngleAxisd(At(r, "pitch_deg") * kDeg, Eigen::Vector3d::UnitY()) *
         Eigen::AngleAxisd(At(r, "roll_deg") * kDeg, Eigen::Vector3d::UnitX());
}

KfginsPva TruthPva(const std::map<std::string, double>& r, double sow) {
  KfginsPva p;
  p.sow = sow;
  p.lat_deg = At(r, "lat_deg");
  p.lon_deg = At(r, "lon_deg");
  p.height_m = At(r, "height_m");
  p.v_enu_mps = {At(r, "v_e_mps"), At(r, "v_n_mps"), At(r, "v_u_mps")};
  p.q_enu_flu = TruthAttitude(r);
  return p;
}

struct RunData {
  CaptureImu imu;
  Csv fixes, truth;
  std::map<std::string, std::string> conf;
  double uere_m = 2.5, vel_std_mps = 0.2;
};

RunData Load(const std::string& run_dir) {
  RunData d;
  d.imu = ReadCaptureImu(FindImuCapture(run_dir));
  if (d.imu.samples.empty()) throw std::runtime_error(run_dir + ": the IMU capture has no samples");
  d.fixes = ReadCsv(run_dir + "/gnss_fixes.csv");
  d.truth = ReadCsv(run_dir + "/truth.csv");
  d.conf = ReadNavdConf(run_dir + "/navd.conf");
  d.uere_m = Number(d.conf, "nmea_uere_m", 2.5);
  d.vel_std_mps = Number(d.conf, "nmea_velocity_std_mps", 0.2);
  return d;
}

double SowOf(double gps_s) { return std::fmod(gps_s, kWeek_s); }

KfginsFix FixOf(const RunData& d, const std::map<std::string, double>& r) {
  KfginsFix f;
  f.sow = SowOf(d.imu.gps_at_emulated_zero_s + At(r, "t_s"));
  f.lat_deg = At(r, "lat_deg");
  f.lon_deg = At(r, "lon_deg");
  f.height_m = At(r, "height_m");
  const double h = std::max(At(r, "hdop"), 0.5) * d.uere_m / std::sqrt(2.0);
  f.std_ned_m = {h, h, 2 * h};
  return f;
}

// the truth row nearest to a scenario time
const std::map<std::string, double>& TruthNear(const Csv& truth, double t_s) {
  const std::map<std::string, double>* best = &truth.rows.front();
  for (const auto& r : truth.rows)
    if (std::abs(At(r, "t_s") - t_s) < std::abs(At(*best, "t_s") - t_s)) best = &r;
  return *best;
}

RunExportResult ExportKfgins(const RunData& d, const std::string& out) {
  KfginsTextFiles files(out);
  RunExportResult res;
  for (const CaptureImuSample& s : d.imu.samples) {
    files.WriteImu(SowOf(s.t_gps_s), {s.dtheta_flu_rad, s.dvel_flu_mps});
    ++res.imu_lines;
  }
  // NMEA (RMC) reports no vertical velocity: the receiver's fix says 0 there, as navd takes it
  const bool nmea = !d.conf.count("gnss_protocol") || d.conf.at("gnss_protocol") != "ubx";
  for (const auto& r : d.fixes.rows) {
    const KfginsFix f = FixOf(d, r);
    files.WriteGnss(f);
    files.WriteGnssPosVel(f,
                          {At(r, "vel_n_mps"), At(r, "vel_e_mps"), nmea ? 0.0 : At(r, "vel_d_mps")},
                          {d.vel_std_mps, d.vel_std_mps, 2 * d.vel_std_mps});
    ++res.gnss_lines;
  }
  for (const auto& r : d.truth.rows) {
    files.WriteTruth(TruthPva(r, SowOf(d.imu.gps_at_emulated_zero_s + At(r, "t_s"))));
    ++res.truth_lines;
  }
  KfginsYaml y;
  const CaptureImuSample& first = d.imu.samples.front();
  y.imudatarate_hz = 1.0 / first.dt_s;
  y.starttime_s = SowOf(first.t_gps_s);
  y.init =
      TruthPva(TruthNear(d.truth, first.t_gps_s - d.imu.gps_at_emulated_zero_s), y.starttime_s);
  std::stringstream lever(d.conf.count("lever_arm_m") ? d.conf.at("lever_arm_m") : "0,0,0");
  for (int i = 0; i < 3; ++i) {
    std::string c;
    std::getline(lever, c, ',');
    y.antlever_flu_m[i] = std::strtod(c.c_str(), nullptr);
  }
  y.arw_deg_rthr = Number(d.conf, "gyro_noise", 2e-4) * 60 / kDeg;
  y.vrw_mps_rthr = Number(d.conf, "accel_noise", 0.02) * 60;
  y.gbstd_deg_hr = Number(d.conf, "init_gyro_bias_std", 0.005) / kDeg * 3600;
  y.abstd_mgal = Number(d.conf, "init_accel_bias_std", 0.05) * 1e5;
  y.initposstd_m.setConstant(1.0);
  y.initvelstd_mps.setConstant(0.2);
  y.initattstd_deg = {2, 2, 10};
  files.WriteConfig(y);
  files.WriteConfig(y, "GNSS-POSVEL.txt", "kf-gins-posvel.yaml");
  files.Close();
  return res;
}

std::FILE* CreateCsv(const std::string& path, const char* header) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot create");
  std::fprintf(f, "%s\n", header);
  return f;
}

RunExportResult ExportGnssInsSim(const RunData& d, const std::string& out) {
  RunExportResult res;
  std::FILE* time = CreateCsv(out + "/time.csv", "time (sec)");
  std::FILE* gyro = CreateCsv(out + "/gyro-0.csv", "gyro_x (deg/s),gyro_y (deg/s),gyro_z (deg/s)");
  std::FILE* acc =
      CreateCsv(out + "/accel-0.csv", "accel_x (m/s^2),accel_y (m/s^2),accel_z (m/s^2)");
  const double t0 = d.imu.gps_at_emulated_zero_s;
  for (const CaptureImuSample& s : d.imu.samples) {
    const Eigen::Vector3d w = s.dtheta_flu_rad / s.dt_s / kDeg, a = s.dvel_flu_mps / s.dt_s;
    std::fprintf(time, "%.9f\n", s.t_gps_s - t0);
    std::fprintf(gyro, "%.10g,%.10g,%.10g\n", w.x(), -w.y(), -w.z());
    std::fprintf(acc, "%.10g,%.10g,%.10g\n", a.x(), -a.y(), -a.z());
    ++res.imu_lines;
  }
  std::FILE* gt = CreateCsv(out + "/gps_time.csv", "gps_time (sec)");
  std::FILE* gps = CreateCsv(out + "/gps-0.csv",
                             "gps_lat (deg),gps_lon (deg),gps_alt (m),gps_vN (m/s),gps_vE (m/s),"
                             "gps_vD (m/s)");
  for (const auto& r : d.fixes.rows) {
    std::fprintf(gt, "%.9f\n", At(r, "t_s"));
    std::fprintf(gps, "%.11f,%.11f,%.5f,%.6f,%.6f,%.6f\n", At(r, "lat_deg"), At(r, "lon_deg"),
                 At(r, "height_m"), At(r, "vel_n_mps"), At(r, "vel_e_mps"), At(r, "vel_d_mps"));
    ++res.gnss_lines;
  }
  std::FILE* rt = CreateCsv(out + "/ref_time.csv", "time (sec)");
  std::FILE* rp =
      CreateCsv(out + "/ref_pos.csv", "ref_pos_lat (deg),ref_pos_lon (deg),ref_pos_alt (m)");
  std::FILE* rv =
      CreateCsv(out + "/ref_vel.csv", "ref_vel_x (m/s),ref_vel_y (m/s),ref_vel_z (m/s)");
  std::FILE* ra =
      CreateCsv(out + "/ref_att_euler.csv", "ref_Yaw (deg),ref_Pitch (deg),ref_Roll (deg)");
  for (const auto& r : d.truth.rows) {
    const Eigen::Vector3d e = KfginsEulerDeg(TruthAttitude(r));
    std::fprintf(rt, "%.9f\n", At(r, "t_s"));
    std::fprintf(rp, "%.11f,%.11f,%.5f\n", At(r, "lat_deg"), At(r, "lon_deg"), At(r, "height_m"));
    std::fprintf(rv, "%.6f,%.6f,%.6f\n", At(r, "v_n_mps"), At(r, "v_e_mps"), -At(r, "v_u_mps"));
    std::fprintf(ra, "%.8f,%.8f,%.8f\n", e.z(), e.y(), e.x());
    ++res.truth_lines;
  }
  bool ok = true;
  for (std::FILE* f : {time, gyro, acc, gt, gps, rt, rp, rv, ra}) ok = std::fclose(f) == 0 && ok;
  if (!ok) throw std::runtime_error(out + ": write error");
  return res;
}

}  // namespace

RunExportResult ExportRun(const std::string& run_dir, const std::string& format,
                          const std::string& out_dir) {
  if (format != "kfgins" && format != "gnss-ins-sim")
    throw std::runtime_error("--format: kfgins or gnss-ins-sim, not '" + format + "'");
  const RunData d = Load(run_dir);
  std::filesystem::create_directories(out_dir);
  RunExportResult r = format == "kfgins" ? ExportKfgins(d, out_dir) : ExportGnssInsSim(d, out_dir);
  r.bad_frames = d.imu.bad_frames;
  return r;
}

}  // namespace hil::harness

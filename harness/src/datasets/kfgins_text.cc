#include "hil/harness/datasets/kfgins_text.h"

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "hil/firmware_emu/angles.h"

namespace hil::harness {
namespace {

std::FILE* Create(const std::string& path) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  if (!f) throw std::runtime_error(path + ": cannot create: " + std::strerror(errno));
  return f;
}

// NED from ENU
Eigen::Vector3d Ned(const Eigen::Vector3d& enu) { return {enu.y(), enu.x(), -enu.z()}; }

void WriteVector(std::FILE* f, const char* key, const Eigen::Vector3d& v) {
  std::fprintf(f, "%s: [%.12g, %.12g, %.12g]\n", key, v.x(), v.y(), v.z());
}

// lat, lon to 1e-11° (1 µm), height to 10 µm
void WritePosition(std::FILE* f, const KfginsPva& p) {
  std::fprintf(f, "initpos: [%.11f, %.11f, %.5f]\n", p.lat_deg, p.lon_deg, p.height_m);
}

}  // namespace

Eigen::Vector3d KfginsEulerDeg(const Eigen::Quaterniond& q) {
  // C_ned_frd = T · C_enu_flu · D with T the ENU/NED swap and D = diag(1, −1, −1)
  Eigen::Matrix3d t;
  t << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  const Eigen::Matrix3d c = t * q.toRotationMatrix() * Eigen::Vector3d(1, -1, -1).asDiagonal();
  const double pitch = std::asin(std::max(-1.0, std::min(1.0, -c(2, 0))));
  return Eigen::Vector3d(std::atan2(c(2, 1), c(2, 2)), pitch, std::atan2(c(1, 0), c(0, 0))) / kDeg;
}

KfginsTextFiles::KfginsTextFiles(const std::string& dir) : dir_(dir) {
  imu_ = Create(dir + "/IMU.txt");
  gnss_ = Create(dir + "/GNSS.txt");
  truth_ = Create(dir + "/truth.nav");
}

KfginsTextFiles::~KfginsTextFiles() {
  for (std::FILE* f : {imu_, gnss_, truth_, posvel_})
    if (f) std::fclose(f);
}

void KfginsTextFiles::WriteImu(double sow, const KfginsImuIncrement& inc) {
  // FRD = (x, −y, −z) of FLU
  const Eigen::Vector3d& a = inc.dtheta_flu_rad;
  const Eigen::Vector3d& v = inc.dvel_flu_mps;
  std::fprintf(imu_, "%.9f %.10e %.10e %.10e %.10e %.10e %.10e\n", sow, a.x(), -a.y(), -a.z(),
               v.x(), -v.y(), -v.z());
}

void KfginsTextFiles::WriteGnss(const KfginsFix& f) {
  std::fprintf(gnss_, "%.9f %.11f %.11f %.5f %.5f %.5f %.5f\n", f.sow, f.lat_deg, f.lon_deg,
               f.height_m, f.std_ned_m.x(), f.std_ned_m.y(), f.std_ned_m.z());
}

void KfginsTextFiles::WriteGnssPosVel(const KfginsFix& f, const Eigen::Vector3d& v,
                                      const Eigen::Vector3d& s) {
  if (!posvel_) posvel_ = Create(dir_ + "/GNSS-POSVEL.txt");
  std::fprintf(posvel_, "%.9f %.11f %.11f %.5f %.5f %.5f %.5f %.6f %.6f %.6f %.5f %.5f %.5f\n",
               f.sow, f.lat_deg, f.lon_deg, f.height_m, f.std_ned_m.x(), f.std_ned_m.y(),
               f.std_ned_m.z(), v.x(), v.y(), v.z(), s.x(), s.y(), s.z());
}

void KfginsTextFiles::WriteTruth(const KfginsPva& p) {
  const Eigen::Vector3d v = Ned(p.v_enu_mps);
  const Eigen::Vector3d e = KfginsEulerDeg(p.q_enu_flu);
  std::fprintf(truth_, "0 %.9f %.11f %.11f %.5f %.6f %.6f %.6f %.8f %.8f %.8f\n", p.sow, p.lat_deg,
               p.lon_deg, p.height_m, v.x(), v.y(), v.z(), e.x(), e.y(), e.z());
}

void KfginsTextFiles::WriteConfig(const KfginsYaml& y, const std::string& gnss_file,
                                  const std::string& name) const {
  std::FILE* f = Create(dir_ + "/" + name);
  std::fprintf(f,
               "# KF-GINS configuration written by hil (paths relative to this folder)\n"
               "imupath: \"IMU.txt\"\ngnsspath: \"%s\"\noutputpath: \"result\"\n"
               "imudatalen: 7\nimudatarate: %.12g\nstarttime: %.9f\nendtime: -1\n",
               gnss_file.c_str(), y.imudatarate_hz, y.starttime_s);
  WritePosition(f, y.init);
  WriteVector(f, "initvel", Ned(y.init.v_enu_mps));
  WriteVector(f, "initatt", KfginsEulerDeg(y.init.q_enu_flu));
  WriteVector(f, "initposstd", y.initposstd_m);
  WriteVector(f, "initvelstd", y.initvelstd_mps);
  WriteVector(f, "initattstd", y.initattstd_deg);
  // KF-GINS requires the initial IMU errors and takes the noise per axis ([x, y, z])
  WriteVector(f, "initgyrbias", y.initgyrbias_deg_hr);
  WriteVector(f, "initaccbias", y.initaccbias_mgal);
  for (const char* key : {"initgyrscale", "initaccscale"}) std::fprintf(f, "%s: [0, 0, 0]\n", key);
  if (y.initbgstd_deg_hr > 0)
    WriteVector(f, "initbgstd", Eigen::Vector3d::Constant(y.initbgstd_deg_hr));
  if (y.initbastd_mgal > 0)
    WriteVector(f, "initbastd", Eigen::Vector3d::Constant(y.initbastd_mgal));
  std::fprintf(f, "imunoise:\n");
  const std::pair<const char*, double> noise[] = {
      {"arw", y.arw_deg_rthr}, {"vrw", y.vrw_mps_rthr}, {"gbstd", y.gbstd_deg_hr},
      {"abstd", y.abstd_mgal}, {"gsstd", y.gsstd_ppm},  {"asstd", y.asstd_ppm}};
  for (const auto& [key, v] : noise) std::fprintf(f, "  %s: [%.12g, %.12g, %.12g]\n", key, v, v, v);
  std::fprintf(f, "  corrtime: %.12g\n", y.corrtime_hr);
  const Eigen::Vector3d& l = y.antlever_flu_m;
  WriteVector(f, "antlever", {l.x(), -l.y(), -l.z()});
  if (std::fclose(f) != 0) throw std::runtime_error(dir_ + "/" + name + ": write error");
}

void KfginsTextFiles::Close() {
  std::FILE* files[] = {imu_, gnss_, truth_, posvel_};
  imu_ = gnss_ = truth_ = posvel_ = nullptr;
  bool ok = true;
  for (std::FILE* f : files) {
    if (!f) continue;
    ok = std::ferror(f) == 0 && ok;
    ok = std::fclose(f) == 0 && ok;
  }
  if (!ok) throw std::runtime_error(dir_ + ": write error");
}

std::vector<KfginsNavLine> ReadKfginsNav(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot open");
  std::vector<KfginsNavLine> out;
  std::string line;
  long n = 0;
  while (std::getline(in, line)) {
    ++n;
    if (line.empty() || line[0] == '#') continue;
    std::istringstream s(line);
    double week = 0;
    KfginsNavLine l;
    if (!(s >> week >> l.sow >> l.lat_deg >> l.lon_deg >> l.height_m >> l.v_ned_mps.x() >>
          l.v_ned_mps.y() >> l.v_ned_mps.z() >> l.rpy_deg.x() >> l.rpy_deg.y() >> l.rpy_deg.z()))
      throw std::runtime_error(path + ":" + std::to_string(n) + ": expected 11 numbers");
    out.push_back(l);
  }
  return out;
}

}  // namespace hil::harness

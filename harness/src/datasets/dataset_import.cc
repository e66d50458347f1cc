#include "hil/harness/datasets/dataset_import.h"

#include <algorithm>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <stdexcept>

#include "hil/harness/datasets/import_fields.h"
#include "hil/harness/datasets/kfgins_text.h"
#include "hil/harness/datasets/rtklib_pos.h"
#include "hil/harness/datasets/rtklib_timetag.h"
#include "hil/harness/datasets/ubx_nav_log.h"

namespace hil::harness {
namespace {

constexpr double kImportDeg = std::numbers::pi / 180;
constexpr double kImportWeek_s = 604800.0;
constexpr double kImportGpsEpochUnix_s = 315964800.0;

// one GNSS epoch on GPS time (seconds since the GPS epoch), antenna position
struct ImportGnssEpoch {
  double t_s = 0, lat_deg = 0, lon_deg = 0, height_m = 0;
  Eigen::Vector3d std_ned_m = Eigen::Vector3d::Zero();
  bool has_velocity = false;
  Eigen::Vector3d v_ned_mps = Eigen::Vector3d::Zero(), v_std_ned_mps = Eigen::Vector3d::Zero();
  int quality = 0;
};

void ImportAppendf(std::string& s, const char* fmt, ...) {
  char buf[512];
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, ap);
  va_end(ap);
  s += buf;
}

std::vector<ImportGnssEpoch> FromPos(const std::string& path, int max_q, std::size_t& dropped) {
  std::vector<ImportGnssEpoch> out;
  for (const RtklibPosEpoch& p : ReadRtklibPos(path)) {
    if (p.quality < 1 || p.quality > max_q) {
      ++dropped;
      continue;
    }
    out.push_back({p.week * kImportWeek_s + p.sow, p.lat_deg, p.lon_deg, p.height_m, p.std_ned_m,
                   p.has_velocity, p.v_ned_mps, p.v_std_ned_mps, p.quality});
  }
  if (out.empty())
    throw ImportInputError(path, 0, "Q", "no epoch with Q ≤ " + std::to_string(max_q));
  return out;
}

// UBX gives seconds of week only: the week is the reference's (the nearest sow)
std::vector<ImportGnssEpoch> FromUbx(const std::string& path, double ref_t_s, bool msl,
                                     std::string& report) {
  const UbxNavLog log = ReadUbxNavLog(path);
  ImportAppendf(report,
                "GNSS input %s: %llu frames (%llu NAV-PVT, %llu NAV-POSLLH, %llu NAV-VELNED), "
                "%llu bad checksums, %llu cut, %llu epochs without a 3-D fix, %llu repeated iTOW\n",
                path.c_str(), (unsigned long long)log.frames, (unsigned long long)log.nav_pvt,
                (unsigned long long)log.posllh, (unsigned long long)log.velned,
                (unsigned long long)log.bad_checksum, (unsigned long long)log.cut_frames,
                (unsigned long long)log.not_fixed, (unsigned long long)log.duplicates);
  const double week0 = std::floor(ref_t_s / kImportWeek_s) * kImportWeek_s;
  std::vector<ImportGnssEpoch> out;
  for (const UbxNavFix& f : log.fixes) {
    double t = week0 + f.sow;
    if (t - ref_t_s > kImportWeek_s / 2) t -= kImportWeek_s;
    if (ref_t_s - t > kImportWeek_s / 2) t += kImportWeek_s;
    out.push_back({t, f.lat_deg, f.lon_deg, msl ? f.height_msl_m : f.height_m, f.std_ned_m,
                   f.has_velocity, f.v_ned_mps, f.v_std_ned_mps,
                   f.carrier_solution == 2   ? 1
                   : f.carrier_solution == 1 ? 2
                                             : 5});
  }
  return out;
}

}  // namespace

Eigen::Matrix3d ParseImuAxes(const std::string& axes) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
  const std::vector<std::string_view> f = SplitFields(axes, true);
  if (f.size() != 3) throw std::invalid_argument("--imu-axes: three signed axes, e.g. x,-y,-z");
  for (int r = 0; r < 3; ++r) {
    std::string_view a = f[static_cast<std::size_t>(r)];
    double sign = 1;
    if (!a.empty() && (a[0] == '-' || a[0] == '+')) sign = a[0] == '-' ? -1 : 1, a.remove_prefix(1);
    if (a.size() != 1 || a[0] < 'x' || a[0] > 'z')
      throw std::invalid_argument("--imu-axes: '" + std::string(f[static_cast<std::size_t>(r)]) +
                                  "' is not x, y or z with an optional sign");
    m(r, a[0] - 'x') = sign;
  }
  if (std::abs(m.determinant()) != 1.0)
    throw std::invalid_argument("--imu-axes: each sensor axis must be used once");
  return m;
}

namespace {

// the stream position each sample's line ended at, as the logger counted it
struct TagLineEnds {
  bool add_cr = false;
};

TagLineEnds MatchTagToFile(const ImuCsv& csv, const RtklibTimeTag& tag, const std::string& tag_path,
                           std::string& report) {
  const std::uint64_t last = tag.records.back().file_pos;
  const std::uint64_t lf_lines = csv.newlines;
  if (last == csv.file_bytes) return {false};
  if (!csv.has_cr && last == csv.file_bytes + lf_lines) {
    report += "time tag counts CR LF line ends; the CSV has LF only: one byte added per line\n";
    return {true};
  }
  throw ImportInputError(tag_path, static_cast<long>(tag.records.size()), "file position",
                         "last position " + std::to_string(last) + " matches neither the CSV's " +
                             std::to_string(csv.file_bytes) + " bytes nor that plus one CR a line");
}

std::vector<TimedImuSample> LoadImu(const DatasetImportOptions& o, ImuTickFit& fit,
                                    std::string& report) {
  const ImuCsv csv = ReadImuCsv(o.imu_csv, o.csv);
  const std::string tag_path = o.imu_tag.empty() ? o.imu_csv + ".tag" : o.imu_tag;
  const RtklibTimeTag tag = ReadRtklibTimeTag(tag_path, o.tag_fpos_bytes);
  ImportAppendf(report, "IMU %s: %zu samples, %ld lines (%ld cut at the log's ends)\n",
                o.imu_csv.c_str(), csv.samples.size(), csv.lines, csv.cut_lines);
  ImportAppendf(report, "time tag %s: '%s', opened %.3f GPST (s since 1970), %zu records\n",
                tag_path.c_str(), tag.header.c_str(), tag.open_gpst_s, tag.records.size());
  const TagLineEnds ends = MatchTagToFile(csv, tag, tag_path, report);
  std::vector<double> ticks, tags;
  for (const ImuCsvSample& s : csv.samples) {
    const std::uint64_t pos = s.end_pos + (ends.add_cr ? static_cast<std::uint64_t>(s.line) : 0);
    ticks.push_back(s.tick_s);
    tags.push_back(RtklibTimeTagTimeOf(tag, pos) - kImportGpsEpochUnix_s);
  }
  fit = FitImuTicks(ticks, tags);
  ImportAppendf(report,
                "tick fit: %.1f ppm against the tags, tag − fit residual RMS %.1f ms "
                "(%.1f to %.1f ms)\n",
                (fit.scale - 1) * 1e6, fit.residual_rms_s * 1e3, fit.residual_min_s * 1e3,
                fit.residual_max_s * 1e3);
  const Eigen::Matrix3d axes = ParseImuAxes(o.imu_axes);
  std::vector<TimedImuSample> out;
  for (const ImuCsvSample& s : csv.samples)
    out.push_back({fit.At(s.tick_s), axes * s.w_sensor_radps, axes * s.f_sensor_mps2});
  return out;
}

std::vector<CourseEpoch> CoursesOf(const std::vector<ImportGnssEpoch>& g) {
  std::vector<CourseEpoch> c;
  for (const ImportGnssEpoch& e : g)
    if (e.has_velocity) c.push_back({e.t_s, e.v_ned_mps});
  return c;
}

// yaw rate: the bias-free rate about the down direction seen at rest
std::vector<double> YawRates(const std::vector<TimedImuSample>& imu, const ImuAlignment& a,
                             std::vector<double>& t) {
  const Eigen::Vector3d down = -a.f_static_frd_mps2.normalized();
  std::vector<double> r;
  for (const TimedImuSample& s : imu) {
    t.push_back(s.t_s);
    r.push_back((s.w_frd_radps - a.gyro_bias_frd_radps).dot(down));
  }
  return r;
}

ImportGnssEpoch InterpolateEpoch(const std::vector<ImportGnssEpoch>& g, double t) {
  std::size_t j = 1;
  while (j + 1 < g.size() && g[j].t_s < t) ++j;
  const ImportGnssEpoch &a = g[j - 1], &b = g[j];
  const double u = std::clamp((t - a.t_s) / (b.t_s - a.t_s), 0.0, 1.0);
  ImportGnssEpoch e = a;
  e.t_s = t;
  e.lat_deg += u * (b.lat_deg - a.lat_deg);
  e.lon_deg += u * (b.lon_deg - a.lon_deg);
  e.height_m += u * (b.height_m - a.height_m);
  e.v_ned_mps += u * (b.v_ned_mps - a.v_ned_mps);
  return e;
}

// the IMU's position: the antenna's less the lever arm turned into NED
KfginsPva ImuPva(const ImportGnssEpoch& e, double sow, const Eigen::Matrix3d& c_ned_frd,
                 const Eigen::Vector3d& lever_frd) {
  constexpr double kA = 6378137.0, kE2 = 6.69437999014e-3;
  const double sl = std::sin(e.lat_deg * kImportDeg), w = std::sqrt(1 - kE2 * sl * sl);
  const double rm = kA * (1 - kE2) / (w * w * w), rn = kA / w;
  const Eigen::Vector3d d = c_ned_frd * lever_frd;
  KfginsPva p;
  p.sow = sow;
  p.lat_deg = e.lat_deg - d.x() / (rm + e.height_m) / kImportDeg;
  p.lon_deg =
      e.lon_deg - d.y() / ((rn + e.height_m) * std::cos(e.lat_deg * kImportDeg)) / kImportDeg;
  p.height_m = e.height_m + d.z();
  p.v_enu_mps = {e.v_ned_mps.y(), e.v_ned_mps.x(), -e.v_ned_mps.z()};
  Eigen::Matrix3d t;
  t << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  p.q_enu_flu = Eigen::Quaterniond(t * c_ned_frd * Eigen::Vector3d(1, -1, -1).asDiagonal());
  return p;
}

struct ImportSpan {
  double week0 = 0, t_start = 0, t_end = 0;
};

std::size_t WriteImu(KfginsTextFiles& files, const std::vector<TimedImuSample>& imu,
                     const ImportSpan& s) {
  std::size_t n = 0;
  for (std::size_t i = 1; i < imu.size(); ++i) {
    if (imu[i].t_s < s.t_start - 1.0 || imu[i].t_s > s.t_end) continue;
    const double dt = imu[i].t_s - imu[i - 1].t_s;
    const Eigen::Vector3d w = 0.5 * dt * (imu[i].w_frd_radps + imu[i - 1].w_frd_radps);
    const Eigen::Vector3d f = 0.5 * dt * (imu[i].f_frd_mps2 + imu[i - 1].f_frd_mps2);
    const Eigen::Vector3d flu(1, -1, -1);  // the writer takes FLU
    files.WriteImu(imu[i].t_s - s.week0, {flu.cwiseProduct(w), flu.cwiseProduct(f)});
    ++n;
  }
  return n;
}

std::size_t WriteGnss(KfginsTextFiles& files, const std::vector<ImportGnssEpoch>& gnss,
                      const ImportSpan& s, const std::vector<OutageWindow>& windows, bool posvel) {
  std::size_t n = 0;
  for (const ImportGnssEpoch& e : gnss) {
    if (e.t_s < s.t_start - 1.0 || e.t_s > s.t_end || InOutage(windows, e.t_s)) continue;
    const KfginsFix f{e.t_s - s.week0, e.lat_deg, e.lon_deg, e.height_m, e.std_ned_m};
    files.WriteGnss(f);
    if (posvel) files.WriteGnssPosVel(f, e.v_ned_mps, e.v_std_ned_mps);
    ++n;
  }
  return n;
}

// the truth: the reference moved to the IMU, yaw from the course (less the mounting yaw) while
// moving, held otherwise; roll and pitch are not observed by the reference and written as 0
std::size_t WriteTruth(KfginsTextFiles& files, const std::vector<ImportGnssEpoch>& ref,
                       const ImportSpan& s, const ImuAlignment& a, const DatasetImportOptions& o) {
  double yaw = a.yaw_rad;
  std::size_t n = 0;
  for (const ImportGnssEpoch& e : ref) {
    if (e.t_s < s.t_start - 1.0 || e.t_s > s.t_end) continue;
    if (e.v_ned_mps.head<2>().norm() > o.align.motion_speed_mps)
      yaw = std::atan2(e.v_ned_mps.y(), e.v_ned_mps.x()) - a.mount_yaw_rad;
    files.WriteTruth(ImuPva(e, e.t_s - s.week0, NedFromFrd(0, 0, yaw), o.lever_frd_m));
    ++n;
  }
  return n;
}

void WriteConfigs(KfginsTextFiles& files, const std::vector<TimedImuSample>& imu,
                  const std::vector<ImportGnssEpoch>& ref, const ImportSpan& s,
                  const ImuAlignment& a, const DatasetImportOptions& o, bool posvel) {
  KfginsYaml y;
  const ImportNoise& nz = o.noise;
  // KF-GINS reads the rate as an integer
  y.imudatarate_hz =
      std::round(static_cast<double>(imu.size() - 1) / (imu.back().t_s - imu.front().t_s));
  y.starttime_s = s.t_start - s.week0;
  y.init = ImuPva(InterpolateEpoch(ref, s.t_start), y.starttime_s,
                  NedFromFrd(a.roll_rad, a.pitch_rad, a.yaw_rad), o.lever_frd_m);
  y.initposstd_m = nz.initposstd_m;
  y.initvelstd_mps = nz.initvelstd_mps;
  y.initattstd_deg = nz.initattstd_deg;
  y.antlever_flu_m = {o.lever_frd_m.x(), -o.lever_frd_m.y(), -o.lever_frd_m.z()};
  y.arw_deg_rthr = nz.arw_deg_rthr, y.vrw_mps_rthr = nz.vrw_mps_rthr;
  y.gbstd_deg_hr = nz.gbstd_deg_hr, y.abstd_mgal = nz.abstd_mgal;
  y.gsstd_ppm = nz.gsstd_ppm, y.asstd_ppm = nz.asstd_ppm, y.corrtime_hr = nz.corrtime_hr;
  y.initgyrbias_deg_hr = a.gyro_bias_frd_radps / kImportDeg * 3600.0;
  y.initaccbias_mgal = a.accel_bias_frd_mps2 * 1e5;
  y.initbgstd_deg_hr = nz.initbgstd_deg_hr, y.initbastd_mgal = nz.initbastd_mgal;
  files.WriteConfig(y);
  if (posvel) files.WriteConfig(y, "GNSS-POSVEL.txt", "kf-gins-posvel.yaml");
}

void ReportAlignment(const ImuAlignment& a, const ImportSpan& s, std::string& rep) {
  const Eigen::Vector3d f = a.f_static_frd_mps2, b = a.gyro_bias_frd_radps / kImportDeg;
  ImportAppendf(
      rep,
      "rest %.3f-%.3f s of week: specific force FRD (%.4f, %.4f, %.4f) m/s², "
      "gyro bias FRD (%.4f, %.4f, %.4f) °/s, accelerometer bias along gravity %.1f mg\n",
      a.static_from_s - s.week0, a.static_to_s - s.week0, f.x(), f.y(), f.z(), b.x(), b.y(), b.z(),
      a.accel_bias_frd_mps2.norm() / 9.80665e-3 * (f.dot(a.accel_bias_frd_mps2) > 0 ? 1 : -1));
  ImportAppendf(rep,
                "initial attitude: roll %.2f°, pitch %.2f°, yaw %.2f° (yaw from %zu GNSS velocity "
                "increments, %.1f-%.1f s of week)\n",
                a.roll_rad / kImportDeg, a.pitch_rad / kImportDeg, a.yaw_rad / kImportDeg,
                a.yaw_fit_intervals, a.yaw_fit_from_s - s.week0, a.yaw_fit_to_s - s.week0);
  ImportAppendf(rep, "mounting yaw (course − IMU heading while moving, %zu epochs): %.1f°\n",
                a.mount_yaw_epochs, a.mount_yaw_rad / kImportDeg);
}

// the GNSS input: a UBX log or a .pos file (the reference by default), by quality
std::vector<ImportGnssEpoch> LoadGnssInput(const DatasetImportOptions& o, double ref_t_s,
                                           std::string& rep) {
  std::vector<ImportGnssEpoch> gnss;
  std::size_t dropped = 0;
  if (!o.gnss_ubx.empty()) {
    for (const ImportGnssEpoch& e : FromUbx(o.gnss_ubx, ref_t_s, o.ubx_height_msl, rep))
      if (e.quality <= o.gnss_max_q)
        gnss.push_back(e);
      else
        ++dropped;
  } else {
    gnss = FromPos(o.gnss_pos.empty() ? o.reference_pos : o.gnss_pos, o.gnss_max_q, dropped);
  }
  ImportAppendf(rep, "GNSS input: %zu epochs with quality ≤ %d (%zu others left out)\n",
                gnss.size(), o.gnss_max_q, dropped);
  return gnss;
}

}  // namespace

DatasetImportResult ImportDataset(const DatasetImportOptions& o, const std::string& dir) {
  DatasetImportResult r;
  std::string& rep = r.report;
  std::size_t dropped = 0;
  const std::vector<ImportGnssEpoch> ref = FromPos(o.reference_pos, o.reference_max_q, dropped);
  ImportAppendf(rep, "reference %s: %zu epochs with Q ≤ %d (%zu others left out)\n",
                o.reference_pos.c_str(), ref.size(), o.reference_max_q, dropped);
  const std::vector<ImportGnssEpoch> gnss = LoadGnssInput(o, ref.front().t_s, rep);
  std::vector<TimedImuSample> imu = LoadImu(o, r.tick_fit, rep);
  const std::vector<CourseEpoch> courses = CoursesOf(ref);
  if (courses.size() < 2)
    throw ImportInputError(o.reference_pos, 0, "vn",
                           "the reference has no velocities (needed to align)");
  AlignmentOptions al = o.align;
  al.normal_gravity_mps2 = NormalGravity(ref.front().lat_deg, ref.front().height_m);
  const ImuAlignment first = AlignImu(imu, courses, al);
  if (first.f_static_frd_mps2.z() > -0.8 * al.normal_gravity_mps2)
    throw std::runtime_error("--imu-axes " + o.imu_axes + ": at rest the body z axis reads " +
                             std::to_string(first.f_static_frd_mps2.z()) +
                             " m/s²; FRD's down axis must read about −g: choose other axes");
  if (o.imu_lag_s) {
    r.lag_s = *o.imu_lag_s;
  } else {
    std::vector<double> t;
    const std::vector<double> rate = YawRates(imu, first, t);
    r.lag = EstimateImuLag(t, rate, courses, o.max_lag_s, o.lag_min_speed_mps);
    r.lag_s = r.lag->lag_s;
  }
  for (TimedImuSample& s : imu) s.t_s -= r.lag_s;
  if (r.lag)
    ImportAppendf(rep,
                  "IMU lag behind GPS time (cross-correlation of gyro heading rate with the course "
                  "rate, %zu intervals, peak correlation %.3f): %.4f s (subtracted)\n",
                  r.lag->intervals, r.lag->correlation, r.lag_s);
  else
    ImportAppendf(rep, "IMU lag behind GPS time (given): %.4f s (subtracted)\n", r.lag_s);
  r.alignment = AlignImu(imu, courses, al);
  ImportSpan span;
  span.week0 = std::floor(ref.front().t_s / kImportWeek_s) * kImportWeek_s;
  span.t_end = std::min(ref.back().t_s, imu.back().t_s);
  span.t_start = imu.back().t_s;
  for (std::size_t i = 1; i < imu.size(); ++i)  // the first line of IMU.txt is the second sample
    if (imu[i].t_s >= r.alignment.static_from_s) {
      span.t_start = imu[i].t_s;
      break;
    }
  ReportAlignment(r.alignment, span, rep);
  if (o.have_outages) r.windows = PlanOutages(o.outages, span.t_start, span.t_end);
  std::filesystem::create_directories(dir);
  KfginsTextFiles files(dir);
  const bool posvel = std::all_of(gnss.begin(), gnss.end(),
                                  [](const ImportGnssEpoch& e) { return e.has_velocity; });
  r.imu_lines = WriteImu(files, imu, span);
  r.gnss_lines = WriteGnss(files, gnss, span, r.windows, posvel);
  r.truth_lines = WriteTruth(files, ref, span, r.alignment, o);
  WriteConfigs(files, imu, ref, span, r.alignment, o, posvel);
  files.Close();
  std::vector<OutageWindow> sow_windows;
  for (const OutageWindow& w : r.windows) {
    sow_windows.push_back({w.start_s - span.week0, w.end_s - span.week0});
    ImportAppendf(rep, "outage %.3f-%.3f s of week (%.1f-%.1f s after the start)\n",
                  w.start_s - span.week0, w.end_s - span.week0, w.start_s - span.t_start,
                  w.end_s - span.t_start);
  }
  WriteOutageWindows(dir + "/outages.txt", sow_windows);
  ImportAppendf(rep,
                "wrote %s: IMU.txt %zu lines from %.3f s of week, GNSS.txt %zu, truth.nav %zu%s\n",
                dir.c_str(), r.imu_lines, span.t_start - span.week0, r.gnss_lines, r.truth_lines,
                posvel ? ", GNSS-POSVEL.txt" : "");
  std::FILE* f = std::fopen((dir + "/import_report.txt").c_str(), "w");
  if (!f || std::fputs(rep.c_str(), f) < 0 || std::fclose(f) != 0)
    throw std::runtime_error(dir + "/import_report.txt: write error");
  return r;
}

}  // namespace hil::harness

#include "hil/harness/datasets/outage_score.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {

std::vector<KfginsStdLine> ReadKfginsStd(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  std::vector<KfginsStdLine> out;
  std::string line;
  long n = 0;
  static const char* kNames[] = {"sow", "σN", "σE", "σD", "σvN", "σvE", "σvD"};
  while (std::getline(in, line)) {
    ++n;
    const std::vector<std::string_view> f = SplitFields(line, false);
    if (f.empty() || f[0][0] == '#') continue;
    if (f.size() < 7) throw ImportInputError(path, n, kNames[f.size()], "missing");
    double v[7];
    for (int i = 0; i < 7; ++i)
      v[i] = ParseFiniteField(f[static_cast<std::size_t>(i)], path, n, kNames[i]);
    out.push_back({v[0], {v[1], v[2], v[3]}, {v[4], v[5], v[6]}});
  }
  return out;
}

namespace {

// the error of the result against one truth epoch, NED metres and m/s, heading in degrees
struct ScoreEpochError {
  Eigen::Vector3d pos_ned = Eigen::Vector3d::Zero(), vel_ned = Eigen::Vector3d::Zero();
  double heading_deg = 0;
};

Eigen::Vector3d ScoreNedOffset(const KfginsNavLine& from, double lat, double lon, double h) {
  constexpr double kA = 6378137.0, kE2 = 6.69437999014e-3, kD = 3.14159265358979323846 / 180;
  const double s = std::sin(from.lat_deg * kD), w = std::sqrt(1 - kE2 * s * s);
  const double rm = kA * (1 - kE2) / (w * w * w), rn = kA / w;
  return {(lat - from.lat_deg) * kD * (rm + from.height_m),
          (lon - from.lon_deg) * kD * (rn + from.height_m) * std::cos(from.lat_deg * kD),
          -(h - from.height_m)};
}

// false when the result does not bracket the epoch closely enough
bool ScoreErrorAt(const KfginsNavLine& truth, const std::vector<KfginsNavLine>& est,
                  ScoreEpochError& e) {
  const auto it = std::lower_bound(est.begin(), est.end(), truth.sow - 1e-9,
                                   [](const KfginsNavLine& l, double t) { return l.sow < t; });
  if (it == est.end()) return false;
  const KfginsNavLine& b = *it;
  const KfginsNavLine& a = it == est.begin() ? b : *(it - 1);
  if (b.sow - a.sow > 0.2 || (it == est.begin() && std::abs(b.sow - truth.sow) > 1e-6))
    return false;
  const double u = b.sow > a.sow ? (truth.sow - a.sow) / (b.sow - a.sow) : 0.0;
  e.pos_ned = ScoreNedOffset(truth, a.lat_deg + u * (b.lat_deg - a.lat_deg),
                             a.lon_deg + u * (b.lon_deg - a.lon_deg),
                             a.height_m + u * (b.height_m - a.height_m));
  e.vel_ned = a.v_ned_mps + u * (b.v_ned_mps - a.v_ned_mps) - truth.v_ned_mps;
  const double yaw = (u < 0.5 ? a : b).rpy_deg.z();
  e.heading_deg = std::remainder(yaw - truth.rpy_deg.z(), 360.0);
  return true;
}

const KfginsStdLine* ScoreStdAt(const std::vector<KfginsStdLine>& s, double sow) {
  const auto it = std::upper_bound(s.begin(), s.end(), sow + 1e-9,
                                   [](double t, const KfginsStdLine& l) { return t < l.sow; });
  if (it == s.begin()) return nullptr;
  return &*(it - 1);
}

void SummarizeWindows(OutageScore& sc) {
  if (sc.windows.empty()) return;
  double s2h = 0, s23 = 0, sh = 0, s3 = 0, shd = 0;
  for (const WindowScore& w : sc.windows) {
    s2h += w.max_h_m * w.max_h_m, s23 += w.max_3d_m * w.max_3d_m;
    sh += w.max_h_m, s3 += w.max_3d_m, shd += w.heading_end_deg * w.heading_end_deg;
    sc.worst_max_h_m = std::max(sc.worst_max_h_m, w.max_h_m);
    sc.worst_max_3d_m = std::max(sc.worst_max_3d_m, w.max_3d_m);
  }
  const double n = static_cast<double>(sc.windows.size());
  sc.rms_of_max_h_m = std::sqrt(s2h / n), sc.rms_of_max_3d_m = std::sqrt(s23 / n);
  sc.mean_of_max_h_m = sh / n, sc.mean_of_max_3d_m = s3 / n;
  sc.rms_heading_end_deg = std::sqrt(shd / n);
}

}  // namespace

OutageScore ScoreOutages(const std::vector<KfginsNavLine>& truth,
                         const std::vector<KfginsNavLine>& est,
                         const std::vector<OutageWindow>& windows, double from_s,
                         const std::vector<KfginsStdLine>* stds) {
  OutageScore sc;
  for (const OutageWindow& w : windows) sc.windows.push_back({w});
  double gh = 0, gv = 0, n_pos = 0, n_pv = 0;
  std::size_t covered = 0;
  for (const KfginsNavLine& t : truth) {
    ScoreEpochError e;
    if (!ScoreErrorAt(t, est, e)) continue;
    ++covered;
    const double h = e.pos_ned.head<2>().norm(), d3 = e.pos_ned.norm();
    bool inside = false;
    for (WindowScore& w : sc.windows) {
      if (t.sow < w.window.start_s || t.sow >= w.window.end_s) continue;
      inside = true;
      ++w.epochs;
      w.max_h_m = std::max(w.max_h_m, h), w.max_3d_m = std::max(w.max_3d_m, d3);
      w.rms_h_m += h * h, w.rms_3d_m += d3 * d3;
      w.heading_end_deg = e.heading_deg;
    }
    if (!inside && t.sow - truth.front().sow >= from_s) {
      ++sc.gnss_epochs;
      gh += h * h, gv += e.pos_ned.z() * e.pos_ned.z();
      sc.max_h_gnss_m = std::max(sc.max_h_gnss_m, h);
    }
    const KfginsStdLine* s = stds ? ScoreStdAt(*stds, t.sow) : nullptr;
    if (s && (s->pos_ned_m.array() > 0).all() && (s->vel_ned_mps.array() > 0).all()) {
      const double np = e.pos_ned.cwiseQuotient(s->pos_ned_m).squaredNorm();
      n_pos += np, n_pv += np + e.vel_ned.cwiseQuotient(s->vel_ned_mps).squaredNorm();
      ++sc.nees_epochs;
    }
  }
  if (covered == 0) throw std::runtime_error("no truth epoch is covered by the result");
  for (WindowScore& w : sc.windows)
    if (w.epochs > 0)
      w.rms_h_m = std::sqrt(w.rms_h_m / static_cast<double>(w.epochs)),
      w.rms_3d_m = std::sqrt(w.rms_3d_m / static_cast<double>(w.epochs));
  if (sc.gnss_epochs > 0) {
    const double n = static_cast<double>(sc.gnss_epochs);
    sc.rmse_h_gnss_m = std::sqrt(gh / n), sc.rmse_v_gnss_m = std::sqrt(gv / n);
    sc.rmse_3d_gnss_m = std::sqrt((gh + gv) / n);
  }
  if (sc.nees_epochs > 0) {
    sc.has_nees = true;
    sc.mean_nees_pos = n_pos / static_cast<double>(sc.nees_epochs);
    sc.mean_nees_posvel = n_pv / static_cast<double>(sc.nees_epochs);
  }
  SummarizeWindows(sc);
  return sc;
}

std::string OutageScoreText(const OutageScore& s) {
  std::string out;
  char buf[400];
  for (const WindowScore& w : s.windows) {
    std::snprintf(
        buf, sizeof buf,
        "outage %.3f-%.3f s: %zu epochs, horizontal max %.3f m rms %.3f m, 3-D max %.3f m "
        "rms %.3f m, heading error at end %.2f°\n",
        w.window.start_s, w.window.end_s, w.epochs, w.max_h_m, w.rms_h_m, w.max_3d_m, w.rms_3d_m,
        w.heading_end_deg);
    out += buf;
  }
  if (!s.windows.empty()) {
    std::snprintf(buf, sizeof buf,
                  "outages (%zu): RMS of maxima horizontal %.3f m, 3-D %.3f m; mean of maxima "
                  "horizontal %.3f m, 3-D %.3f m; worst horizontal %.3f m, 3-D %.3f m; RMS heading "
                  "error at ends %.2f°\n",
                  s.windows.size(), s.rms_of_max_h_m, s.rms_of_max_3d_m, s.mean_of_max_h_m,
                  s.mean_of_max_3d_m, s.worst_max_h_m, s.worst_max_3d_m, s.rms_heading_end_deg);
    out += buf;
  }
  std::snprintf(buf, sizeof buf,
                "GNSS present (%zu epochs): RMSE horizontal %.4f m, vertical %.4f m, 3-D %.4f m, "
                "max horizontal %.4f m\n",
                s.gnss_epochs, s.rmse_h_gnss_m, s.rmse_v_gnss_m, s.rmse_3d_gnss_m, s.max_h_gnss_m);
  out += buf;
  if (s.has_nees) {
    std::snprintf(buf, sizeof buf,
                  "NEES (%zu epochs): position %.2f (3 expected), position+velocity %.2f (6 "
                  "expected)\n",
                  s.nees_epochs, s.mean_nees_pos, s.mean_nees_posvel);
    out += buf;
  }
  return out;
}

std::string OutageScoreJson(const OutageScore& s) {
  nlohmann::json j;
  j["windows"] = nlohmann::json::array();
  for (const WindowScore& w : s.windows)
    j["windows"].push_back({{"start_sow", w.window.start_s},
                            {"end_sow", w.window.end_s},
                            {"epochs", w.epochs},
                            {"max_h_m", w.max_h_m},
                            {"rms_h_m", w.rms_h_m},
                            {"max_3d_m", w.max_3d_m},
                            {"rms_3d_m", w.rms_3d_m},
                            {"heading_end_deg", w.heading_end_deg}});
  j["rms_of_max_h_m"] = s.rms_of_max_h_m, j["rms_of_max_3d_m"] = s.rms_of_max_3d_m;
  j["mean_of_max_h_m"] = s.mean_of_max_h_m, j["mean_of_max_3d_m"] = s.mean_of_max_3d_m;
  j["worst_max_h_m"] = s.worst_max_h_m, j["worst_max_3d_m"] = s.worst_max_3d_m;
  j["rms_heading_end_deg"] = s.rms_heading_end_deg;
  j["gnss_present"] = {{"epochs", s.gnss_epochs},
                       {"rmse_h_m", s.rmse_h_gnss_m},
                       {"rmse_v_m", s.rmse_v_gnss_m},
                       {"rmse_3d_m", s.rmse_3d_gnss_m},
                       {"max_h_m", s.max_h_gnss_m}};
  if (s.has_nees)
    j["nees"] = {{"epochs", s.nees_epochs},
                 {"position", s.mean_nees_pos},
                 {"position_velocity", s.mean_nees_posvel}};
  return j.dump(2) + "\n";
}

}  // namespace hil::harness

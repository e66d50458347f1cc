#include "hil/harness/eval/path_tracking.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hil::harness {
namespace {

struct Foot {
  std::size_t edge = 0;
  double s_m = 0, xte_m = 0, yaw_rad = 0;
};

Foot Project(const std::vector<Eigen::Vector2d>& v, const std::vector<double>& s0,
             const Eigen::Vector2d& p) {
  Foot best;
  double best_d = INFINITY;
  for (std::size_t i = 0; i + 1 < v.size(); ++i) {
    const Eigen::Vector2d d = v[i + 1] - v[i];
    const double len = d.norm();
    const Eigen::Vector2d u = d / len;
    const bool first = i == 0, last = i + 2 == v.size();
    double a = (p - v[i]).dot(u);
    if (!(first && a < 0) && !(last && a > len)) a = std::clamp(a, 0.0, len);  // ends extend
    const Eigen::Vector2d q = v[i] + a * u;
    const double dist = (p - q).norm();
    if (dist < best_d - 1e-9) {
      best_d = dist;
      best.edge = i;
      best.s_m = s0[i] + a;
      best.xte_m = u.x() * (p - v[i]).y() - u.y() * (p - v[i]).x();
      best.yaw_rad = std::atan2(u.y(), u.x());
    }
  }
  return best;
}

double Wrap(double a) { return std::remainder(a, 2 * std::numbers::pi); }

XteStats Stats(const std::vector<double>& xte, const std::vector<double>& heading) {
  XteStats s;
  s.samples = xte.size();
  if (xte.empty()) return s;
  std::vector<double> absv;
  double sum = 0, sq = 0, hsq = 0;
  for (std::size_t i = 0; i < xte.size(); ++i) {
    absv.push_back(std::fabs(xte[i]));
    sum += absv.back();
    sq += xte[i] * xte[i];
    hsq += heading[i] * heading[i];
  }
  const double n = static_cast<double>(xte.size());
  s.mean_abs_m = sum / n;
  s.rmse_m = std::sqrt(sq / n);
  s.heading_rmse_deg = std::sqrt(hsq / n) * 180 / std::numbers::pi;
  std::sort(absv.begin(), absv.end());
  s.max_abs_m = absv.back();
  s.p95_abs_m = absv[std::min(absv.size() - 1, static_cast<std::size_t>(std::ceil(0.95 * n)) - 1)];
  return s;
}

// Paper 003's figures from the start: every moving sample, and the stable point (the first
// sign change of the deviation after an initial offset) with the mean |XTE| after it.
void ScoreFromStart(const std::vector<Foot>& feet, const std::vector<TrackSample>& track,
                    TrackingMetrics& m) {
  std::vector<double> xte, head;
  std::optional<std::size_t> stable;
  const double x0 = feet.front().xte_m;
  for (std::size_t i = 0; i < track.size(); ++i) {
    if (!stable && std::fabs(x0) > m.settle_band_m && feet[i].xte_m * x0 <= 0) stable = i;
    if (track[i].speed_mps < 0.05) continue;
    xte.push_back(feet[i].xte_m);
    head.push_back(Wrap(feet[i].yaw_rad - track[i].yaw_rad));
  }
  m.from_start = Stats(xte, head);
  if (!stable) return;
  m.stable_distance_m = feet[*stable].s_m - feet.front().s_m;
  double sum = 0;
  for (std::size_t i = *stable; i < track.size(); ++i) sum += std::fabs(feet[i].xte_m);
  m.steady_state_mean_abs_m = sum / static_cast<double>(track.size() - *stable);
}

}  // namespace

TrackingMetrics ScoreTracking(const std::vector<Eigen::Vector2d>& path,
                              const std::vector<TrackSample>& track, double settle_band_m) {
  PathGeometry g;
  g.vertices = path;
  for (std::size_t e = 0; e + 1 < path.size(); ++e) {
    g.edge_segment.push_back(static_cast<int>(e));
    g.segment_is_turn.push_back(false);
  }
  return ScoreTracking(g, track, settle_band_m);
}

TrackingMetrics ScoreTracking(const PathGeometry& geometry, const std::vector<TrackSample>& track,
                              double settle_band_m) {
  const std::vector<Eigen::Vector2d>& path = geometry.vertices;
  TrackingMetrics m;
  m.settle_band_m = settle_band_m;
  if (path.size() < 2 || track.empty()) return m;
  std::vector<double> s0{0};
  for (std::size_t i = 1; i < path.size(); ++i)
    s0.push_back(s0.back() + (path[i] - path[i - 1]).norm());
  std::vector<Foot> feet;
  for (std::size_t i = 0; i < track.size(); ++i) {
    feet.push_back(Project(path, s0, track[i].p_N_m));
    m.s_m.push_back(feet.back().s_m);
    m.xte_m.push_back(feet.back().xte_m);
    if (i > 0) m.distance_travelled_m += (track[i].p_N_m - track[i - 1].p_N_m).norm();
  }
  m.initial_cross_track_m = feet.front().xte_m;
  // settled: from the first sample after which |XTE| stays inside the band (while moving)
  std::size_t settle = track.size();
  for (std::size_t i = track.size(); i-- > 0;) {
    if (std::fabs(feet[i].xte_m) > settle_band_m) break;
    settle = i;
  }
  std::size_t from = 0;
  if (settle < track.size()) {
    // after an initial offset the figures are those of the settled vehicle (a path with turns
    // leaves the band in every turn: its figures are those of the whole run)
    const bool turns = std::find(geometry.segment_is_turn.begin(), geometry.segment_is_turn.end(),
                                 true) != geometry.segment_is_turn.end();
    if (std::fabs(m.initial_cross_track_m) > settle_band_m && !turns) from = settle;
    m.settling_time_s = ToSeconds(track[settle].t - track.front().t);
    m.settling_distance_m = feet[settle].s_m - feet.front().s_m;
  }
  std::vector<double> xte, head;
  const std::size_t segments = geometry.segment_is_turn.size();
  std::vector<std::vector<double>> seg_xte(segments), seg_head(segments);
  for (std::size_t i = from; i < track.size(); ++i) {
    if (track[i].speed_mps < 0.05) continue;  // a parked vehicle tracks nothing
    const double he = Wrap(feet[i].yaw_rad - track[i].yaw_rad);
    xte.push_back(feet[i].xte_m);
    head.push_back(he);
    const auto seg = static_cast<std::size_t>(geometry.edge_segment[feet[i].edge]);
    seg_xte[seg].push_back(feet[i].xte_m);
    seg_head[seg].push_back(he);
  }
  m.all = Stats(xte, head);
  ScoreFromStart(feet, track, m);
  std::vector<double> kind_xte[2], kind_head[2];  // straight, turn
  for (std::size_t k = 0; k < segments; ++k) {
    SegmentTracking st;
    st.index = static_cast<int>(k);
    st.kind = geometry.segment_is_turn[k] ? "turn" : "straight";
    bool any = false;
    for (std::size_t e = 0; e + 1 < path.size(); ++e) {
      if (static_cast<std::size_t>(geometry.edge_segment[e]) != k) continue;
      if (!any) st.start_s_m = s0[e];
      st.end_s_m = s0[e + 1];
      any = true;
    }
    st.stats = Stats(seg_xte[k], seg_head[k]);
    m.segments.push_back(st);
    const bool turn = geometry.segment_is_turn[k];
    kind_xte[turn].insert(kind_xte[turn].end(), seg_xte[k].begin(), seg_xte[k].end());
    kind_head[turn].insert(kind_head[turn].end(), seg_head[k].begin(), seg_head[k].end());
  }
  m.straight = Stats(kind_xte[0], kind_head[0]);
  m.turns = Stats(kind_xte[1], kind_head[1]);
  return m;
}

}  // namespace hil::harness

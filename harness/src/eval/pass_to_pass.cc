#include "hil/harness/eval/pass_to_pass.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>

namespace hil::harness {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// A straight segment of the path: a planned row.
struct Row {
  int segment = 0;
  Eigen::Vector2d a_m{0, 0}, u{1, 0};  ///< start and unit direction of travel
  double length_m = 0;
  std::vector<Eigen::Vector2d> driven_m;  ///< its samples, clipped to the margins and the window
  std::vector<double> xte_m;              ///< theirs against the planned row (+ left of travel)
};

// The straight segments of the path, each from its first to its last vertex.
std::vector<Row> Rows(const PathGeometry& g) {
  std::vector<Row> rows;
  const std::size_t segments = g.segment_is_turn.size();
  for (std::size_t k = 0; k < segments; ++k) {
    if (g.segment_is_turn[k]) continue;
    std::optional<std::size_t> first, last;
    for (std::size_t e = 0; e + 1 < g.vertices.size(); ++e) {
      if (static_cast<std::size_t>(g.edge_segment[e]) != k) continue;
      if (!first) first = e;
      last = e + 1;
    }
    if (!first) continue;
    const Eigen::Vector2d d = g.vertices[*last] - g.vertices[*first];
    if (d.norm() <= 0) continue;
    Row r;
    r.segment = static_cast<int>(k);
    r.a_m = g.vertices[*first];
    r.length_m = d.norm();
    r.u = d / r.length_m;
    rows.push_back(r);
  }
  return rows;
}

// The segment of the path edge nearest to p.
int NearestSegment(const PathGeometry& g, const Eigen::Vector2d& p) {
  double best = std::numeric_limits<double>::infinity();
  int seg = -1;
  for (std::size_t e = 0; e + 1 < g.vertices.size(); ++e) {
    const Eigen::Vector2d d = g.vertices[e + 1] - g.vertices[e];
    const double len2 = d.squaredNorm();
    const double t = len2 > 0 ? std::clamp((p - g.vertices[e]).dot(d) / len2, 0.0, 1.0) : 0.0;
    const double dist = (p - (g.vertices[e] + t * d)).norm();
    if (dist < best - 1e-9) {
      best = dist;
      seg = g.edge_segment[e];
    }
  }
  return seg;
}

// Both errors of p against the driven track `ref` (≥ 2 samples), nullopt when p's foot on it lies
// beyond either end. `side` is +1 when the later pass is planned left of `ref`'s direction.
struct PointErrors {
  double nearest_m = 0, interpolated_m = 0;
};
std::optional<PointErrors> Errors(const std::vector<Eigen::Vector2d>& ref, const Eigen::Vector2d& p,
                                  double side, double spacing_m) {
  double best = std::numeric_limits<double>::infinity(), offset = 0;
  bool beyond_end = false;
  for (std::size_t i = 0; i + 1 < ref.size(); ++i) {
    const Eigen::Vector2d d = ref[i + 1] - ref[i];
    const double len = d.norm();
    if (len <= 0) continue;
    const Eigen::Vector2d u = d / len;
    const double a = (p - ref[i]).dot(u);
    const Eigen::Vector2d q = ref[i] + std::clamp(a, 0.0, len) * u;
    const double dist = (p - q).norm();
    if (dist < best - 1e-12) {
      best = dist;
      offset = Cross(u, p - q) >= 0 ? dist : -dist;
      beyond_end = (i == 0 && a < -1e-9) || (i + 2 == ref.size() && a > len + 1e-9);  // nm
    }
  }
  if (beyond_end || !std::isfinite(best)) return std::nullopt;
  std::size_t n = 0;
  double nd = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const double dist = (p - ref[i]).norm();
    if (dist < nd) nd = dist, n = i;
  }
  // the nearest sample's side: against the track's direction there (its neighbours')
  const Eigen::Vector2d dir = ref[std::min(n + 1, ref.size() - 1)] - ref[n > 0 ? n - 1 : 0];
  const double n_signed = Cross(dir, p - ref[n]) >= 0 ? nd : -nd;
  return PointErrors{side * n_signed - spacing_m, side * offset - spacing_m};
}

// Assigns the track's samples in the window to the rows, inside their margins.
void AssignSamples(const PathGeometry& g, const TrackPass& track, const PassToPassConfig& c,
                   std::vector<Row>& rows, PassToPassMetrics& m) {
  std::optional<Time> end;
  track([&](const TrackSample& s) {
    if (!end) {
      end = s.t + DurationFromSeconds(c.window_s);
      m.window_start_s = ToSeconds(s.t);
      m.window_end_s = m.window_start_s;
    }
    if (s.t > *end) return;  // the samples come in time order: none after it is in the window
    if (s.speed_mps < c.min_speed_mps) return;
    const int seg = NearestSegment(g, s.p_N_m);
    for (Row& r : rows) {
      if (r.segment != seg) continue;
      const double along = (s.p_N_m - r.a_m).dot(r.u);
      if (along < c.margin_m || along > r.length_m - c.margin_m) break;
      r.driven_m.push_back(s.p_N_m);
      r.xte_m.push_back(Cross(r.u, s.p_N_m - r.a_m));
      m.window_end_s = ToSeconds(s.t);
      break;
    }
  });
}

// Pass `next` against the driven track of `prev`, its point errors appended to the totals.
std::optional<PassPair> ScorePair(const Row& prev, const Row& next, const PassToPassConfig& c,
                                  std::vector<double>& all_np, std::vector<double>& all_ip,
                                  std::vector<double>& diff) {
  const double cos_angle = std::fabs(prev.u.dot(next.u));
  if (cos_angle < std::cos(c.max_angle_deg * std::numbers::pi / 180)) return std::nullopt;
  if (prev.driven_m.size() < 2 || next.driven_m.empty()) return std::nullopt;
  const Eigen::Vector2d mid = next.a_m + 0.5 * next.length_m * next.u;
  const double lateral = Cross(prev.u, mid - prev.a_m);
  PassPair pair;
  pair.from_segment = prev.segment;
  pair.to_segment = next.segment;
  pair.spacing_m = std::fabs(lateral);
  const double side = lateral >= 0 ? 1.0 : -1.0;
  std::vector<double> np, ip;
  for (const Eigen::Vector2d& p : next.driven_m) {
    const std::optional<PointErrors> e = Errors(prev.driven_m, p, side, pair.spacing_m);
    if (!e) continue;
    np.push_back(e->nearest_m);
    ip.push_back(e->interpolated_m);
    diff.push_back(std::fabs(e->nearest_m - e->interpolated_m));
  }
  pair.nearest_point = ErrorStats(np);
  pair.interpolated = ErrorStats(ip);
  all_np.insert(all_np.end(), np.begin(), np.end());
  all_ip.insert(all_ip.end(), ip.begin(), ip.end());
  return pair;
}

}  // namespace

PassErrorStats ErrorStats(const std::vector<double>& signed_errors_m) {
  PassErrorStats s;
  s.samples = signed_errors_m.size();
  if (signed_errors_m.empty()) return s;
  std::vector<double> absv;
  absv.reserve(signed_errors_m.size());
  double sum = 0, sum_abs = 0;
  for (const double e : signed_errors_m) {
    sum += e;
    absv.push_back(std::fabs(e));
    sum_abs += absv.back();
  }
  const auto n = static_cast<double>(signed_errors_m.size());
  s.mean_m = sum / n;
  s.mean_abs_m = sum_abs / n;
  std::sort(absv.begin(), absv.end());
  s.max_abs_m = absv.back();
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * n));
  s.p95_abs_m = absv[std::clamp<std::size_t>(rank, 1, absv.size()) - 1];
  return s;
}

PassToPassMetrics ScorePassToPass(const PathGeometry& geometry,
                                  const std::vector<TrackSample>& track,
                                  const PassToPassConfig& config) {
  if (track.empty()) {
    PassToPassMetrics m;
    m.config = config;
    return m;
  }
  return ScorePassToPass(geometry, PassOver(track), config);
}

PassToPassMetrics ScorePassToPass(const PathGeometry& geometry, const TrackPass& track,
                                  const PassToPassConfig& config) {
  PassToPassMetrics m;
  m.config = config;
  if (geometry.vertices.size() < 2) return m;
  std::vector<Row> rows = Rows(geometry);
  AssignSamples(geometry, track, config, rows, m);
  std::vector<double> all_np, all_ip, diff, absolute;
  const Row* prev = nullptr;
  for (const Row& r : rows) {
    if (r.driven_m.empty()) continue;
    ++m.passes;
    absolute.insert(absolute.end(), r.xte_m.begin(), r.xte_m.end());
    if (prev) {  // consecutive passes (straight segments driven in the window), if parallel
      if (auto pair = ScorePair(*prev, r, config, all_np, all_ip, diff)) m.pairs.push_back(*pair);
    }
    prev = &r;
  }
  m.nearest_point = ErrorStats(all_np);
  m.interpolated = ErrorStats(all_ip);
  m.absolute = ErrorStats(absolute);
  if (!diff.empty()) {
    double sum = 0;
    for (const double d : diff) {
      sum += d;
      m.method_difference_max_m = std::max(m.method_difference_max_m, d);
    }
    m.method_difference_mean_m = sum / static_cast<double>(diff.size());
  }
  return m;
}

}  // namespace hil::harness

#include "hil/harness/eval/path_tracking.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "hil/harness/core/spill_file.h"
#include "hil/harness/eval/exact_selection.h"
#include "hil/harness/eval/series_decimator.h"

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

// XteStats's sums in the order the samples come (the additions a sum over a vector of them makes);
// the percentile from a pass over the same samples' |XTE|.
struct XteSums {
  std::size_t n = 0;
  double sum = 0, sq = 0, hsq = 0, max = 0;

  void Add(double xte, double heading) {
    const double a = std::fabs(xte);
    if (n == 0 || a > max) max = a;
    sum += a;
    sq += xte * xte;
    hsq += heading * heading;
    ++n;
  }
  XteStats Stats(const ValuePass& abs_values) const {
    XteStats s;
    s.samples = n;
    if (n == 0) return s;
    const auto count = static_cast<double>(n);
    s.mean_abs_m = sum / count;
    s.rmse_m = std::sqrt(sq / count);
    s.heading_rmse_deg = std::sqrt(hsq / count) * 180 / std::numbers::pi;
    s.max_abs_m = max;
    s.p95_abs_m = NearestRankP95(n, abs_values);
    return s;
  }
};

// A set of samples' sums with their |XTE| on disk.
struct XteSet {
  XteSums sums;
  SpillFile<double> abs_m;

  void Add(double xte, double heading) {
    sums.Add(xte, heading);
    abs_m.Add(std::fabs(xte));
  }
  XteStats Stats() const {
    return sums.Stats([this](const ValueVisit& v) { abs_m.ForEach(v); });
  }
};

// A sample's XTE and heading error, as the segments' partition holds them.
struct SegmentValue {
  double xte_m = 0, heading_rad = 0;
};

class TrackingScorer {
 public:
  TrackingScorer(const PathGeometry& g, double band_m) : g_(g) {
    m_.settle_band_m = band_m;
    s0_.push_back(0);
    const std::vector<Eigen::Vector2d>& v = g.vertices;
    for (std::size_t i = 1; i < v.size(); ++i) s0_.push_back(s0_.back() + (v[i] - v[i - 1]).norm());
  }

  TrackingMetrics Score(const TrackPass& track) {
    FirstPass(track);
    if (n_ == 0) return std::move(m_);
    Settle();
    EvaluatedPass(track);
    Segments(track);
    return std::move(m_);
  }

 private:
  Foot FootOf(const TrackSample& s) const { return Project(g_.vertices, s0_, s.p_N_m); }
  std::size_t SegmentOf(const Foot& f) const {
    return static_cast<std::size_t>(g_.edge_segment[f.edge]);
  }
  void FirstPass(const TrackPass& track);
  void FromStart(std::size_t i, const TrackSample& s, const Foot& f);
  void Settle();
  void EvaluatedPass(const TrackPass& track);
  void Partition(const TrackPass& track, std::vector<std::size_t>& offset,
                 SpillFile<SegmentValue>& part);
  void Segments(const TrackPass& track);

  const PathGeometry& g_;
  std::vector<double> s0_;
  TrackingMetrics m_;
  std::size_t n_ = 0, settle_ = 0, from_ = 0;
  TrackSample first_;
  Foot first_foot_;
  Eigen::Vector2d last_p_{0, 0};
  bool settle_open_ = true;  // the next sample is the settling candidate's
  Time settle_t_{};
  double settle_s_m_ = 0;
  std::optional<std::size_t> stable_;
  double steady_sum_ = 0;
  XteSet from_start_;
  std::vector<std::size_t> segment_samples_;  // evaluated moving samples per segment
};

// Every sample: the start, the distance, the settling candidate (the sample after the last one
// outside the band), paper 003's figures from the start, the plotted series.
void TrackingScorer::FirstPass(const TrackPass& track) {
  SeriesDecimator<Eigen::Vector2d> plot(kTrackingPlotBuckets, 0.01);
  track([&](const TrackSample& s) {
    const Foot f = FootOf(s);
    if (n_ == 0) first_ = s, first_foot_ = f, m_.initial_cross_track_m = f.xte_m;
    if (n_ > 0) m_.distance_travelled_m += (s.p_N_m - last_p_).norm();
    last_p_ = s.p_N_m;
    plot.Add(ToSeconds(s.t), f.xte_m, Eigen::Vector2d(f.s_m, f.xte_m));
    if (std::fabs(f.xte_m) > m_.settle_band_m) {
      settle_ = n_ + 1;
      settle_open_ = true;
    } else if (settle_open_) {
      settle_t_ = s.t;
      settle_s_m_ = f.s_m;
      settle_open_ = false;
    }
    FromStart(n_, s, f);
    ++n_;
  });
  for (const Eigen::Vector2d& p : plot.Points()) {
    m_.s_m.push_back(p.x());
    m_.xte_m.push_back(p.y());
  }
  m_.from_start = from_start_.Stats();
  if (!stable_) return;
  m_.steady_state_mean_abs_m = steady_sum_ / static_cast<double>(n_ - *stable_);
}

// Paper 003's figures from the start: every moving sample, and the stable point (the first sign
// change of the deviation after an initial offset) with the mean |XTE| from it on.
void TrackingScorer::FromStart(std::size_t i, const TrackSample& s, const Foot& f) {
  const double x0 = first_foot_.xte_m;
  if (!stable_ && std::fabs(x0) > m_.settle_band_m && f.xte_m * x0 <= 0) {
    stable_ = i;
    m_.stable_distance_m = f.s_m - first_foot_.s_m;
  }
  if (stable_) steady_sum_ += std::fabs(f.xte_m);
  if (s.speed_mps < 0.05) return;
  from_start_.Add(f.xte_m, Wrap(f.yaw_rad - s.yaw_rad));
}

// Settled: from the first sample after which |XTE| stays inside the band.
void TrackingScorer::Settle() {
  if (settle_ >= n_) return;
  // after an initial offset the figures are those of the settled vehicle (a path with turns
  // leaves the band in every turn: its figures are those of the whole run)
  const std::vector<bool>& kinds = g_.segment_is_turn;
  const bool turns = std::find(kinds.begin(), kinds.end(), true) != kinds.end();
  if (std::fabs(m_.initial_cross_track_m) > m_.settle_band_m && !turns) from_ = settle_;
  m_.settling_time_s = ToSeconds(settle_t_ - first_.t);
  m_.settling_distance_m = settle_s_m_ - first_foot_.s_m;
}

// The evaluated samples (from `from_`, moving): the whole run's figures, the segments' counts.
void TrackingScorer::EvaluatedPass(const TrackPass& track) {
  XteSet all;
  segment_samples_.assign(g_.segment_is_turn.size(), 0);
  std::size_t i = 0;
  track([&](const TrackSample& s) {
    if (i++ < from_ || s.speed_mps < 0.05) return;  // a parked vehicle tracks nothing
    const Foot f = FootOf(s);
    all.Add(f.xte_m, Wrap(f.yaw_rad - s.yaw_rad));
    ++segment_samples_[SegmentOf(f)];
  });
  m_.all = all.Stats();
}

// The evaluated samples' values grouped by segment on disk, each segment's in time order from
// `offset[k]`: per-segment buffers of together at most 32 768 values (our choice).
void TrackingScorer::Partition(const TrackPass& track, std::vector<std::size_t>& offset,
                               SpillFile<SegmentValue>& part) {
  const std::size_t segments = segment_samples_.size();
  offset.assign(segments + 1, 0);
  for (std::size_t k = 0; k < segments; ++k) offset[k + 1] = offset[k] + segment_samples_[k];
  const std::size_t per_buffer =
      std::max<std::size_t>(8, 32768 / std::max<std::size_t>(1, segments));
  std::vector<std::vector<SegmentValue>> buffer(segments);
  std::vector<std::size_t> written(segments, 0);
  const auto flush = [&](std::size_t k) {
    part.WriteAt(offset[k] + written[k], buffer[k].data(), buffer[k].size());
    written[k] += buffer[k].size();
    buffer[k].clear();
  };
  std::size_t i = 0;
  track([&](const TrackSample& s) {
    if (i++ < from_ || s.speed_mps < 0.05) return;
    const Foot f = FootOf(s);
    const std::size_t k = SegmentOf(f);
    buffer[k].push_back({f.xte_m, Wrap(f.yaw_rad - s.yaw_rad)});
    if (buffer[k].size() >= per_buffer) flush(k);
  });
  for (std::size_t k = 0; k < segments; ++k) flush(k);
}

// Each segment's figures, and the straight and turn segments' together (in segment order).
void TrackingScorer::Segments(const TrackPass& track) {
  std::vector<std::size_t> offset;
  SpillFile<SegmentValue> part(1);
  Partition(track, offset, part);
  const auto abs_of = [&part, &offset](std::vector<std::size_t> ks) -> ValuePass {
    return [&part, &offset, ks = std::move(ks)](const ValueVisit& visit) {
      for (const std::size_t k : ks)
        part.ForEach(offset[k], offset[k + 1],
                     [&](const SegmentValue& v) { visit(std::fabs(v.xte_m)); });
    };
  };
  XteSums kind[2];  // straight, turn
  std::vector<std::size_t> kind_segments[2];
  const std::vector<Eigen::Vector2d>& path = g_.vertices;
  for (std::size_t k = 0; k < segment_samples_.size(); ++k) {
    SegmentTracking st;
    st.index = static_cast<int>(k);
    const bool turn = g_.segment_is_turn[k];
    st.kind = turn ? "turn" : "straight";
    bool any = false;
    for (std::size_t e = 0; e + 1 < path.size(); ++e) {
      if (static_cast<std::size_t>(g_.edge_segment[e]) != k) continue;
      if (!any) st.start_s_m = s0_[e];
      st.end_s_m = s0_[e + 1];
      any = true;
    }
    XteSums sums;
    part.ForEach(offset[k], offset[k + 1], [&](const SegmentValue& v) {
      sums.Add(v.xte_m, v.heading_rad);
      kind[turn].Add(v.xte_m, v.heading_rad);
    });
    st.stats = sums.Stats(abs_of({k}));
    m_.segments.push_back(st);
    kind_segments[turn].push_back(k);
  }
  m_.straight = kind[0].Stats(abs_of(kind_segments[0]));
  m_.turns = kind[1].Stats(abs_of(kind_segments[1]));
}

}  // namespace

TrackPass PassOver(const std::vector<TrackSample>& track) {
  return [&track](const TrackVisit& visit) {
    for (const TrackSample& s : track) visit(s);
  };
}

TrackPass PassBetween(TrackPass track, Time from, Time to) {
  return [track = std::move(track), from, to](const TrackVisit& visit) {
    track([&](const TrackSample& s) {
      if (s.t >= from && s.t <= to) visit(s);
    });
  };
}

TrackingMetrics ScoreTracking(const std::vector<Eigen::Vector2d>& path,
                              const std::vector<TrackSample>& track, double settle_band_m) {
  PathGeometry g;
  g.vertices = path;
  for (std::size_t e = 0; e + 1 < path.size(); ++e) {
    g.edge_segment.push_back(static_cast<int>(e));
    g.segment_is_turn.push_back(false);
  }
  return ScoreTracking(g, PassOver(track), settle_band_m);
}

TrackingMetrics ScoreTracking(const PathGeometry& geometry, const std::vector<TrackSample>& track,
                              double settle_band_m) {
  return ScoreTracking(geometry, PassOver(track), settle_band_m);
}

TrackingMetrics ScoreTracking(const PathGeometry& geometry, const TrackPass& track,
                              double settle_band_m) {
  if (geometry.vertices.size() < 2) {
    TrackingMetrics m;
    m.settle_band_m = settle_band_m;
    return m;
  }
  return TrackingScorer(geometry, settle_band_m).Score(track);
}

}  // namespace hil::harness

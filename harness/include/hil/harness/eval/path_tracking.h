#pragma once
/// @file
/// Closed loop: how well the truth vehicle followed the planned path (report.json `tracking`).
/// The vehicle's reference point (truth, 10 Hz) against the path file's polyline: signed
/// cross-track by interpolation onto the nearest edge (ISO 12188-2's lateral deviation, + = left
/// of the direction of travel), heading error against the edge's direction, settling after the
/// start (the first time |XTE| stays below `settle_band_m` for good), and figures per segment
/// (the path file's segments, path_file_reader.h: a row, a side, a headland turn, a corner).
/// The track is read in passes (TrackPass), never held: a run's track may be days long (issue 40);
/// its percentiles are exact (exact_selection.h) over values spilled to disk (spill_file.h).

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/sim_time.h"
#include "hil/harness/scenario/path_file_reader.h"

namespace hil::harness {

/// One truth sample of the vehicle's reference point.
struct TrackSample {
  Time t{};
  Eigen::Vector2d p_N_m{0, 0};
  double yaw_rad = 0;  ///< ENU, counter-clockwise from east
  double speed_mps = 0;
};

/// A track read in time order: each call of a TrackPass visits every sample once, from the first.
using TrackVisit = std::function<void(const TrackSample&)>;
using TrackPass = std::function<void(const TrackVisit&)>;
/// Passes over `track` (which must outlive them).
TrackPass PassOver(const std::vector<TrackSample>& track);
/// Passes over the samples of `track` with `from` <= t <= `to`.
TrackPass PassBetween(TrackPass track, Time from, Time to);

struct XteStats {
  std::size_t samples = 0;
  double mean_abs_m = 0, rmse_m = 0, p95_abs_m = 0, max_abs_m = 0, heading_rmse_deg = 0;
};

struct SegmentTracking {
  int index = 0;
  std::string kind = "straight";
  double start_s_m = 0, end_s_m = 0;  ///< along the path
  XteStats stats;
};

struct TrackingMetrics {
  /// The whole evaluated run; after an initial offset beyond the band, from settling on.
  XteStats all;
  std::optional<double> settling_distance_m, settling_time_s;
  double initial_cross_track_m = 0;
  double settle_band_m = 0.05;
  double distance_travelled_m = 0;
  std::vector<SegmentTracking> segments;
  /// Every moving sample from the start (the approach after an offset included): paper 003's
  /// "mean deviation from start to end" and "largest deviation in the run".
  XteStats from_start;
  /// Paper 003's stable point: after an initial offset beyond the band, where the deviation first
  /// reaches 0 (changes sign); the along-path distance to it ("stable distance") and the mean
  /// |XTE| from it on ("steady-state deviation"). Empty without an offset or a crossing.
  std::optional<double> stable_distance_m, steady_state_mean_abs_m;
  /// The samples on straight segments (rows, AB lines, edges) and on turns, each together.
  XteStats straight, turns;
  /// The series for the plots: along-path distance and signed XTE of the samples, decimated in
  /// time (SeriesDecimator, kTrackingPlotBuckets: every sample of a run up to about 5 min).
  std::vector<double> s_m, xte_m;
};

/// Our choice, as the run's other plotted series (RunScoring::kPlotBuckets).
inline constexpr std::size_t kTrackingPlotBuckets = 2048;

/// Scores `track` (time order) against the polyline `path`, each edge its own straight segment.
TrackingMetrics ScoreTracking(const std::vector<Eigen::Vector2d>& path,
                              const std::vector<TrackSample>& track, double settle_band_m = 0.05);
/// The same with the path file's segments (rows, sides, turns: kind "straight" or "turn").
TrackingMetrics ScoreTracking(const PathGeometry& geometry, const std::vector<TrackSample>& track,
                              double settle_band_m = 0.05);
/// The same over a track read in passes (four at most), in memory bounded whatever its length.
TrackingMetrics ScoreTracking(const PathGeometry& geometry, const TrackPass& track,
                              double settle_band_m = 0.05);

}  // namespace hil::harness

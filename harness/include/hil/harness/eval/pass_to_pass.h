#pragma once
/// @file
/// Closed loop, ISO 12188-2 style: the pass-to-pass (relative) cross-track error between adjacent
/// passes of the driven track (report.json `pass_to_pass`).
///
/// What public sources say (ISO 12188-2:2012's own text is not public): the standard judges an
/// automated guidance system by the lateral deviation of a reference point on straight, level
/// passes in steady state; pass-to-pass accuracy is the relative accuracy over a 15 min window (the
/// skip or overlap between one pass and the next, quoted at 95 %); the standard does not say how to
/// compute the relative cross-track error from discrete samples, and a nearest-point calculation
/// and an interpolation along the previous pass can differ by up to 25 cm (Rounsaville, Dvorak and
/// Stombaugh, Trans. ASABE 59(6) 1609-1616, 2016). Both are computed here.
///
/// Choices of ours where the public text is silent (parameters, PassToPassConfig):
/// - passes: the straight segments of the planned path (path_file_reader.h), taken in path order;
///   two consecutive ones are adjacent passes when parallel within `max_angle_deg`. A truth sample
///   belongs to the pass whose segment holds its nearest path edge. Headland turns are no pass.
/// - steady state: `margin_m` at each end of a pass is left out (the settling after a turn).
/// - the window: the samples from the first evaluated one to `window_s` later; passes are clipped
///   to it.
/// - pass-to-pass error of a point p of pass k+1: its distance to pass k's driven track, signed
///   positive toward the side where pass k+1 is planned, minus the nominal spacing (the planned
///   distance between the two rows): + is a gap (skip), − an overlap. Nearest point: the distance
///   to the nearest sample of pass k. Interpolated: the perpendicular distance to pass k's track as
///   a polyline (linear interpolation between its samples). A point whose foot on pass k's track
///   falls beyond either end of it has no partner and is left out of both.
/// - p95: the nearest-rank 95th percentile of the unsigned errors (as `tracking`'s p95).
/// - absolute figures beside: the same passes' signed cross-track error against the planned rows.

#include <cstddef>
#include <vector>

#include "hil/harness/eval/path_tracking.h"
#include "hil/harness/scenario/pass_to_pass_spec.h"
#include "hil/harness/scenario/path_file_reader.h"

namespace hil::harness {

/// Figures of a set of signed errors (metres).
struct PassErrorStats {
  std::size_t samples = 0;
  double mean_m = 0;      ///< signed: + gap (skip), − overlap
  double mean_abs_m = 0;  ///< mean of the unsigned errors
  double p95_abs_m = 0;   ///< nearest-rank 95th percentile of the unsigned errors
  double max_abs_m = 0;
};

/// Two adjacent passes: pass `to_segment` against the driven track of pass `from_segment`.
struct PassPair {
  int from_segment = 0, to_segment = 0;  ///< the path's segment indices
  double spacing_m = 0;                  ///< nominal: the planned rows' distance
  PassErrorStats nearest_point, interpolated;
};

struct PassToPassMetrics {
  PassToPassConfig config;
  double window_start_s = 0, window_end_s = 0;  ///< run time of the first and last sample used
  std::size_t passes = 0;                       ///< straight segments with samples in the window
  std::vector<PassPair> pairs;
  PassErrorStats nearest_point, interpolated;  ///< all pairs together
  /// |nearest point − interpolated| over the same points
  double method_difference_mean_m = 0, method_difference_max_m = 0;
  /// the evaluated passes' cross-track error against the planned rows (+ left of travel)
  PassErrorStats absolute;
};

/// The signed errors' figures (empty input: all zero, samples 0).
PassErrorStats ErrorStats(const std::vector<double>& signed_errors_m);

/// Scores `track` (time order; its first sample opens the window) on `geometry`'s passes.
PassToPassMetrics ScorePassToPass(const PathGeometry& geometry,
                                  const std::vector<TrackSample>& track,
                                  const PassToPassConfig& config = {});
/// The same over a track read in one pass: only the window's samples are held.
PassToPassMetrics ScorePassToPass(const PathGeometry& geometry, const TrackPass& track,
                                  const PassToPassConfig& config = {});

}  // namespace hil::harness

#pragma once
/// @file
/// Paper 001's figures of a run (seeds_001_003.md A.13): the truth vehicle's deviation from its
/// aisle, measured against the ridges of the world model (GreenhouseWorld::Locate), on the straight
/// parts of the rows only: samples whose along-row position lies at least `margin_m` inside both
/// ridge ends (the headland turns and the entries into a row are not row following).
/// - lateral deviation: the reference point's distance from the aisle's centre line (the seed001
///   scenarios place the rangefinders' set line there);
/// - heading deviation: the angle between the direction of travel and the rows, either way along
///   them (folded into ±90°).
/// Per run: the maximum of each (`max_lateral_deviation_m`, `max_heading_deviation_deg`); the
/// campaign takes the max and the mean of these maxima across runs.

#include <cstddef>
#include <vector>

#include "hil/firmware_emu/world/greenhouse_world.h"
#include "hil/harness/eval/path_tracking.h"

namespace hil::harness {

struct RowDeviation {
  std::size_t samples = 0;
  double max_lateral_deviation_m = 0, mean_abs_lateral_m = 0;
  double max_heading_deviation_deg = 0;
};

RowDeviation ScoreRowDeviation(const world::GreenhouseWorld& world, const TrackPass& track,
                               double margin_m);

}  // namespace hil::harness

#pragma once
// Truth configurations shared by the truth tests and the benchmark.
#include "hil/truth/truth_integrator.h"

namespace hil::truth::testing {

/// Seed 003's 15 × 15 m rectangle from (−7, −7), clockwise, on rough ground with engine
/// vibration, at 0.8 m/s: turning, rolling and pitching, Earth rotation on.
inline TruthConfig RoughTurningConfig() {
  TruthConfig c;
  c.origin = {34.2, 108.9, 400};
  c.vehicle = VehicleParams::GreenhousePlatform();
  c.path = MakeRectangle({-7, -7}, 15, 15, 0, true, 2);
  c.speed_mps = 0.8;
  c.terrain.type = TerrainConfig::Type::kRough;
  c.terrain.amplitude_m = 0.05;
  c.terrain.seed = 7;
  VibrationComponent v;
  v.frequency_hz = 25;
  const double w = 2 * 3.141592653589793 * v.frequency_hz;
  v.heave_m = 0.5 / (w * w);
  v.roll_rad = 2.0 * 3.141592653589793 / 180 / w;
  v.pitch_rad = 1.0 * 3.141592653589793 / 180 / w;
  c.vibration.components.push_back(v);
  c.earth_rotation = true;
  return c;
}

/// Seed 004: a tractor on a boustrophedon field pattern at 1 m/s for about 1800 s (10 rows of
/// 170 m, 7.5 m apart, headland turns of radius 3.5 m).
inline TruthConfig TractorFieldConfig() {
  TruthConfig c;
  c.origin = {45.75, 126.63, 150};
  c.vehicle = VehicleParams::Tractor();
  BoustrophedonSpec b;
  b.row_length_m = 170;
  b.row_spacing_m = 7.5;
  b.rows = 10;
  b.turn_radius_m = 3.5;
  c.path = MakeBoustrophedon(b);
  c.guidance.lookahead_m = 3;
  c.speed_mps = 1.0;
  c.terrain.type = TerrainConfig::Type::kRough;
  c.terrain.amplitude_m = 0.03;
  c.terrain.min_wavelength_m = 5;
  c.terrain.max_wavelength_m = 40;
  return c;
}

}  // namespace hil::truth::testing

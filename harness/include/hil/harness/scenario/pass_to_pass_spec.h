#pragma once
/// @file
/// `closed_loop.pass_to_pass:` of a scenario: the parameters of the ISO 12188-2 style pass-to-pass
/// evaluation (harness/include/hil/harness/eval/pass_to_pass.h says what each one decides and why
/// the defaults are ours where ISO 12188-2's public descriptions are silent).

namespace hil::harness {

struct PassToPassConfig {
  double window_s = 900;        ///< 15 min: the window pass-to-pass accuracy is quoted over
  double margin_m = 10;         ///< left out at each end of a pass (settling after the turn)
  double max_angle_deg = 5;     ///< two straight segments this parallel are adjacent passes
  double min_speed_mps = 0.05;  ///< slower samples are a parked vehicle, not a pass
};

}  // namespace hil::harness

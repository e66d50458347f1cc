#pragma once
/// @file
/// The estimator's output at one time of validity, and its JSON-lines form (one object per line),
/// which is navd's stdout contract with the harness:
///   {"tov_utc_s": 1370851200.000000000, "tov_unix_ns": 1370851200000000000, "lat_deg": …,
///    "lon_deg": …, "height_m": …, "vel_enu_mps": [e, n, u], "speed_mps": …, "pos_std_enu_m":
///    [...], "yaw_deg": …, "roll_deg": …, "pitch_deg": …, "vel_std_enu_mps": [...], "nis_pos": …,
///    "mean_nis_pos": …, "mode": "ekf", "status": N}
/// (vel_enu_mps, speed_mps and the fields after pos_std_enu_m are present when known: a fix whose
/// receiver reported a speed without a course carries speed_mps and no vel_enu_mps).
/// `tov_unix_ns` is the time of validity as integer UTC nanoseconds since the Unix epoch (what the
/// harness reads), `tov_utc_s` the same in seconds for readers that want a number; `yaw_deg` is the
/// heading, degrees clockwise from true north (absent when unknown).

#include <array>
#include <cstdint>
#include <optional>
#include <string>

namespace hil::estimator {

struct NavSolution {
  std::int64_t tov_unix_ns = 0;                      ///< time of validity, UTC
  double lat_deg = 0, lon_deg = 0;                   ///< WGS-84
  double height_m = 0;                               ///< ellipsoidal height
  std::optional<std::array<double, 3>> vel_enu_mps;  ///< velocity in the local ENU frame
  std::optional<double> speed_mps;        ///< horizontal speed, also when its direction is unknown
  std::optional<double> yaw_deg;          ///< heading clockwise from true north
  std::array<double, 3> pos_std_enu_m{};  ///< 1-sigma position uncertainty, ENU
  std::optional<double> roll_deg,
      pitch_deg;  ///< body FLU: roll right-wing-down positive, pitch nose-up positive
  std::optional<std::array<double, 3>> vel_std_enu_mps;  ///< 1-sigma velocity uncertainty, ENU
  std::optional<double> nis_pos;  ///< NIS of the last GNSS position update (3 dof)
  std::optional<double>
      mean_nis_pos;                ///< running mean of the accepted position NIS (3 if consistent)
  std::string mode;                ///< filter mode name
  std::uint32_t status_flags = 0;  ///< health bit field (see the filter's status enum)
};

/// Formats a solution as one JSON object followed by '\n'.
std::string ToJsonLine(const NavSolution& s);

}  // namespace hil::estimator

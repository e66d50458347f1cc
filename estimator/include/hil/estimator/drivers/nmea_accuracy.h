#pragma once
/// @file
/// The accuracy navd gives an NMEA fix. GGA carries no accuracy estimate, only HDOP and the fix
/// quality, so the 1σ is configured: by default HDOP × UERE / √2 per horizontal axis; an RTK
/// rover's fixed (quality 4) and float (quality 5) solutions have their own configured 1σ,
/// because their error does not scale with a pseudorange UERE (a fixed solution is centimetres
/// whatever the HDOP, a float one decimetres). Vertical 1σ is twice the horizontal, with the
/// altitude's rounding (step²/12 of variance: GGA often writes it to 0.1 m) added. RMC's speed and
/// course give the horizontal velocity with the configured 1σ; its vertical (not in RMC) is 0 with
/// twice that 1σ.

#include <optional>

namespace hil::estimator {

/// Configured NMEA accuracies ([filter] nmea_uere_m, nmea_rtk_fixed_std_m, nmea_rtk_float_std_m).
struct NmeaAccuracy {
  double uere_m = 2.5;            ///< user equivalent range error (GPS, DGPS fixes)
  double rtk_fixed_std_m = 0.0;   ///< horizontal 1σ per axis of an RTK fixed fix (0: use UERE)
  double rtk_float_std_m = 0.0;   ///< horizontal 1σ per axis of an RTK float fix (0: use UERE)
  double velocity_std_mps = 0.2;  ///< horizontal 1σ per axis of the RMC speed/course velocity
};

/// GGA fix quality values used here.
inline constexpr int kGgaQualityRtkFixed = 4;
inline constexpr int kGgaQualityRtkFloat = 5;

/// Horizontal 1σ per axis (m) of an NMEA fix of GGA quality `quality` and HDOP `hdop` (a missing
/// HDOP counts as 5).
double NmeaHorizontalStd(const NmeaAccuracy& a, int quality, std::optional<double> hdop);

}  // namespace hil::estimator

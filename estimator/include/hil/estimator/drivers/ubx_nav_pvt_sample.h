#pragma once
/// @file
/// A UBX NAV-PVT message (u-blox 8/9, protocol 27+) as a GnssSample: one message per epoch holds
/// the whole solution, so no epoch assembly is needed. The accuracy is the receiver's own (hAcc,
/// vAcc, sAcc), inflated and floored by navd's settings; the GGA-style fix quality comes from the
/// flags: carrSoln 2 → 4 (RTK fixed), 1 → 5 (RTK float), else diffSoln → 2 (DGNSS), else 1.

#include <optional>

#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

/// How navd turns NAV-PVT's accuracy estimates into 1σ's ([filter] ubx_acc_scale,
/// ubx_pos_std_floor_m, ubx_vel_std_floor_mps). u-blox does not define hAcc/vAcc/sAcc exactly
/// ("horizontal/vertical accuracy estimate"); they behave like 1σ-ish figures, hAcc like a radial
/// RMS (our emulated F9P writes √2 × its per-axis σ). Per horizontal axis navd takes
/// scale × hAcc / √2, vertical scale × vAcc, each velocity axis scale × sAcc, none below its floor.
struct UbxPvtAccuracy {
  /// Inflation of the receiver's estimates: our choice, not a measured figure. 1.5 leaves room for
  /// a receiver that is optimistic after a re-acquisition (an undefined estimate is not trusted
  /// at face value) while still weighting a 1 m float fix 30 × below a 3 cm fixed one.
  double scale = 1.5;
  /// Per-axis floors: 1 cm (a fixed RTK solution's hAcc is ~1 cm and the antenna phase centre
  /// and lever arm are not known better), 2 cm/s (below the INS's velocity errors at the rates
  /// NAV-PVT comes at).
  double pos_floor_m = 0.01;
  double vel_floor_mps = 0.02;
  /// Ceiling on an RTK float fix's vertical 1σ ([filter] ubx_float_up_std_max_m): 0.3 m, our
  /// choice. The emulated F9P's float vAcc (1.0-1.5 m, × scale: 1.5-2.2 m) overstates its height
  /// error (0.2-0.56 m measured on rtk_f9p_radio_loss, seed 44); at that σ the float's ~10 s leave
  /// the height unaided and navd's roll drifts 0.10° -> 0.19°, a bias that no fixed fix on a
  /// straight row corrects (2.8 m antenna height: +0.4 cm east, fused/raw 1.58 -> 2.03). GGA's
  /// float σ is 2 × nmea_rtk_float_std_m plus the correlated float model, a few cm. 0.3 m: above
  /// the largest measured float height error; any ceiling 0.01-0.3 m gives the same figures.
  double float_up_max_std_m = 0.3;
};

/// GGA-style fix quality of a NAV-PVT (4 fixed, 5 float, 2 DGNSS, 1 GNSS).
int NavPvtFixQuality(const UbxMessage& m);

/// The sample of a NAV-PVT, or none when it holds no usable fix (gnssFixOK clear, fixType not
/// 2-D/3-D/GNSS+DR, invalidLlh set) or no valid UTC date and time to place iTOW's week. Its
/// time: iTOW (ms) in the GPS week that holds the UTC date and time + `leap_s`.
std::optional<GnssSample> NavPvtToGnssSample(const UbxMessage& m, int leap_s,
                                             const UbxPvtAccuracy& acc);

}  // namespace hil::estimator::drivers

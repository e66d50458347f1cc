#pragma once
/// @file
/// Everything the UBX and NMEA encoders need from one navigation epoch of a receiver: the
/// protocol-neutral fix, the sky, the fix-state flags and the receiver clock. Encoders never see
/// the truth.

#include <cstdint>
#include <vector>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/fix_state.h"
#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/firmware_emu/gnss/gps_time.h"

namespace hil::gnss {

struct NavEpoch {
  GnssFix fix;                      ///< fix.fix_type == kNoFix when there is none
  bool position_known = false;      ///< a position exists (fix now or earlier), even if invalid
  std::vector<SatelliteView> sats;  ///< sorted by svid
  std::vector<int> used_in_channel_order;  ///< svids of used satellites, by channel
  FixStatus status;
  GpsWeekTime gps;          ///< GPS time of the epoch
  int leap_s = 18;          ///< GPS − UTC
  bool leap_known = false;  ///< from the almanac (else the firmware default)
  double clk_bias_ns = 0, clk_drift_nsps = 0;
  double t_acc_ns = 0, f_acc_psps = 0;
  bool sbas_corrections = false;  ///< DGPS (SBAS) corrections applied to the solution
  double geoid_separation_m() const { return fix.geoid_separation_m; }
};

}  // namespace hil::gnss

#pragma once
/// @file
/// Receiver profiles: everything that distinguishes one emulated receiver product from another
/// (defaults of the port and the output, banner and version strings, TTFF, error grade).
///  - `neo-5m` (default): u-blox NEO-5M, UART1 9600 8N1, NMEA RMC, VTG, GGA, GSA, GSV, GLL at 1 Hz
///    in that order, the $GPTXT banner after start and reset, firmware-6 number formats, maximum
///    navigation rate 4 Hz (UNVERIFIED: shared/reference/ublox5.md §4), metre-level errors.
///    CFG-RATE faster than that maximum is acknowledged and run ("ACK and run", issue 40), down to
///    `cfg_rate_max_hz` (10 Hz, 100 ms); shorter periods are NAKed. No source says what a NEO-5M
///    does: the u-blox 5 receiver description (GPS.G5-X-07036) bounds measRate nowhere and fixes
///    navRate at 1 (as ublox_msgs' CfgRATE.msg quotes it), and the 4 Hz of u-blox-5/6-class data
///    sheets is a performance figure, not a documented refusal; the next generation, whose NEO-6M
///    data sheet says 5 Hz, acknowledges and runs 10 Hz (iNavFlight/inav issue #48, 2016: "10hz
///    with neo6m works perfectly", "It works with my 6M too"). The captures in
///    shared/vectors/gpsd-ublox5 hold no CFG-RATE. So this is the profile's choice by analogy, and
///    the 10 Hz floor is ours (UNVERIFIED). Stock PX4 asks every receiver for 5 Hz (200 ms) and
///    so configures this one.
///    Banner and MON-VER strings are those of a real u-blox 5 with firmware 6.02 (gpsd's nl551e
///    capture); the MOD line names the NEO-5M by analogy with the LEA-5H's (UNVERIFIED).
///  - `rtk`: an RTK rover for seed 004: 10 Hz, 115200 baud, NMEA RMC, VTG, GGA every epoch and
///    GSA, GSV once a second, 7 decimals of minutes, GGA quality 5 (float, decimetres) for the
///    first `rtk_fixed_after_s` after each (re)acquisition, then 4 (fixed, centimetres).

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "hil/firmware_emu/gnss/fix_state.h"
#include "hil/firmware_emu/gnss/nmea_encoder.h"
#include "hil/firmware_emu/gnss/receiver_model.h"

namespace hil::gnss {

struct ReceiverProfile {
  std::string name;
  int baud = 9600;
  double rate_hz = 1.0;
  double max_rate_hz = 4.0;       ///< data-sheet maximum: a scenario's rate_hz may not exceed it
  double cfg_rate_max_hz = 10.0;  ///< fastest CFG-RATE acknowledged and run (see above)
  std::map<std::uint8_t, std::uint8_t> nmea_rates;  ///< class-0xF0 id → rate (per epoch)
  std::vector<std::string> banner;                  ///< $GPTXT lines after start/reset
  std::string sw_version, hw_version;               ///< MON-VER
  std::vector<std::string> version_extensions;
  nmea::NmeaFormat format;
  FixStateConfig fix_state;
  ReceiverModelConfig model;  ///< default error grade
  bool rtk = false;
  double rtk_fixed_after_s = 20.0;
  double rtk_float_sigma_m = 0.15;
};

/// The profile named `name` ("neo-5m" or "rtk"). @throws std::invalid_argument otherwise.
ReceiverProfile ProfileByName(const std::string& name);

}  // namespace hil::gnss

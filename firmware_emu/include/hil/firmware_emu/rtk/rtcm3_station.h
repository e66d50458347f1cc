#pragma once
/// @file
/// RTCM 3 station messages (RTCM 10403.3 §3.5.3): 1005 (stationary RTK reference station ARP) and
/// 1006 (the same with the antenna height). Bodies only; rtcm3_frame.h frames them.
///
/// 1005 body, 152 bits: DF002 message number u12 · DF003 station ID u12 · DF021 ITRF realization
/// year u6 · DF022 GPS u1 · DF023 GLONASS u1 · DF024 Galileo u1 · DF141 reference-station
/// indicator u1 · DF025 ARP ECEF-X s38 (0.0001 m) · DF142 single receiver oscillator u1 · DF001
/// reserved u1 · DF026 ARP ECEF-Y s38 · DF364 quarter cycle indicator u2 · DF027 ARP ECEF-Z s38.
/// 1006 appends DF028 antenna height u16 (0.0001 m): 168 bits.

#include <string>

#include <Eigen/Core>

namespace hil::rtcm3 {

/// What the station messages say about the base.
struct StationInfo {
  int station_id = 0;                                 ///< DF003, 0–4095
  Eigen::Vector3d arp_E_m = Eigen::Vector3d::Zero();  ///< antenna reference point, ECEF
  double antenna_height_m = 0;                        ///< DF028: ARP above the marker
  int itrf_year = 0;                                  ///< DF021 (0: not specified)
  bool gps = true, glonass = false, galileo = false;  ///< DF022–DF024: services observed
  bool single_oscillator = true;                      ///< DF142: one clock for all signals
  int quarter_cycle = 0;                              ///< DF364 (0: correction status unknown)
};

/// The 1005 body. @throws std::out_of_range for a field that does not fit.
std::string Encode1005(const StationInfo& s);
/// The 1006 body. @throws std::out_of_range for a field that does not fit.
std::string Encode1006(const StationInfo& s);
/// Decodes a 1005 or 1006 body (the tests' reader; antenna height 0 for 1005).
/// @throws std::invalid_argument when the body is neither or has the wrong length.
StationInfo DecodeStation(const std::string& body);

}  // namespace hil::rtcm3

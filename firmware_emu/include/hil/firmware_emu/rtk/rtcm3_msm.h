#pragma once
/// @file
/// RTCM 3 Multiple Signal Messages (RTCM 10403.3 §3.5.12), MSM4 and MSM7 for GPS (1074, 1077).
/// Bodies only; rtcm3_frame.h frames them. Field tables: vectors/rtcm3/README.md.
///
/// Header: DF002 u12 · DF003 u12 · DF004 GPS epoch time u30 (ms of week) · DF393 multiple
/// message u1 · DF409 IODS u3 · DF001 reserved u7 · DF411 clock steering u2 · DF412 external
/// clock u2 · DF417 smoothing u1 · DF418 smoothing interval u3 · DF394 satellite mask u64 · DF395
/// signal mask u32 · DF396 cell mask (Nsat·Nsig bits, at most 64).
/// MSM4 satellite data: DF397 rough range integer ms u8 · DF398 rough range modulo 1 ms u10
/// (2^-10 ms). Signal data: DF400 fine pseudorange s15 (2^-24 ms) · DF401 fine phaserange s22
/// (2^-29 ms) · DF402 lock time indicator u4 · DF420 half-cycle ambiguity u1 · DF403 CNR u6 (dBHz).
/// MSM7 satellite data: DF397 u8 · DF419 extended info u4 · DF398 u10 · DF399 rough phaserange
/// rate s14 (m/s). Signal data: DF405 fine pseudorange s20 (2^-29 ms) · DF406 fine phaserange s24
/// (2^-31 ms) · DF407 lock time u10 (extended) · DF420 u1 · DF408 CNR u10 (2^-4 dBHz) · DF404
/// fine phaserange rate s15 (0.0001 m/s).
/// Ranges are in light-milliseconds (299 792.458 m); a field that does not fit is sent as the
/// standard's "invalid" value.

#include <cstdint>
#include <string>
#include <vector>

namespace hil::rtcm3 {

/// One light-millisecond in metres (the unit of MSM ranges).
inline constexpr double kLightMs_m = 299792.458;

/// One signal of one satellite (a cell).
struct MsmSignal {
  int signal_id = 2;               ///< DF395 bit number 1–32 (GPS: 2 = 1C, 10 = 2W, 16 = 2L…)
  double pseudorange_m = 0;        ///< full pseudorange; NaN: invalid
  double phaserange_m = 0;         ///< carrier phase × wavelength; NaN: invalid
  double phaserange_rate_mps = 0;  ///< MSM7 only; NaN: invalid
  double lock_time_s = 0;          ///< continuous carrier lock so far
  bool half_cycle = false;         ///< DF420: half-cycle ambiguity unresolved
  double cnr_dbhz = 0;             ///< 0: not computed
};

/// One satellite and its signals (sorted by signal_id).
struct MsmSatellite {
  int id = 1;  ///< DF394 bit number 1–64 (GPS PRN)
  std::vector<MsmSignal> signals;
};

/// One MSM epoch of one constellation.
struct MsmEpoch {
  int station_id = 0;                    ///< DF003
  std::uint32_t epoch_time_ms = 0;       ///< DF004: GPS time of week (ms)
  bool multiple_message = false;         ///< DF393: more MSMs of this epoch follow
  int iods = 0;                          ///< DF409
  int clock_steering = 0;                ///< DF411: 0 none, 1 steered, 2 unknown
  int external_clock = 0;                ///< DF412: 0 internal, 1 external locked, 2 not locked
  bool smoothing = false;                ///< DF417
  int smoothing_interval = 0;            ///< DF418 code
  std::vector<MsmSatellite> satellites;  ///< sorted by id
};

enum class MsmKind { kMsm4 = 4, kMsm7 = 7 };

/// GPS MSM body (1074 or 1077). @throws std::invalid_argument when satellites × signals > 64,
/// an id is out of range or ids are not ascending.
std::string EncodeGpsMsm(const MsmEpoch& epoch, MsmKind kind);
/// Decodes a GPS MSM4/MSM7 body into what the fields hold (the tests' reader): values at the
/// message's resolution, invalid fields as NaN. @throws std::invalid_argument on a malformed body.
MsmEpoch DecodeGpsMsm(const std::string& body, MsmKind& kind);

/// DF402 (MSM4) lock time indicator of a lock time.
int LockIndicatorMsm4(double lock_time_s);
/// DF407 (MSM7, extended resolution) lock time indicator of a lock time.
int LockIndicatorMsm7(double lock_time_s);
/// The minimum lock time (s) a DF407 indicator stands for.
double LockTimeOfMsm7Indicator(int indicator);

}  // namespace hil::rtcm3

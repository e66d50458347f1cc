#pragma once
/// @file
/// UBX RXM-RAWX (0x02 0x15), the raw measurements of a u-blox F9 (protocol 27+): the ZED-F9P
/// interface description (u-blox UBX-18010854, HPG 1.32) §3.17.x, version 1. Payload 16 + 32 ×
/// numMeas bytes: 0 rcvTow R8 (s, receiver time), 8 week U2, 10 leapS I1, 11 numMeas U1,
/// 12 recStat X1 (bit 0 leapSec determined, bit 1 clkReset), 13 version U1 (1), 14 reserved;
/// per measurement at 16 + 32 n: 0 prMes R8 (m), 8 cpMes R8 (cycles), 16 doMes R4 (Hz, positive
/// for an approaching satellite), 20 gnssId, 21 svId, 22 sigId, 23 freqId, 24 locktime U2 (ms,
/// saturating at 64500), 26 cno U1 (dBHz), 27 prStdev (0.01 m × 2^n), 28 cpStdev (0.004 cycles
/// × n), 29 doStdev (0.002 Hz × 2^n), 30 trkStat (bit 0 prValid, 1 cpValid, 2 halfCyc, 3
/// subHalfCyc), 31 reserved. vectors/gnss/README.md ("ZED-F9P messages") lists the same.

#include <cstdint>
#include <vector>

namespace hil::gnss::ubx {

inline constexpr std::uint8_t kRxmRawx = 0x15;
/// UBX sigId of GPS L1 C/A and L2 CL (interface description §1.5, "GNSS signal identifiers").
inline constexpr std::uint8_t kSigGpsL1Ca = 0, kSigGpsL2Cl = 3;
/// locktime saturates here (the interface description: "maximum 64500 ms").
inline constexpr double kRawxMaxLocktime_ms = 64500;

struct RawxMeasurement {
  double pr_m = 0, cp_cycles = 0;
  double do_hz = 0;
  std::uint8_t gnss_id = 0, sv_id = 0, sig_id = 0, freq_id = 0;
  double locktime_ms = 0;
  double cno_dbhz = 0;
  double pr_sigma_m = 0, cp_sigma_cycles = 0, do_sigma_hz = 0;
  bool pr_valid = true, cp_valid = true, half_cyc = true;
};

struct RawxEpoch {
  double rcv_tow_s = 0;  ///< the measurement time in the receiver's clock
  std::uint16_t week = 0;
  int leap_s = 0;
  bool leap_valid = false, clk_reset = false;
  std::vector<RawxMeasurement> meas;  ///< at most 255 (numMeas is a U1)
};

/// The RXM-RAWX payload of `e`. Standard deviations go to the nearest code at or above them.
std::vector<std::uint8_t> EncodeRxmRawx(const RawxEpoch& e);

}  // namespace hil::gnss::ubx

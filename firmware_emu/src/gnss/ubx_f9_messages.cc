#include "hil/firmware_emu/gnss/ubx_f9_messages.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss::ubx {
namespace {

constexpr std::uint32_t kF9UnknownAcc = 0xFFFFFFFFu;

std::int64_t F9Round(double v) { return static_cast<std::int64_t>(std::llround(v)); }
std::uint64_t F9RoundU(double v) {
  if (!(v >= 0)) return 0;
  return static_cast<std::uint64_t>(std::llround(std::min(v, 4.0e9)));
}
std::uint32_t F9Itow(const NavEpoch& e) {
  return static_cast<std::uint32_t>((e.gps.tow_ns + 500000) / 1000000);
}

// lat/lon in 1e-7 deg and the 1e-9 deg remainder (−99…+99), heights in mm and 0.1 mm remainder.
struct HighPrecision {
  std::int64_t coarse;
  std::int64_t fine;
};
HighPrecision SplitHp(double value, double coarse_unit, double fine_unit) {
  const std::int64_t total = F9Round(value / fine_unit);
  const auto ratio = static_cast<std::int64_t>(std::llround(coarse_unit / fine_unit));
  std::int64_t coarse = total / ratio;
  return {coarse, total - coarse * ratio};
}

std::uint8_t PvtFlags(const F9Epoch& e) {
  std::uint8_t f = 0;
  if (e.nav.fix.valid()) f |= 0x01;                                             // gnssFixOK
  if (e.nav.fix.valid() && e.diff_soln) f |= 0x02;                              // diffSoln
  f |= static_cast<std::uint8_t>(static_cast<std::uint8_t>(e.carr_soln) << 6);  // carrSoln
  return f;
}

std::uint32_t RelposFlags(const F9Epoch& e, bool rel_pos_valid) {
  const bool fix_ok = e.nav.fix.valid();
  std::uint32_t flags = 0;
  if (fix_ok) flags |= 1U;                                    // gnssFixOK
  if (fix_ok && e.rel_diff_soln) flags |= 1U << 1;            // diffSoln
  if (rel_pos_valid) flags |= 1U << 2;                        // relPosValid
  flags |= static_cast<std::uint32_t>(e.rel_carr_soln) << 3;  // carrSoln
  if (e.is_moving) flags |= 1U << 5;                          // isMoving
  if (e.ref_pos_miss) flags |= 1U << 6;                       // refPosMiss
  if (e.ref_obs_miss) flags |= 1U << 7;                       // refObsMiss
  if (rel_pos_valid && e.heading_valid) flags |= 1U << 8;     // relPosHeadingValid
  return flags;
}

}  // namespace

std::uint8_t LastCorrectionAgeCode(double age_s) {
  if (age_s < 0) return 0;
  constexpr double kUpper_s[] = {1, 2, 5, 10, 15, 20, 30, 45, 60, 90, 120};
  for (std::uint8_t k = 0; k < 11; ++k) {
    if (age_s < kUpper_s[k]) return static_cast<std::uint8_t>(k + 1);
  }
  return 12;
}

std::vector<std::uint8_t> EncodeNavPvt(const F9Epoch& e) {
  const NavEpoch& n = e.nav;
  const GnssFix& f = n.fix;
  const bool valid = f.valid();
  const UtcTime u = UtcFrom(f.utc);
  const bool tk = n.status.time_known;
  Writer w;
  w.U4(F9Itow(n)).U2(u.year).U1(u.month).U1(u.day).U1(u.hour).U1(u.minute).U1(u.second);  // 0–10
  w.U1(tk ? (n.leap_known ? 0x07 : 0x03) : 0x00);  // 11 valid: validDate, validTime, resolved
  w.U4(F9RoundU(n.t_acc_ns)).I4(u.nanosecond);     // 12 tAcc, 16 nano
  w.U1(static_cast<std::uint8_t>(f.fix_type)).U1(PvtFlags(e));  // 20 fixType, 21 flags
  w.U1(tk ? 0xE0 : 0x00).U1(valid ? f.num_sv : 0);              // 22 flags2 (confirmed*), 23 numSV
  const bool pos = n.position_known;
  w.I4(pos ? F9Round(f.lon_deg * 1e7) : 0)
      .I4(pos ? F9Round(f.lat_deg * 1e7) : 0);                         // 24 lon, 28 lat
  w.I4(pos ? F9Round(f.height_m * 1e3) : 0);                           // 32 height
  w.I4(pos ? F9Round((f.height_m - f.geoid_separation_m) * 1e3) : 0);  // 36 hMSL
  w.U4(valid ? F9RoundU(f.h_acc_m * 1e3) : kF9UnknownAcc);             // 40 hAcc
  w.U4(valid ? F9RoundU(f.v_acc_m * 1e3) : kF9UnknownAcc);             // 44 vAcc
  w.I4(F9Round(f.vel_n_mps * 1e3)).I4(F9Round(f.vel_e_mps * 1e3)).I4(F9Round(f.vel_d_mps * 1e3));
  w.I4(F9Round(f.ground_speed_mps() * 1e3));                  // 60 gSpeed
  w.I4(valid ? F9Round(f.course_deg() * 1e5) : 0);            // 64 headMot
  w.U4(valid ? F9RoundU(f.s_acc_mps * 1e3) : kF9UnknownAcc);  // 68 sAcc
  w.U4(F9RoundU(std::min(f.heading_acc_deg, 180.0) * 1e5));   // 72 headAcc
  w.U2(F9RoundU(std::min(f.pdop, 99.99) * 100));              // 76 pDOP
  const auto age = static_cast<std::uint16_t>(LastCorrectionAgeCode(e.correction_age_s) << 1);
  w.U2(static_cast<std::uint16_t>((pos ? 0 : 1) | age));  // 78 flags3: invalidLlh, lastCorrAge
  w.Zeros(4);                                             // 80 reserved0
  w.I4(0).I2(0).U2(0);                                    // 84 headVeh, 88 magDec, 90 magAcc
  return w.bytes();
}

std::vector<std::uint8_t> EncodeNavHpposllh(const F9Epoch& e) {
  const GnssFix& f = e.nav.fix;
  const bool pos = e.nav.position_known;
  const HighPrecision lon = SplitHp(pos ? f.lon_deg : 0, 1e-7, 1e-9);
  const HighPrecision lat = SplitHp(pos ? f.lat_deg : 0, 1e-7, 1e-9);
  const HighPrecision h = SplitHp(pos ? f.height_m : 0, 1e-3, 1e-4);
  const HighPrecision msl = SplitHp(pos ? f.height_m - f.geoid_separation_m : 0, 1e-3, 1e-4);
  Writer w;
  w.U1(0).Zeros(2).U1(pos ? 0 : 1).U4(F9Itow(e.nav));  // 0 version, 3 flags (invalidLlh), 4 iTOW
  w.I4(lon.coarse).I4(lat.coarse).I4(h.coarse).I4(msl.coarse);  // 8 lon, 12 lat, 16, 20
  w.I1(lon.fine).I1(lat.fine).I1(h.fine).I1(msl.fine);          // 24 lonHp … 27 hMSLHp
  w.U4(f.valid() ? F9RoundU(f.h_acc_m * 1e4) : kF9UnknownAcc);  // 28 hAcc (0.1 mm)
  w.U4(f.valid() ? F9RoundU(f.v_acc_m * 1e4) : kF9UnknownAcc);  // 32 vAcc
  return w.bytes();
}

std::vector<std::uint8_t> EncodeNavSat(const F9Epoch& e) {
  Writer w;
  const auto& sats = e.nav.sats;
  w.U4(F9Itow(e.nav)).U1(1).U1(sats.size()).Zeros(2);  // 0 iTOW, 4 version, 5 numSvs
  for (const SatelliteView& s : sats) {
    const bool rtcm = s.used && e.diff_soln && !s.sbas;
    std::uint32_t flags = static_cast<std::uint32_t>(std::clamp(s.quality, 0, 7));  // qualityInd
    if (s.used) flags |= 1U << 3;                                                   // svUsed
    flags |= 1U << 4;                                                               // health: ok
    if (rtcm) flags |= 1U << 6;                                                     // diffCorr
    if (s.orbit_known) flags |= (1U << 8) | (1U << 11);       // orbitSource ephemeris, ephAvail
    if (rtcm) flags |= (1U << 17) | (1U << 20) | (1U << 21);  // rtcmCorrUsed, prCorr, crCorr
    w.U1(s.sbas ? 1 : 0).U1(s.svid).U1(s.cno_dbhz);           // gnssId (0 GPS, 1 SBAS), svId, cno
    w.I1(s.orbit_known ? F9Round(s.elev_deg) : -91).I2(s.orbit_known ? F9Round(s.azim_deg) : 0);
    w.I2(s.used ? F9Round(s.pr_res_m * 10.0) : 0).U4(flags);  // prRes (0.1 m), flags
  }
  return w.bytes();
}

std::vector<std::uint8_t> EncodeNavRelposned(const F9Epoch& e) {
  const bool ok = e.relpos_valid && e.nav.fix.valid();
  const Eigen::Vector3d r = ok ? e.rel_pos_NED_m : Eigen::Vector3d::Zero();
  const double length_m = r.norm();
  const HighPrecision n = SplitHp(r.x(), 1e-2, 1e-4), east = SplitHp(r.y(), 1e-2, 1e-4);
  const HighPrecision d = SplitHp(r.z(), 1e-2, 1e-4), len = SplitHp(length_m, 1e-2, 1e-4);
  double heading_deg = std::atan2(r.y(), r.x()) * 180.0 / std::numbers::pi;
  if (heading_deg < 0) heading_deg += 360.0;
  const Eigen::Vector3d acc = ok ? e.rel_acc_NED_m : Eigen::Vector3d::Zero();
  Writer w;
  w.U1(1).U1(0).U2(e.ref_station_id).U4(F9Itow(e.nav));  // 0 version, 2 refStationId, 4 iTOW
  w.I4(n.coarse).I4(east.coarse).I4(d.coarse);           // 8 relPosN/E/D (cm)
  w.I4(len.coarse).I4(ok ? F9Round(heading_deg * 1e5) : 0).Zeros(4);  // 20 length, 24 heading
  w.I1(n.fine).I1(east.fine).I1(d.fine).I1(len.fine);                 // 32 HP parts (0.1 mm)
  w.U4(F9RoundU(acc.x() * 1e4))
      .U4(F9RoundU(acc.y() * 1e4))
      .U4(F9RoundU(acc.z() * 1e4));                           // 36 accNED
  w.U4(F9RoundU(acc.norm() * 1e4));                           // 48 accLength
  w.U4(ok ? F9RoundU(e.acc_heading_deg * 1e5) : 0).Zeros(4);  // 52 accHeading, 56 reserved
  w.U4(RelposFlags(e, ok));                                   // 60 flags

  return w.bytes();
}

std::vector<std::uint8_t> EncodeRxmRtcm(int msg_type, int ref_station, bool crc_failed, bool used) {
  Writer w;
  const unsigned msg_used = crc_failed ? 0U : used ? 2U : 1U;
  const auto flags = static_cast<std::uint8_t>((crc_failed ? 1U : 0U) | msg_used << 1);
  w.U1(2).U1(flags).U2(0).U2(ref_station).U2(msg_type);  // version, flags, subType, ref, type
  return w.bytes();
}

std::vector<std::uint8_t> EncodeF9MonVer() {
  return EncodeMonVer("EXT CORE 1.00 (61b2dd)", "00190000",
                      {"ROM BASE 0x118B2060", "FWVER=HPG 1.32", "PROTVER=27.31", "MOD=ZED-F9P",
                       "GPS;GLO;GAL;BDS", "SBAS;QZSS"});
}

}  // namespace hil::gnss::ubx

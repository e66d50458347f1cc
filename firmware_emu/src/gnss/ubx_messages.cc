#include "hil/firmware_emu/gnss/ubx_messages.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "hil/firmware_emu/gnss/geodesy.h"

namespace hil::gnss::ubx {
namespace {

constexpr std::uint32_t kUnknownAcc = 0xFFFFFFFFu;

std::int64_t Round(double v) { return static_cast<std::int64_t>(std::llround(v)); }
std::uint64_t RoundU(double v, std::uint64_t max = 0xFFFFFFFFu) {
  if (!(v >= 0)) return 0;
  return std::min<std::uint64_t>(static_cast<std::uint64_t>(std::llround(std::min(v, 4.0e9))), max);
}
std::uint64_t Dop(double d) { return RoundU(d * 100.0, 9999); }

// iTOW (ms) and fTOW (ns, −500000..500000) of the epoch.
std::uint32_t Itow(const NavEpoch& e) {
  return static_cast<std::uint32_t>((e.gps.tow_ns + 500000) / 1000000);
}
std::int64_t Ftow(const NavEpoch& e) {
  return e.gps.tow_ns - static_cast<std::int64_t>(Itow(e)) * 1000000;
}

std::uint8_t FixFlags(const NavEpoch& e) {
  std::uint8_t f = 0;
  if (e.fix.valid()) f |= 0x01;                        // gpsFixOk
  if (e.fix.valid() && e.sbas_corrections) f |= 0x02;  // diffSoln
  if (e.status.time_known) f |= 0x0C;                  // wknSet, towSet
  return f;
}

Eigen::Vector3d EcefPos(const NavEpoch& e) {
  if (!e.position_known) return Eigen::Vector3d::Zero();
  return EcefFromGeodetic(e.fix.lat_deg, e.fix.lon_deg, e.fix.height_m);
}
Eigen::Vector3d EcefVel(const NavEpoch& e) {
  if (!e.fix.valid()) return Eigen::Vector3d::Zero();
  const Eigen::Vector3d v_enu(e.fix.vel_e_mps, e.fix.vel_n_mps, -e.fix.vel_d_mps);
  return RotationEcefFromEnu(e.fix.lat_deg, e.fix.lon_deg) * v_enu;
}
std::uint64_t AccMm(const NavEpoch& e, double acc_m) {
  return e.fix.valid() ? RoundU(acc_m * 1000.0) : kUnknownAcc;
}
std::uint64_t AccCm(const NavEpoch& e, double acc_m) {
  return e.fix.valid() ? RoundU(acc_m * 100.0) : kUnknownAcc;
}

// NAV-SOL: ECEF position and velocity, fix type and flags.
void WriteNavSol(Writer& w, const NavEpoch& e) {
  const GnssFix& f = e.fix;
  const Eigen::Vector3d p = EcefPos(e) * 100.0, v = EcefVel(e) * 100.0;
  w.U4(Itow(e))
      .I4(Ftow(e))
      .I2(e.status.time_known ? e.gps.week : 0)
      .U1(static_cast<std::uint8_t>(f.fix_type))
      .U1(FixFlags(e));
  w.I4(Round(p.x())).I4(Round(p.y())).I4(Round(p.z())).U4(AccCm(e, f.p_acc_m));
  w.I4(Round(v.x())).I4(Round(v.y())).I4(Round(v.z())).U4(AccCm(e, f.s_acc_mps));
  w.U2(f.valid() ? Dop(f.pdop) : 9999)
      .U1(0)
      .U1(static_cast<std::uint64_t>(f.valid() ? f.num_sv : 0))
      .U4(0);
}

// NAV-VELNED: NED velocity, speed, ground speed and course.
void WriteNavVelNed(Writer& w, const NavEpoch& e) {
  const GnssFix& f = e.fix;
  const bool k = f.valid();
  const double gs = k ? f.ground_speed_mps() : 0.0;
  const double sp = k ? std::sqrt(gs * gs + f.vel_d_mps * f.vel_d_mps) : 0.0;
  w.U4(Itow(e))
      .I4(k ? Round(f.vel_n_mps * 100) : 0)
      .I4(k ? Round(f.vel_e_mps * 100) : 0)
      .I4(k ? Round(f.vel_d_mps * 100) : 0);
  w.U4(RoundU(sp * 100)).U4(RoundU(gs * 100)).I4(k ? Round(f.course_deg() * 1e5) : 0);
  w.U4(AccCm(e, f.s_acc_mps)).U4(k ? RoundU(f.heading_acc_deg * 1e5) : RoundU(180.0 * 1e5));
}

// NAV-TIMEUTC: the UTC date and time of the epoch.
void WriteNavTimeUtc(Writer& w, const NavEpoch& e) {
  const GnssFix& f = e.fix;
  const UtcTime u = UtcFrom(f.utc);
  const std::uint8_t valid = e.status.time_known ? (0x03 | (e.leap_known ? 0x04 : 0)) : 0;
  w.U4(Itow(e)).U4(RoundU(e.t_acc_ns)).I4(u.nanosecond).U2(static_cast<std::uint64_t>(u.year));
  w.U1(static_cast<std::uint64_t>(u.month))
      .U1(static_cast<std::uint64_t>(u.day))
      .U1(static_cast<std::uint64_t>(u.hour));
  w.U1(static_cast<std::uint64_t>(u.minute)).U1(static_cast<std::uint64_t>(u.second)).U1(valid);
}

// NAV-SVINFO: one block per satellite with a known orbit or tracked.
void WriteNavSvInfo(Writer& w, const NavEpoch& e) {
  const GnssFix& f = e.fix;
  std::vector<const SatelliteView*> list;
  for (const auto& s : e.sats) {
    if (s.orbit_known || s.tracked) list.push_back(&s);
  }
  w.U4(Itow(e)).U1(list.size()).U1(1 /* chipGen: u-blox 5 */).U2(0);
  for (const SatelliteView* s : list) {
    std::uint8_t flags = 0;
    if (s->used && f.valid()) flags |= 0x01;
    if (s->used && f.valid() && e.sbas_corrections) flags |= 0x02;
    if (s->orbit_known) flags |= 0x04;
    if (s->orbit_known && s->tracked) flags |= 0x08;
    w.U1(static_cast<std::uint64_t>(s->channel))
        .U1(static_cast<std::uint64_t>(s->svid))
        .U1(flags)
        .U1(static_cast<std::uint64_t>(s->quality));
    w.U1(static_cast<std::uint64_t>(s->cno_dbhz)).I1(s->orbit_known ? std::lround(s->elev_deg) : 0);
    w.I2(s->orbit_known ? std::lround(s->azim_deg) % 360 : 0).I4(Round(s->pr_res_m * 100));
  }
}

}  // namespace

std::string MessageName(std::uint8_t cls, std::uint8_t id) {
  struct Named {
    std::uint8_t cls, id;
    const char* name;
  };
  static constexpr Named kNames[] = {
      {kNav, kNavPosEcef, "NAV-POSECEF"},
      {kNav, kNavPosLlh, "NAV-POSLLH"},
      {kNav, kNavStatus, "NAV-STATUS"},
      {kNav, kNavDop, "NAV-DOP"},
      {kNav, kNavSol, "NAV-SOL"},
      {kNav, kNavVelEcef, "NAV-VELECEF"},
      {kNav, kNavVelNed, "NAV-VELNED"},
      {kNav, kNavTimeGps, "NAV-TIMEGPS"},
      {kNav, kNavTimeUtc, "NAV-TIMEUTC"},
      {kNav, kNavClock, "NAV-CLOCK"},
      {kNav, kNavSvInfo, "NAV-SVINFO"},
      {kMon, kMonVer, "MON-VER"},
      {kMon, kMonHw, "MON-HW"},
      {kAck, kAckAck, "ACK-ACK"},
      {kAck, kAckNak, "ACK-NAK"},
      {kCfg, 0x00, "CFG-PRT"},
      {kCfg, 0x01, "CFG-MSG"},
      {kCfg, 0x04, "CFG-RST"},
      {kCfg, 0x07, "CFG-TP"},
      {kCfg, 0x08, "CFG-RATE"},
      {kCfg, 0x09, "CFG-CFG"},
      {kCfg, 0x16, "CFG-SBAS"},
      {kCfg, 0x17, "CFG-NMEA"},
      {kCfg, 0x24, "CFG-NAV5"},
  };
  for (const Named& n : kNames) {
    if (n.cls == cls && n.id == id) return std::string("UBX-") + n.name;
  }
  char buf[24];
  std::snprintf(buf, sizeof buf, "UBX-%02X-%02X", cls, id);
  return buf;
}

std::vector<std::uint8_t> EncodeNav(std::uint8_t id, const NavEpoch& e) {
  const GnssFix& f = e.fix;
  Writer w;
  switch (id) {
    case kNavPosEcef: {  // len 20
      const Eigen::Vector3d p = EcefPos(e) * 100.0;
      w.U4(Itow(e)).I4(Round(p.x())).I4(Round(p.y())).I4(Round(p.z())).U4(AccCm(e, f.p_acc_m));
      break;
    }
    case kNavPosLlh: {  // len 28
      const bool k = e.position_known;
      w.U4(Itow(e)).I4(k ? Round(f.lon_deg * 1e7) : 0).I4(k ? Round(f.lat_deg * 1e7) : 0);
      w.I4(k ? Round(f.height_m * 1000.0) : 0)
          .I4(k ? Round((f.height_m - f.geoid_separation_m) * 1000.0) : 0);
      w.U4(AccMm(e, f.h_acc_m)).U4(AccMm(e, f.v_acc_m));
      break;
    }
    case kNavStatus:  // len 16
      w.U4(Itow(e))
          .U1(static_cast<std::uint8_t>(f.fix_type))
          .U1(FixFlags(e))
          .U1(e.sbas_corrections ? 1 : 0)
          .U1(0);
      w.U4(e.status.ttff_ms).U4(e.status.msss_ms);
      break;
    case kNavDop:  // len 18
      w.U4(Itow(e));
      if (f.valid())
        w.U2(Dop(f.gdop))
            .U2(Dop(f.pdop))
            .U2(Dop(f.tdop))
            .U2(Dop(f.vdop))
            .U2(Dop(f.hdop))
            .U2(Dop(f.ndop))
            .U2(Dop(f.edop));
      else
        for (int i = 0; i < 7; ++i) w.U2(9999);
      break;
    case kNavSol:  // len 52
      WriteNavSol(w, e);
      break;
    case kNavVelEcef: {  // len 20
      const Eigen::Vector3d v = EcefVel(e) * 100.0;
      w.U4(Itow(e)).I4(Round(v.x())).I4(Round(v.y())).I4(Round(v.z())).U4(AccCm(e, f.s_acc_mps));
      break;
    }
    case kNavVelNed:  // len 36
      WriteNavVelNed(w, e);
      break;
    case kNavTimeGps: {  // len 16
      const std::uint8_t valid = e.status.time_known ? (0x03 | (e.leap_known ? 0x04 : 0)) : 0;
      w.U4(Itow(e)).I4(Ftow(e)).I2(e.gps.week).I1(e.leap_s).U1(valid).U4(RoundU(e.t_acc_ns));
      break;
    }
    case kNavTimeUtc:  // len 20
      WriteNavTimeUtc(w, e);
      break;
    case kNavClock:  // len 20
      w.U4(Itow(e))
          .I4(Round(e.clk_bias_ns))
          .I4(Round(e.clk_drift_nsps))
          .U4(RoundU(e.t_acc_ns))
          .U4(RoundU(e.f_acc_psps));
      break;
    case kNavSvInfo:  // len 8 + 12·numCh
      WriteNavSvInfo(w, e);
      break;
    default:
      break;
  }
  return w.bytes();
}

std::vector<std::uint8_t> EncodeMonVer(const std::string& sw, const std::string& hw,
                                       const std::vector<std::string>& extensions) {
  Writer w;
  w.Chars(sw, 30).Chars(hw, 10);
  for (const auto& x : extensions) w.Chars(x, 30);
  return w.bytes();
}

std::vector<std::uint8_t> EncodeMonHw(std::uint32_t used_mask) {
  Writer w;
  w.U4(0x0000EFFF).U4(0).U4(0x00010000).U4(0x0001E7EF);  // pinSel, pinBank, pinDir, pinVal
  w.U2(76).U2(4096).U1(2).U1(1).U1(0x01).U1(
      0);  // noisePerMS, agcCnt, aStatus OK, aPower on, rtcCalib
  w.U4(used_mask);
  for (int i = 0; i < 25; ++i)
    w.U1(static_cast<std::uint64_t>(i < 17 ? i : 0xFF));  // VP: pin → peripheral map
  w.U1(0).U2(0);                                          // jamInd (reserved on u-blox 5), reserved
  w.U4(0).U4(0x0000FFFF).U4(0);                           // pinIrq, pullH, pullL
  return w.bytes();
}

std::string Ack(bool ok, std::uint8_t cls, std::uint8_t id) {
  Writer w;
  w.U1(cls).U1(id);
  return Frame(kAck, ok ? kAckAck : kAckNak, w);
}

}  // namespace hil::gnss::ubx

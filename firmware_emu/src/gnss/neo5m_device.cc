#include "hil/firmware_emu/gnss/neo5m_device.h"

#include <algorithm>
#include <cmath>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/nmea_encoder.h"
#include "hil/firmware_emu/gnss/nmea_sky_sentences.h"
#include "hil/firmware_emu/gnss/nmea_ublox_sentences.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss {
namespace {

constexpr std::int64_t kNsPerMs = 1000000;

// NMEA sentences in the order a u-blox 5 sends them within an epoch (class-0xF0 ids).
constexpr std::uint8_t kNmeaOrder[] = {0x04 /*RMC*/, 0x05 /*VTG*/, 0x00 /*GGA*/, 0x02 /*GSA*/,
                                       0x03 /*GSV*/, 0x01 /*GLL*/, 0x08 /*ZDA*/};

ReceiverProfile ProfileWithOverrides(const Neo5mConfig& c) {
  ReceiverProfile p = ProfileByName(c.profile);
  if (c.baud > 0) p.baud = c.baud;
  if (c.rate_hz > 0) p.rate_hz = c.rate_hz;
  if (c.model) p.model = *c.model;
  return p;
}

ubx::ReceiverSettings DefaultSettings(const ReceiverProfile& p) {
  return ubx::ReceiverSettings::Defaults(
      static_cast<std::uint32_t>(p.baud),
      static_cast<std::uint16_t>(std::lround(1000.0 / p.rate_hz)), p.nmea_rates);
}

// Deterministic pseudorange residual (m) of a used satellite at an epoch: a small smooth value.
double Residual(int svid, double gps_s) { return 0.6 * std::sin(gps_s / 23.0 + svid * 1.7); }

// What the scripted faults active at `t_s` do to the output; their effects on the sky and on the
// errors go into `cond` and `in`.
struct ActiveFaults {
  bool overload = false, data_gap = false;
};
ActiveFaults ApplyFaults(const std::vector<GnssFault>& faults, Time t, SkyConditions& cond,
                         ErrorInputs& in) {
  ActiveFaults active;
  for (const GnssFault& f : faults) {
    if (t < f.start || t >= f.end) continue;
    switch (f.kind) {
      case GnssFault::Kind::kOutage:
        cond.sky_blocked = true;
        break;
      case GnssFault::Kind::kObstruction:
        cond.blocked_below_deg = std::max(cond.blocked_below_deg, f.elevation_deg);
        break;
      case GnssFault::Kind::kStep:
        in.offset_N_m += f.offset_N_m;
        break;
      case GnssFault::Kind::kMultipath:
        in.multipath_sigma_m = std::hypot(in.multipath_sigma_m, f.sigma_m);
        break;
      case GnssFault::Kind::kOverload:
        active.overload = true;
        break;
      case GnssFault::Kind::kDataGap:
        active.data_gap = true;
        break;
    }
  }
  return active;
}

// The satellites as the fix leaves them: none used without a fix (the tracked ones flagged
// quality 4), the used ones with their pseudorange residuals.
void MarkSatellites(std::vector<SatelliteView>& sats, bool orbit_known, bool valid, double gps_s) {
  for (auto& s : sats) {
    s.orbit_known = orbit_known;
    if (!valid) {
      s.used = false;
      if (s.tracked) s.quality = 4;
    }
    if (s.used) s.pr_res_m = Residual(s.svid, gps_s);
  }
}

// Whether an SBAS satellite is tracked (its corrections can then be applied).
bool AnySbasTracked(const std::vector<SatelliteView>& sats) {
  return std::any_of(sats.begin(), sats.end(),
                     [](const SatelliteView& s) { return s.sbas && s.tracked; });
}

// The svids of the used satellites in the order of their channels (GSA's list).
std::vector<int> UsedInChannelOrder(const std::vector<SatelliteView>& sats) {
  std::vector<const SatelliteView*> by_channel;
  for (const auto& s : sats) {
    if (s.used) by_channel.push_back(&s);
  }
  std::sort(by_channel.begin(), by_channel.end(),
            [](auto* a, auto* b) { return a->channel < b->channel; });
  std::vector<int> svids;
  for (const auto* s : by_channel) svids.push_back(s->nmea_id());
  return svids;
}

}  // namespace

Neo5mDevice::Neo5mDevice(const Neo5mConfig& config, std::uint64_t seed)
    : config_(config),
      profile_(ProfileWithOverrides(config)),
      model_(profile_.model, seed, config.common_seed != 0 ? config.common_seed : seed + 1),
      constellation_(seed),
      fix_state_(profile_.fix_state),
      session_(DefaultSettings(profile_), profile_.cfg_rate_max_hz) {
  if (profile_.rate_hz > profile_.max_rate_hz) {
    throw std::invalid_argument("GNSS rate " + std::to_string(profile_.rate_hz) +
                                " Hz is above the " + profile_.name + " maximum of " +
                                std::to_string(profile_.max_rate_hz) + " Hz");
  }
  // receiver clock: a drift of a few hundred ns/s from the seed, the bias starting inside ±0.5 ms
  const std::uint64_t h = seed * 0x9E3779B97F4A7C15ULL;
  clk_drift_nsps_ = 150.0 + static_cast<double>((h >> 20) % 300);
  clk_bias_ns_ = static_cast<double>((h >> 40) % 1000000) - 500000.0;
  next_epoch_ = NextGridEpoch(TimeFromNs(-1));
  fix_state_.Restart(Time{}, config_.start);
  if (config_.rtk_rough) rtk_.emplace(*config_.rtk_rough, seed ^ 0x52544B524F554748ULL);
}

void Neo5mDevice::ShadeSky(SkyConditions& cond, const Eigen::Vector3d& p_NA_N_m) const {
  if (!config_.shading.active()) return;
  cond.shade = [this, p_NA_N_m](SatelliteView& s, double& cno_dbhz) {
    const SignalEffect fx = ShadeSignal(config_.shading, p_NA_N_m, s.azim_deg, s.elev_deg);
    cno_dbhz += fx.cno_change_db;
    s.code_multipath_m = fx.code_error_m;
    s.carrier_multipath_m = fx.carrier_error_m;
    s.nlos = fx.nlos;
  };
  cond.track_min_dbhz = config_.shading.track_min_dbhz;
  cond.nav_min_dbhz = config_.shading.nav_min_dbhz;
}

bool Neo5mDevice::RtkFloat(Time t, double dt_s, bool valid, const NavEpoch& e, ErrorInputs& in) {
  if (valid && !had_fix_last_) t_fix_since_ = t;
  had_fix_last_ = valid;
  if (rtk_) {
    last_rtk_ = rtk_->Step(t, dt_s, valid, e.sats);
    in.offset_N_m += last_rtk_.error_N_m;
    in.extra_h_acc_m = std::hypot(in.extra_h_acc_m, last_rtk_.sigma_h_m);
    in.extra_v_acc_m = std::hypot(in.extra_v_acc_m, last_rtk_.sigma_v_m);
    return valid && last_rtk_.state == RtkState::kFloat;
  }
  // the profile's timer: float for rtk_fixed_after_s after each (re)acquisition
  const bool rtk_float =
      profile_.rtk && valid && t - t_fix_since_ < DurationFromSeconds(profile_.rtk_fixed_after_s);
  if (rtk_float)
    in.multipath_sigma_m = std::hypot(in.multipath_sigma_m, profile_.rtk_float_sigma_m);
  return rtk_float;
}

void Neo5mDevice::ApplyMultipath(NavEpoch& e, const Dops& dops, ErrorInputs& in) const {
  if (!config_.shading.active()) return;
  // a standalone fix ranges with the code; an RTK solution with the carrier of the satellites in
  // line of sight (an NLOS carrier holds no fixable ambiguity: the engine drops it)
  std::vector<double> err(e.sats.size(), 0.0);
  for (std::size_t i = 0; i < e.sats.size(); ++i) {
    const SatelliteView& s = e.sats[i];
    err[i] = !profile_.rtk ? s.code_multipath_m : s.nlos ? 0.0 : s.carrier_multipath_m;
  }
  const RangeErrorSolution sol = SolveRangeErrors(e.sats, err);
  if (!sol.valid) return;
  in.offset_N_m += sol.dp_N_m;
  for (std::size_t i = 0; i < e.sats.size(); ++i) {
    if (e.sats[i].used) e.sats[i].pr_res_m += sol.residual_m[i];
  }
  in.extra_h_acc_m = std::hypot(in.extra_h_acc_m, sol.sigma_m * dops.hdop);
  if (dops.vdop < 99) in.extra_v_acc_m = std::hypot(in.extra_v_acc_m, sol.sigma_m * dops.vdop);
}

int Neo5mDevice::baud(int) const {
  return static_cast<int>(session_.current().ports[ubx::kUart1].baud);
}

Duration Neo5mDevice::Period() const {
  return Duration{static_cast<std::int64_t>(session_.current().meas_rate_ms) * kNsPerMs};
}

Time Neo5mDevice::NextGridEpoch(Time after) const {
  // epochs sit on the UTC grid of the measurement period (whole seconds at 1 Hz)
  return hil::NextGridEpoch(after, Period(), config_.start_utc);
}

bool Neo5mDevice::OutputEnabled(std::uint16_t proto) const {
  return (session_.current().ports[ubx::kUart1].out_mask & proto) != 0;
}

void Neo5mDevice::Push(DeviceOutput& out, Time t, std::string bytes, std::string name,
                       bool reply) const {
  SerialMessage m{t, 0, std::move(bytes), std::move(name)};
  m.reply = reply;
  out.serial.push_back(std::move(m));
}

void Neo5mDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  const double dt_s = first_epoch_ ? 0.0 : ToSeconds(t - last_epoch_time_);
  first_epoch_ = false;
  last_epoch_time_ = t;
  next_epoch_ = NextGridEpoch(t);
  if (stopped_) return;

  const ubx::ReceiverSettings& cfg = session_.current();
  NavEpoch e;
  const UnixTime utc = UtcAt(config_.start_utc, t);
  e.gps = GpsFrom(utc);
  e.leap_s = LeapSecondsAt(utc);

  // the sky, limited by the settings and the scripted faults
  SkyConditions cond;
  cond.elevation_mask_deg = cfg.min_elevation_deg();
  cond.sbas_enabled = cfg.sbas_enabled();
  cond.max_sbas = cfg.sbas[2];
  ErrorInputs in;
  const ActiveFaults active = ApplyFaults(config_.faults, t, cond, in);
  overload_ = active.overload;
  const bool data_gap = active.data_gap;
  const double gps_s = static_cast<double>(e.gps.week) * 604800.0 + e.gps.tow_s();
  ShadeSky(cond, truth.p_NB_N_m + truth.q_NB * profile_.model.p_BA_B_m);
  e.sats = constellation_.Sky(gps_s, truth.lat_deg, truth.lon_deg, truth.height_m, cond);
  int usable = 0;
  for (const auto& s : e.sats) usable += s.used ? 1 : 0;
  e.status = fix_state_.Step(t, usable, cfg.fix_mode());
  const bool valid = e.status.fix_type != FixType::kNoFix;
  MarkSatellites(e.sats, e.status.orbit_known, valid, gps_s);
  const Dops dops = ComputeDops(e.sats);

  // the solution (the error processes advance every epoch, with or without a fix)
  if (dops.valid) {
    in.h_scale = std::clamp(dops.hdop / profile_.model.hdop_ref, 0.5, 20.0);
    in.v_scale =
        dops.vdop < 99 ? std::clamp(dops.vdop / profile_.model.vdop_ref, 0.5, 20.0) : in.h_scale;
  }
  if (valid) ApplyMultipath(e, dops, in);
  const bool rtk_float = RtkFloat(t, dt_s, valid, e, in);
  GnssFix fix = model_.Calc(truth, utc, dt_s, in);
  fix.fix_type = e.status.fix_type;
  e.sbas_corrections =
      config_.sbas_corrections && cfg.sbas_used_for_corrections() && AnySbasTracked(e.sats);
  if (profile_.rtk)
    fix.quality = rtk_float ? FixQuality::kRtkFloat : FixQuality::kRtkFixed;
  else
    fix.quality = e.sbas_corrections ? FixQuality::kDgps : FixQuality::kGps;
  if (!valid) fix.quality = FixQuality::kInvalid;
  fix.num_sv = valid ? usable : 0;
  fix.gdop = dops.gdop, fix.pdop = dops.pdop, fix.tdop = dops.tdop, fix.vdop = dops.vdop;
  fix.hdop = dops.hdop, fix.ndop = dops.ndop, fix.edop = dops.edop;
  if (valid) position_known_ = true;
  e.position_known = position_known_;
  if (!valid && position_known_) {
    // without a fix the receiver keeps reporting its last solution, flagged invalid
    const GnssFix& last = last_epoch_.fix;
    fix.lat_deg = last.lat_deg, fix.lon_deg = last.lon_deg, fix.height_m = last.height_m;
  }
  e.fix = fix;
  e.used_in_channel_order = UsedInChannelOrder(e.sats);

  // receiver clock
  clk_bias_ns_ += clk_drift_nsps_ * dt_s;
  if (clk_bias_ns_ > 500000.0)
    clk_bias_ns_ -= 1000000.0;  // 1 ms clock steps, as u-blox receivers make
  e.clk_bias_ns = clk_bias_ns_;
  e.clk_drift_nsps = clk_drift_nsps_;
  e.leap_known = valid || fix_state_.start_kind() != StartKind::kCold;
  e.t_acc_ns = valid ? 20.0 + 15.0 * fix.tdop : 1.0e6;
  e.f_acc_psps = valid ? 500.0 : 1.0e5;
  last_epoch_ = e;
  ++epoch_count_;
  if (!data_gap) EmitEpoch(t + config_.output_lag, out);
}

void Neo5mDevice::EmitEpoch(Time t_ready, DeviceOutput& out) {
  const ubx::ReceiverSettings& cfg = session_.current();
  const NavEpoch& e = last_epoch_;
  if (overload_) ++overloaded_epochs_;
  const auto due = [&](std::uint8_t cls, std::uint8_t id) {
    if (overload_) return true;  // everything, every epoch
    const int r = cfg.Rate(cls, id);
    return r > 0 && (epoch_count_ - 1) % static_cast<std::uint64_t>(r) == 0;
  };
  if (banner_pending_ && OutputEnabled(ubx::kProtoNmea)) {
    for (const auto& line : profile_.banner) Push(out, t_ready, nmea::EncodeTxt(line), "NMEA-TXT");
  }
  banner_pending_ = false;
  if (OutputEnabled(ubx::kProtoUbx)) {
    for (std::uint8_t id : ubx::kNavOutputOrder) {
      if (due(ubx::kNav, id))
        Push(out, t_ready, ubx::Frame(ubx::kNav, id, ubx::EncodeNav(id, e)),
             ubx::MessageName(ubx::kNav, id));
    }
    if (due(ubx::kMon, ubx::kMonHw)) {
      Push(out, t_ready, ubx::Frame(ubx::kMon, ubx::kMonHw, ubx::EncodeMonHw(0x0001FFFF)),
           "UBX-MON-HW");
    }
  }
  if (!OutputEnabled(ubx::kProtoNmea)) return;
  nmea::NmeaFormat fmt = profile_.format;
  fmt.mode_indicator = cfg.nmea_v23();
  const bool tk = e.status.time_known;
  for (std::uint8_t id : kNmeaOrder) {
    if (!due(ubx::kNmeaStd, id)) continue;
    switch (id) {
      case 0x04:
        Push(out, t_ready, nmea::EncodeRmc(e.fix, tk, fmt), "NMEA-RMC");
        break;
      case 0x05:
        Push(out, t_ready, nmea::EncodeVtg(e.fix, fmt), "NMEA-VTG");
        break;
      case 0x00:
        Push(out, t_ready, nmea::EncodeGga(e.fix, tk, fmt), "NMEA-GGA");
        break;
      case 0x02:
        Push(out, t_ready, nmea::EncodeGsa(e), "NMEA-GSA");
        break;
      case 0x03:
        for (auto& s : nmea::EncodeGsv(e, cfg.nmea_num_sv()))
          Push(out, t_ready, std::move(s), "NMEA-GSV");
        break;
      case 0x01:
        Push(out, t_ready, nmea::EncodeGll(e.fix, tk, fmt), "NMEA-GLL");
        break;
      case 0x08:
        Push(out, t_ready, nmea::EncodeZda(e.fix, tk), "NMEA-ZDA");
        break;
      default:
        break;
    }
  }
  if (due(ubx::kNmeaPubx, 0x00)) Push(out, t_ready, nmea::EncodePubx00(e), "NMEA-PUBX00");
  if (due(ubx::kNmeaPubx, 0x04)) Push(out, t_ready, nmea::EncodePubx04(e), "NMEA-PUBX04");
}

void Neo5mDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  if (port != 0) return;
  // the bytes come over the line at the port's baud, after what the host wrote before: a
  // message is whole when its last byte's stop bit has arrived (10 bit times a byte, 8N1)
  Time t_byte_end = std::max(t, rx_line_free_);
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    t_byte_end += Duration{(1000000000LL * 10 + baud(0) / 2) / baud(0)};
    for (const ubx::InputMessage& m : parser_.Feed(bytes.substr(k, 1))) {
      if (m.kind == ubx::InputMessage::Kind::kUbx)
        HandleUbx(m, t_byte_end, out);
      else
        HandleNmea(m, t_byte_end, out);
    }
  }
  rx_line_free_ = t_byte_end;
}

void Neo5mDevice::HandleUbx(const ubx::InputMessage& m, Time t, DeviceOutput& out) {
  if ((session_.current().ports[ubx::kUart1].in_mask & ubx::kProtoUbx) == 0) return;
  const Time t_reply = t + config_.response_delay;
  std::vector<ubx::Reply> replies;
  if (m.cls == ubx::kCfg) {
    const std::uint16_t period_before = session_.current().meas_rate_ms;
    ubx::CfgEffects fx;
    replies = session_.Handle(m.id, m.payload, ubx::kUart1, fx);
    if (session_.current().meas_rate_ms != period_before)
      next_epoch_ = NextGridEpoch(last_epoch_time_);
    if (fx.gps_stop) stopped_ = true;
    if (fx.gps_start && stopped_) {
      stopped_ = false;
      fix_state_.Restart(t, StartKind::kHot);
    }
    if (fx.restart) {
      if (fx.hardware_reset) {
        session_.LoadSaved();
        banner_pending_ = true;
        epoch_count_ = 0;
        next_epoch_ = NextGridEpoch(last_epoch_time_);
      }
      stopped_ = false;
      fix_state_.Restart(t, *fx.restart);
      if (*fx.restart == StartKind::kCold) position_known_ = false;
    }
  } else if (m.payload.empty() && m.cls == ubx::kNav) {
    auto p = ubx::EncodeNav(m.id, last_epoch_);
    if (!p.empty()) replies.push_back({ubx::Frame(m.cls, m.id, p), ubx::MessageName(m.cls, m.id)});
  } else if (m.payload.empty() && m.cls == ubx::kMon && m.id == ubx::kMonVer) {
    replies.push_back({ubx::Frame(m.cls, m.id,
                                  ubx::EncodeMonVer(profile_.sw_version, profile_.hw_version,
                                                    profile_.version_extensions)),
                       "UBX-MON-VER"});
  } else if (m.payload.empty() && m.cls == ubx::kMon && m.id == ubx::kMonHw) {
    replies.push_back({ubx::Frame(m.cls, m.id, ubx::EncodeMonHw(0x0001FFFF)), "UBX-MON-HW"});
  }
  if (!OutputEnabled(ubx::kProtoUbx)) return;
  for (auto& r : replies) Push(out, t_reply, std::move(r.bytes), std::move(r.name), true);
}

void Neo5mDevice::HandleNmea(const ubx::InputMessage& m, Time t, DeviceOutput& out) {
  if ((session_.current().ports[ubx::kUart1].in_mask & ubx::kProtoNmea) == 0) return;
  const std::string& s = m.sentence;
  if (s.rfind("PUBX,40,", 0) == 0 || s.rfind("PUBX,41,", 0) == 0) {
    session_.HandlePubxSet(s);
    return;
  }
  if (!OutputEnabled(ubx::kProtoNmea)) return;
  const Time t_reply = t + config_.response_delay;
  if (s == "PUBX,00")
    Push(out, t_reply, nmea::EncodePubx00(last_epoch_), "NMEA-PUBX00", true);
  else if (s == "PUBX,04")
    Push(out, t_reply, nmea::EncodePubx04(last_epoch_), "NMEA-PUBX04", true);
}

}  // namespace hil::gnss

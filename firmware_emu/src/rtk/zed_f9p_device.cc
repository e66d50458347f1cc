#include "hil/firmware_emu/rtk/zed_f9p_device.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "hil/firmware_emu/gnss/geodesy.h"
#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/nmea_f9_sentences.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;
using gnss::ubx::CarrSoln;

constexpr double kF9CepPerSigma = 1.1774;
constexpr double kDataSheetCep_m = 1.5;  // ZED-F9P data sheet: standalone horizontal CEP

double F9Residual(int svid, double gps_s) { return 0.3 * std::sin(gps_s / 23.0 + svid * 1.7); }

// Moves a geodetic position by a small ENU offset (metres; the local radii of curvature).
void Shift(gnss::GnssFix& f, const Eigen::Vector3d& d_N_m) {
  const double lat = f.lat_deg * std::numbers::pi / 180.0;
  const double s2 = std::sin(lat) * std::sin(lat);
  const double w = std::sqrt(1.0 - gnss::kWgs84E2 * s2);
  const double n_m = gnss::kWgs84A_m / w + f.height_m;
  const double m_m = gnss::kWgs84A_m * (1.0 - gnss::kWgs84E2) / (w * w * w) + f.height_m;
  f.lat_deg += d_N_m.y() / m_m * 180.0 / std::numbers::pi;
  f.lon_deg += d_N_m.x() / (n_m * std::cos(lat)) * 180.0 / std::numbers::pi;
  f.height_m += d_N_m.z();
}

// Without a fix no satellite is used (the tracked ones flagged quality 4); the used svids in the
// order of their channels (GSA's list), as the NEO-5M's receiver does.
void MarkUsed(gnss::NavEpoch& e, bool valid) {
  std::vector<const gnss::SatelliteView*> used;
  for (auto& s : e.sats) {
    if (!valid) {
      s.used = false;
      if (s.tracked) s.quality = 4;
    }
    if (s.used) used.push_back(&s);
  }
  std::sort(used.begin(), used.end(), [](auto* a, auto* b) { return a->channel < b->channel; });
  e.used_in_channel_order.clear();
  for (const auto* s : used) e.used_in_channel_order.push_back(s->nmea_id());
}

// The rover's observation model with the atmosphere of its radio base (common to both sites).
BaseObservablesConfig RawConfig(const ZedF9pConfig& c) {
  BaseObservablesConfig raw = c.raw;
  if (c.radio_base) {
    raw.zenith_tropo_m = c.radio_base->observables.zenith_tropo_m;
    raw.vertical_iono_l1_m = c.radio_base->observables.vertical_iono_l1_m;
    raw.iono_shell_height_m = c.radio_base->observables.iono_shell_height_m;
  }
  return raw;
}

}  // namespace

CarrSoln CarrSolnOf(gnss::RtkState s) {
  return s == gnss::RtkState::kFixed   ? CarrSoln::kFixed
         : s == gnss::RtkState::kFloat ? CarrSoln::kFloat
                                       : CarrSoln::kNone;
}

gnss::ReceiverModelConfig F9pStandaloneModel() {
  gnss::ReceiverModelConfig m;
  m.horizontal_sigma_m = kDataSheetCep_m / kF9CepPerSigma;
  m.vertical_sigma_m = 1.6 * m.horizontal_sigma_m;
  return m;
}

ZedF9pDevice::ZedF9pDevice(const ZedF9pConfig& config, std::uint64_t seed)
    : config_(config),
      model_(config.model, seed, seed + 1),
      constellation_(seed),
      fix_state_(gnss::FixStateConfig{}),
      rtk_(config.rtk, seed),
      raw_obs_(RawConfig(config), 0, 0, 0, seed ^ 0x52415758ULL) {
  std::vector<std::uint8_t> valset{0, 4, 0, 0};  // the saved configuration, into Flash
  for (const auto& [id, value] : config_.flash) {
    for (int k = 0; k < 4; ++k) valset.push_back(static_cast<std::uint8_t>(id >> (8 * k)));
    const std::size_t n = gnss::ubx::F9ValueBytes(id);
    for (std::size_t k = 0; k < n; ++k)
      valset.push_back(static_cast<std::uint8_t>(value >> (8 * k)));
  }
  if (!config_.flash.empty() &&
      db_.Handle(gnss::ubx::kCfgValset, valset).back().name != "UBX-ACK-ACK")
    throw std::invalid_argument("zed_f9p: the saved configuration holds an unknown key or value");
  db_.LoadStored();
  if (config_.radio_base && config_.moving_base)
    throw std::invalid_argument("zed_f9p: a radio base and a moving base both on UART2");
  if (config_.radio_base)
    radio_base_ = std::make_unique<RtkBaseDevice>(*config_.radio_base, config_.radio_base_seed);
  if (config_.moving_base) {
    moving_base_ = std::make_unique<MovingBase>(*config_.moving_base, config_.start_utc,
                                                seed ^ 0x4D4F56494E47ULL);
  }
  next_epoch_ = NextGridEpoch(TimeFromNs(-1));
  fix_state_.Restart(Time{}, config_.start);
}

Duration ZedF9pDevice::Period() const {
  return std::chrono::milliseconds(db_.Get(key::kRateMeas) *
                                   std::max<std::uint64_t>(1, db_.Get(key::kRateNav)));
}

Time ZedF9pDevice::NextGridEpoch(Time after) const {
  return hil::NextGridEpoch(after, Period(), config_.start_utc);
}

Time ZedF9pDevice::next_event_time() const {
  Time t = next_epoch_;
  if (radio_base_) t = std::min(t, radio_base_->next_event_time());
  if (!pending_.empty()) t = std::min(t, pending_.front().t);
  return t;
}

int ZedF9pDevice::baud(int) const { return static_cast<int>(db_.Get(key::kUart1Baudrate)); }

void ZedF9pDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  while (!pending_.empty() && pending_.front().t <= t) {
    const PendingFrame f = pending_.front();
    pending_.pop_front();
    Receive(f.t, f, out);
  }
  if (t >= next_epoch_) RunNavEpoch(truth, out);
  if (radio_base_ && t >= radio_base_->next_event_time()) RadioEpoch(t);
}

void ZedF9pDevice::RunNavEpoch(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  const double dt_s = first_epoch_ ? 0.0 : ToSeconds(t - last_epoch_time_);
  first_epoch_ = false;
  last_epoch_time_ = t;
  next_epoch_ = NextGridEpoch(t);
  if (moving_base_) MovingBaseEpoch(truth);
  gnss::NavEpoch& e = last_.nav;
  const UnixTime utc = UtcAt(config_.start_utc, t);
  e.gps = gnss::GpsFrom(utc);
  e.leap_s = gnss::LeapSecondsAt(utc);
  const double gps_s = static_cast<double>(e.gps.week) * 604800.0 + e.gps.tow_s();
  gnss::SkyConditions sky;
  for (const auto& [start, end] : config_.sky_outages) sky.sky_blocked |= t >= start && t < end;
  e.sats = constellation_.Sky(gps_s, truth.lat_deg, truth.lon_deg, truth.height_m, sky);
  int usable = 0;
  for (auto& s : e.sats) {
    usable += s.used ? 1 : 0;
    if (s.used) s.pr_res_m = F9Residual(s.svid, gps_s);
  }
  e.status = fix_state_.Step(t, usable);
  const bool valid = e.status.fix_type != gnss::FixType::kNoFix;
  MarkUsed(e, valid);
  const gnss::Dops dops = gnss::ComputeDops(e.sats);
  gnss::ErrorInputs in;
  if (dops.valid) {
    in.h_scale = std::clamp(dops.hdop / config_.model.hdop_ref, 0.5, 20.0);
    in.v_scale =
        dops.vdop < 99 ? std::clamp(dops.vdop / config_.model.vdop_ref, 0.5, 20.0) : in.h_scale;
  }
  gnss::GnssFix fix = model_.Calc(truth, utc, dt_s, in);
  fix.fix_type = e.status.fix_type;
  fix.num_sv = valid ? usable : 0;
  fix.gdop = dops.gdop, fix.pdop = dops.pdop, fix.tdop = dops.tdop, fix.vdop = dops.vdop;
  fix.hdop = dops.hdop, fix.ndop = dops.ndop, fix.edop = dops.edop;
  if (moving_base_)
    ApplyMovingBase(truth, dt_s, fix);
  else
    ApplyRtk(t, dt_s, fix);
  if (valid) position_known_ = true;
  e.position_known = position_known_;
  if (!valid && position_known_)
    fix.lat_deg = e.fix.lat_deg, fix.lon_deg = e.fix.lon_deg, fix.height_m = e.fix.height_m;
  e.fix = fix;
  e.leap_known = true;
  e.t_acc_ns = valid ? 20.0 + 15.0 * fix.tdop : 1.0e6;
  if (!moving_base_) FillRelPos();
  ++epoch_count_;
  ++stats_.epochs;
  if (Enabled(key::kUart1OutUbx) && Due(key::kRxmRawxUart1))
    ObserveRaw(truth, e.gps, sky.sky_blocked);
  EmitEpoch(t + config_.output_lag, out);
}

void ZedF9pDevice::ApplyRtk(Time t, double dt_s, gnss::GnssFix& fix) {
  const bool valid3d = fix.fix_type == gnss::FixType::k3D;
  double baseline_m = 0;
  if (station_) {
    baseline_m =
        (gnss::EcefFromGeodetic(fix.lat_deg, fix.lon_deg, fix.height_m) - station_->arp_E_m).norm();
  }
  rtk_.config().dgnss_timeout_s = static_cast<double>(db_.Get(key::kNavspgConstrDgnssTo));
  rtk_.config().fixed_allowed = db_.Get(key::kNavhpgDgnssMode) == 3;
  const RoverRtkEpoch r = rtk_.Step(t, dt_s, valid3d, baseline_m, last_.nav.sats);
  const CarrSoln carr = CarrSolnOf(r.state);
  last_.carr_soln = carr;
  last_.diff_soln = carr != CarrSoln::kNone;
  last_.correction_age_s = last_.diff_soln ? r.correction_age_s : -1.0;
  if (timeline_.empty() || timeline_.back().carr_soln != carr)
    timeline_.push_back({t, carr, r.correction_age_s});
  fix.quality = !fix.valid() ? gnss::FixQuality::kInvalid : gnss::FixQuality::kGps;
  if (carr == CarrSoln::kNone) return;
  // the RTK solution replaces the standalone error by its own
  Shift(fix, r.error_N_m - model_.position_error_N_m());
  fix.h_acc_m = std::numbers::sqrt2 * r.sigma_h_m;
  fix.v_acc_m = r.sigma_v_m;
  fix.p_acc_m = std::hypot(fix.h_acc_m, fix.v_acc_m);
  fix.quality =
      carr == CarrSoln::kFixed ? gnss::FixQuality::kRtkFixed : gnss::FixQuality::kRtkFloat;
  ++(carr == CarrSoln::kFixed ? stats_.epochs_fixed : stats_.epochs_float);
  stats_.epochs_wrong_fix += r.wrong_fix ? 1 : 0;
}

void ZedF9pDevice::FillRelPos() {
  const gnss::GnssFix& f = last_.nav.fix;
  last_.rel_carr_soln = last_.carr_soln;
  last_.rel_diff_soln = last_.diff_soln;
  last_.ref_pos_miss = !station_;
  last_.relpos_valid = station_.has_value() && last_.diff_soln;
  last_.ref_obs_miss = station_.has_value() && !last_.diff_soln;
  if (!station_) return;
  last_.ref_station_id = station_->station_id;
  const Eigen::Vector3d d_E =
      gnss::EcefFromGeodetic(f.lat_deg, f.lon_deg, f.height_m) - station_->arp_E_m;
  const Eigen::Vector3d b = station_->arp_E_m;
  const double lat = std::atan2(b.z(), std::hypot(b.x(), b.y())) * 180.0 / std::numbers::pi;
  const double lon = std::atan2(b.y(), b.x()) * 180.0 / std::numbers::pi;
  const Eigen::Vector3d enu = gnss::RotationEcefFromEnu(lat, lon).transpose() * d_E;
  last_.rel_pos_NED_m = Eigen::Vector3d(enu.y(), enu.x(), -enu.z());
  const double h = f.h_acc_m / std::numbers::sqrt2;
  last_.rel_acc_NED_m = Eigen::Vector3d(h, h, f.v_acc_m);
}

void ZedF9pDevice::Push(DeviceOutput& out, Time t, std::string bytes, std::string name,
                        bool reply) {
  t = std::max(t, last_ready_);
  last_ready_ = t;
  SerialMessage m{t, 0, std::move(bytes), std::move(name)};
  m.reply = reply;
  out.serial.push_back(std::move(m));
}

bool ZedF9pDevice::Due(std::uint32_t k) const {
  const std::uint64_t rate = db_.Get(k);  // per navigation epoch
  return rate > 0 && (epoch_count_ - 1) % rate == 0;
}

void ZedF9pDevice::EmitEpoch(Time t_ready, DeviceOutput& out) {
  using gnss::ubx::Frame;
  namespace ubx = gnss::ubx;
  if (Enabled(key::kUart1OutUbx)) {
    if (Due(key::kRxmRawxUart1))
      Push(out, t_ready, Frame(ubx::kRxm, ubx::kRxmRawx, ubx::EncodeRxmRawx(rawx_)),
           "UBX-RXM-RAWX");
    if (Due(key::kNavPvtUart1))
      Push(out, t_ready, Frame(ubx::kNav, ubx::kNavPvt, ubx::EncodeNavPvt(last_)), "UBX-NAV-PVT");
    if (Due(key::kNavHpposllhUart1))
      Push(out, t_ready, Frame(ubx::kNav, ubx::kNavHpposllh, ubx::EncodeNavHpposllh(last_)),
           "UBX-NAV-HPPOSLLH");
    if (Due(key::kNavRelposnedUart1))
      Push(out, t_ready, Frame(ubx::kNav, ubx::kNavRelposned, ubx::EncodeNavRelposned(last_)),
           "UBX-NAV-RELPOSNED");
    if (Due(key::kNavSatUart1))
      Push(out, t_ready, Frame(ubx::kNav, ubx::kNavSat, ubx::EncodeNavSat(last_)), "UBX-NAV-SAT");
  }
  if (Enabled(key::kUart1OutNmea)) EmitNmea(t_ready, out);
}

void ZedF9pDevice::EmitNmea(Time t_ready, DeviceOutput& out) {
  // the u-blox order of the default set: RMC, VTG, GGA, GSA, GSV, GLL (ours by the NEO-5M's)
  const gnss::GnssFix& f = last_.nav.fix;
  const bool tk = last_.nav.status.time_known;
  const auto due = [this](std::uint32_t k) { return Due(k); };
  if (due(key::kNmeaRmcUart1)) Push(out, t_ready, gnss::nmea::EncodeF9Rmc(f, tk), "NMEA-RMC");
  if (due(key::kNmeaVtgUart1)) Push(out, t_ready, gnss::nmea::EncodeF9Vtg(f), "NMEA-VTG");
  if (due(key::kNmeaGgaUart1)) {
    const int station = station_ ? station_->station_id : 0;
    Push(out, t_ready, gnss::nmea::EncodeF9Gga(f, tk, last_.correction_age_s, station), "NMEA-GGA");
  }
  if (due(key::kNmeaGsaUart1)) Push(out, t_ready, gnss::nmea::EncodeF9Gsa(last_.nav), "NMEA-GSA");
  if (due(key::kNmeaGsvUart1)) {
    for (auto& s : gnss::nmea::EncodeF9Gsv(last_.nav)) Push(out, t_ready, std::move(s), "NMEA-GSV");
  }
  if (due(key::kNmeaGllUart1)) Push(out, t_ready, gnss::nmea::EncodeF9Gll(f, tk), "NMEA-GLL");
}

}  // namespace hil::rtk

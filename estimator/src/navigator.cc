#include "hil/estimator/navigator.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace hil::estimator {

namespace {

/// An IMU interval's length in whole nanoseconds (truncated).
Nanoseconds IntervalNs(double dt_s) { return Nanoseconds{static_cast<std::int64_t>(dt_s * 1e9)}; }

ImuSample ScaledPart(const ImuSample& s, GpsTime t_end, double fraction) {
  ImuSample p = s;
  p.t = t_end;
  p.dt_s = s.dt_s * fraction;
  p.delta_angle_B_rad = s.delta_angle_B_rad * fraction;
  p.delta_velocity_B_mps = s.delta_velocity_B_mps * fraction;
  return p;
}
}  // namespace

const char* NavModeName(NavMode m) {
  switch (m) {
    case NavMode::kEkf:
      return "ekf";
    case NavMode::kPlanar2d:
      return "planar2d";
    case NavMode::kGnssOnly:
      return "gnss_only";
    case NavMode::kImuOnly:
      return "imu_only";
    case NavMode::kMultiGnss:
      return "multi_gnss";
  }
  return "?";
}

std::optional<NavMode> NavModeFromName(const char* name) {
  for (NavMode m : {NavMode::kEkf, NavMode::kPlanar2d, NavMode::kGnssOnly, NavMode::kImuOnly,
                    NavMode::kMultiGnss}) {
    if (std::strcmp(name, NavModeName(m)) == 0) return m;
  }
  return std::nullopt;
}

Navigator::Navigator(const NavigatorParams& params)
    : params_(params),
      planar_(params.planar),
      stationary_(params.stationary, params.ekf.accel_noise_mps2_rthz,
                  params.ekf.gyro_noise_radps_rthz),
      vibration_(params.mode == NavMode::kEkf ? params.vibration_tau_s : 0.0,
                 params.vibration_mean_tau_s),
      accel_scatter_(params.mode == NavMode::kEkf ? params.accel_scatter_tau_s : 0.0,
                     params.accel_scatter_max_rate_hz),
      step_(params.robust.step),
      imu_lag_(params.imu_lag),
      rtk_check_(params.rtk_fix),
      rtk_frames_(params.rtk_fix.same_frame_nis),
      imu_check_(params.imu_usability, params.ekf.accel_noise_mps2_rthz,
                 params.ekf.accel_bias_rw_mps3_rthz),
      fallback_(FallbackVehicleParams(params)),
      vel_noise_(params.gnss_vel_noise) {
  imu_lag_.SetLeverArm(params.ekf.lever_arm_B_m.x(), params.ekf.lever_arm_B_m.y());
}

void Navigator::EnsureFrame(const Lla& origin) {
  if (frame_set_) return;
  frame_ = LocalTangentFrame(origin);
  frame_set_ = true;
  EarthModel earth;
  earth.g_N_mps2 = Eigen::Vector3d(0, 0, -NormalGravity(origin.lat_deg, origin.height_m));
  earth.w_IE_N_radps = frame_.w_IE_N();
  ekf_ = ErrorStateEkf(params_.ekf, earth);
  ekf_.SetGapNoiseAfter(1e-9 * static_cast<double>(params_.robust.gap_after.count()));
}

void Navigator::Push(const ImuSample& tagged) {
  if (!(tagged.dt_s > 0) || tagged.dt_s > 1.0 || !tagged.delta_angle_B_rad.allFinite() ||
      !tagged.delta_velocity_B_mps.allFinite()) {
    ++stats_.bad_input;
    status_ |= kStatusBadInput;
    return;
  }
  ImuSample s = tagged;
  CorrectImuTag(s);
  if (have_imu_ && s.t <= newest_imu_t_) {
    ++stats_.imu_out_of_order;
    return;
  }
  if (have_imu_ && s.t - newest_imu_t_ > IntervalNs(1.5 * s.dt_s)) ++stats_.imu_gaps;
  if (have_imu_ && aligned_ && s.t - newest_imu_t_ > params_.imu_timeout) {
    // back after a loss: nothing can carry the filter through the gap. Drop what is buffered from
    // before it, restart the filter just before this sample and its position at the next fix.
    while (!imu_.empty()) imu_.PopFront();
    while (!gnss_.empty() && gnss_.front().t < s.t) gnss_.PopFront();
    filter_t_ = std::max(filter_t_, s.t - IntervalNs(s.dt_s));
    restart_at_next_fix_ = true;
  }
  ++stats_.imu_samples;
  accel_scatter_.Add(s.delta_velocity_B_mps, s.dt_s);  // the raw samples, before any split
  if (!imu_.Push(s)) ++stats_.imu_overflow;
  newest_imu_t_ = s.t;
  have_imu_ = true;
  fixes_since_imu_ = 0;
  stats_.imu_lost = false;  // a sample just came
}

void Navigator::Push(const GnssSample& g) {
  if (!std::isfinite(g.position.lat_deg) || !std::isfinite(g.position.lon_deg) ||
      !std::isfinite(g.position.height_m) || std::abs(g.position.lat_deg) > 90.0 ||
      !g.pos_std_enu_m.allFinite()) {
    ++stats_.bad_input;
    status_ |= kStatusBadInput;
    return;
  }
  ++stats_.gnss_samples;
  ObserveGnssCourse(g);
  if (FallsBackToFixes() && g.fix_quality > 0) {
    FallbackFix(g);
    ++fixes_since_imu_;
  }  // the fallback solution while the IMU is lost
  if (!newest_gnss_t_ || g.t > *newest_gnss_t_) {
    // the fix period, for the wait on the next epoch (clamped to 20 Hz .. 0.5 Hz)
    if (newest_gnss_t_) {
      gnss_period_ = std::clamp<Nanoseconds>(g.t - *newest_gnss_t_, std::chrono::milliseconds(50),
                                             std::chrono::seconds(2));
    }
    newest_gnss_t_ = g.t;
  }
  const bool lost = ImuLost();
  if (lost && !stats_.imu_lost) ++stats_.imu_losses;
  stats_.imu_lost = lost;
  if (!UsesImu()) {
    if (params_.mode == NavMode::kMultiGnss)
      MultiGnssFix(g);
    else
      GnssOnlyFix(g);
    return;
  }
  if (aligned_ && g.t < filter_t_) {
    ++stats_.gnss_late;
    return;
  }
  // keep the buffer in time order (fixes may arrive out of order within the horizon)
  gnss_.Push(g);
  for (std::size_t i = gnss_.size() - 1; i > 0 && gnss_[i].t < gnss_[i - 1].t; --i)
    std::swap(gnss_[i], gnss_[i - 1]);
}

void Navigator::Push(const HeadingSample& h) {
  if (!std::isfinite(h.yaw_deg)) {
    ++stats_.bad_input;
    return;
  }
  heading_ = h;
}

void Navigator::Update() {
  if (!UsesImu()) return;
  GpsTime horizon_t = newest_imu_t_ - params_.fusion_horizon;
  if (params_.gnss_max_latency > params_.fusion_horizon && gnss_period_ > Nanoseconds{0}) {
    // hold at the next expected GNSS epoch until it arrives or the wait runs out; once it has run
    // out the fixes are missing (an outage): run at the horizon until they return, so that the
    // output predictor does not carry the free INS over the whole wait
    const GpsTime expected_t = *newest_gnss_t_ + gnss_period_;
    if (newest_imu_t_ - expected_t <= params_.gnss_max_latency)
      horizon_t = std::min(horizon_t, expected_t);
  }
  while (!imu_.empty() && imu_.front().t <= horizon_t) {
    ImuSample s = imu_.front();
    imu_.PopFront();
    bool consumed = false;
    // fuse every fix due up to the end of this interval at its own time, splitting the interval
    // there
    while (!gnss_.empty() && gnss_.front().t <= s.t) {
      const GnssSample g = gnss_.front();
      gnss_.PopFront();
      if (aligned_ && !consumed && g.t > filter_t_) {
        const GpsTime start = std::max(s.t - IntervalNs(s.dt_s), filter_t_);
        const double frac =
            static_cast<double>((g.t - start).count()) / static_cast<double>((s.t - start).count());
        if (frac >= 1.0 - 1e-9) {
          ProcessImu(s);
          consumed = true;
        } else if (frac > 0) {
          ProcessImu(ScaledPart(s, g.t, frac));
          s = ScaledPart(s, s.t, 1.0 - frac);
        }
      }
      ProcessGnss(g);
    }
    if (!consumed) ProcessImu(s);
  }
}

void Navigator::ProcessImu(const ImuSample& s) {
  if (!aligned_) {
    // running mean of the specific force for levelling (time constant ≈ 1 s)
    const Eigen::Vector3d f = s.delta_velocity_B_mps / s.dt_s;
    const double w = std::min(1.0, s.dt_s / 1.0);
    mean_f_B_ = mean_f_weight_ == 0 ? f : Eigen::Vector3d((1 - w) * mean_f_B_ + w * f);
    mean_f_weight_ += s.dt_s;
    filter_t_ = s.t;
    return;
  }
  if (s.t <= filter_t_) return;
  if (params_.mode == NavMode::kPlanar2d) {
    const Eigen::Vector3d f = s.delta_velocity_B_mps / s.dt_s;
    // remove gravity's projection on the horizontal axes using the levelled mean at alignment
    planar_.Predict(f.x() - mean_f_B_.x(), f.y() - mean_f_B_.y(), s.delta_angle_B_rad.z() / s.dt_s,
                    s.dt_s);
    filter_t_ = s.t;
    return;
  }
  DetectStationary(s);
  ObserveImuUsability(s);
  if (accel_scatter_.enabled()) ekf_.SetAccelNoiseFloor(accel_scatter_.density2_B_m2ps3());
  ekf_.Predict(s.delta_angle_B_rad, s.delta_velocity_B_mps, s.dt_s);
  // the INS's own velocity increment (no aiding) since the last fix velocity (GnssVelocityNoise)
  const Eigen::Vector3d ins_dv_N_mps =
      ekf_.state().q_NB * ekf_.CompensatedVelocity(s.delta_velocity_B_mps, s.dt_s) +
      ekf_.earth().g_N_mps2 * s.dt_s;
  ins_dv_N_mps_ += ins_dv_N_mps;
  fix_ripple_.Add(ins_dv_N_mps, s.dt_s);
  if (vibration_.enabled()) {
    vibration_.Add(s.delta_velocity_B_mps, s.dt_s);
    ekf_.SetVibrationVariance(vibration_.variance_B_mps2());
  }
  filter_t_ = s.t;
  ControlZeroMotion();
  if (params_.mode == NavMode::kEkf &&
      (params_.ekf.nhc_std_mps > 0 || params_.ekf.speed_rw_mps_rthz > 0) &&
      filter_t_ - last_nhc_t_ >= params_.nhc_period - std::chrono::microseconds(1)) {
    Record(kAidNonHolonomic, ekf_.UpdateNonHolonomic());
    ekf_.UpdateSpeedModel();
    last_nhc_t_ = filter_t_;
    RecordMountAngles();
  }
  RecordGyroScale();
  if (filter_t_ - last_gnss_fused_t_ > params_.outage_flag_after) {
    status_ |= kStatusDeadReckoning;
  }
}

void Navigator::TryAlign(const GnssSample& g) {
  EnsureFrame(g.position);
  if (mean_f_weight_ < 0.2) return;  // need some IMU data to level
  double yaw = 0;
  const double speed = g.vel_enu_mps.head<2>().norm();
  if (heading_) {
    yaw = (90.0 - heading_->yaw_deg) * M_PI / 180.0;
  } else if (g.has_velocity && speed >= params_.align_min_speed_mps) {
    yaw = std::atan2(g.vel_enu_mps.y(), g.vel_enu_mps.x());
  } else {
    return;
  }
  // level: rotate the mean specific force onto the N up axis, then apply the heading
  const Eigen::Quaterniond q_level =
      Eigen::Quaterniond::FromTwoVectors(mean_f_B_.normalized(), Eigen::Vector3d::UnitZ());
  const Eigen::Vector3d x_lev = q_level * Eigen::Vector3d::UnitX();
  const double yaw_lev = std::atan2(x_lev.y(), x_lev.x());
  NavState st;
  st.q_NB = (Eigen::AngleAxisd(yaw - yaw_lev, Eigen::Vector3d::UnitZ()) * q_level).normalized();
  const Eigen::Vector3d p_ant = frame_.ToLocal(g.position);
  st.p_N_m = p_ant - st.q_NB * params_.ekf.lever_arm_B_m;
  st.v_N_mps = g.has_velocity ? g.vel_enu_mps : Eigen::Vector3d::Zero();
  ekf_.Initialize(st);
  planar_.Initialize(p_ant.head<2>(), st.v_N_mps.head<2>(), yaw,
                     g.pos_std_enu_m.head<2>().norm() / std::sqrt(2.0));
  aligned_ = true;
  status_ |= kStatusAligned;
  filter_t_ = g.t;
  last_gnss_fused_t_ = g.t;
  last_nhc_t_ = g.t;
}

void Navigator::InitializeAt(GpsTime t, const Lla& body_position, const Eigen::Vector3d& v_N_mps,
                             const Eigen::Quaterniond& q_NB) {
  EnsureFrame(body_position);
  NavState st;
  st.p_N_m = frame_.ToLocal(body_position);
  st.v_N_mps = v_N_mps;
  st.q_NB = q_NB.normalized();
  ekf_.Initialize(st);
  aligned_ = true;
  status_ |= kStatusAligned;
  filter_t_ = newest_imu_t_ = last_gnss_fused_t_ = last_nhc_t_ = t;
  have_imu_ = true;
}

// The correlated GNSS error model of the fix's kind (RTK float or not) and geometry.
void Navigator::SelectGnssErrorModel(const GnssSample& g) {
  if (!(params_.ekf.gnss_error_tau_s > 0)) return;
  // RTK float and fixed solutions carry different correlated errors (GGA quality 5 = float);
  // the receiver's own error scales with its HDOP when the fix reports one
  const auto& e = params_.ekf;
  const bool is_float =
      e.gnss_float_error_tau_s > 0 && e.gnss_float_error_std_m > 0 && g.fix_quality == 5;
  const double dop = g.hdop > 0 ? std::clamp(g.hdop, 0.5, 20.0) : 1.0;
  if (is_float) {
    // a float solution's error persists over epochs: optionally sized by the receiver's own
    // estimate when it gives one (NAV-PVT hAcc), never below the configured one
    const double float_std_m = e.gnss_float_error_from_receiver
                                   ? std::max(e.gnss_float_error_std_m, g.receiver_h_std_m)
                                   : e.gnss_float_error_std_m;
    ekf_.SetGnssErrorModel(e.gnss_float_error_tau_s, float_std_m, !gnss_float_);
  } else {
    // the height's error scales with the VDOP (GSA), which is often 2-3 × the HDOP: scaled by
    // the HDOP, the tractor rig's fixes at HDOP 2.2 and VDOP 6.3 were modelled at 3.3 cm in
    // height where their error was 5.9 cm (mean vertical NEES 4.8)
    const double vertical_scale = g.vdop > 0 && e.gnss_error_vdop_ref > 0
                                      ? std::clamp(g.vdop, 0.5, 30.0) / e.gnss_error_vdop_ref
                                      : dop;
    const double vertical_std_m =
        (e.gnss_error_vertical_std_m > 0 ? e.gnss_error_vertical_std_m : e.gnss_error_std_m) *
        vertical_scale;
    ekf_.SetGnssErrorModel(e.gnss_error_tau_s, e.gnss_error_std_m * dop, vertical_std_m,
                           gnss_float_);
  }
  gnss_float_ = is_float;
}

void Navigator::ProcessGnss(const GnssSample& g) {
  if (!aligned_) {
    TryAlign(g);
    return;
  }
  if (g.fix_quality <= 0) return;
  if (params_.mode == NavMode::kImuOnly) return;
  const Eigen::Vector3d p = frame_.ToLocal(g.position);
  height_datum_var_m2_ = g.height_datum_std_m * g.height_datum_std_m;
  ControlImuUsability(g, p);
  if (restart_at_next_fix_ && params_.mode == NavMode::kEkf) {
    restart_at_next_fix_ = false;
    ResetToFix(g, p);
    return;
  }
  if (params_.mode == NavMode::kPlanar2d) {
    planar_.UpdatePosition(p.head<2>(), g.pos_std_enu_m.head<2>().norm() / std::sqrt(2.0));
    if (g.has_velocity && params_.use_gnss_velocity)
      planar_.UpdateVelocity(g.vel_enu_mps.head<2>(), g.vel_std_enu_mps.x());
    last_gnss_fused_t_ = g.t;
    status_ = (status_ | kStatusGnssFused) & ~kStatusDeadReckoning;
    return;
  }
  SelectGnssErrorModel(g);
  if (g.has_velocity) {
    last_gnss_vel_t_ = g.t;
    last_gnss_speed_mps_ = g.vel_enu_mps.head<2>().norm();
  }
  const UpdateResult rp = ControlGnssPosition(g, p);
  stats_.last_nis_pos = rp.nis;
  if (rp.accepted) {
    ++stats_.gnss_fused;
    ++stats_.nis_count;
    stats_.mean_nis_pos += (rp.nis - stats_.mean_nis_pos) / static_cast<double>(stats_.nis_count);
    last_gnss_fused_t_ = g.t;
    first_rejected_t_.reset();
    status_ =
        (status_ | kStatusGnssFused) & ~(kStatusGnssRejected | kStatusDeadReckoning | kStatusReset);
    FuseGnssVelocity(g);
    return;
  }
  ++stats_.gnss_rejected;
  status_ = (status_ | kStatusGnssRejected) & ~kStatusGnssFused;
  if (InGnssGlitch(g.t) || rtk_check_.suspect()) {
    // a receiver glitch (GnssStepCheck) or a suspect RTK fix (RtkFixCheck): its fixes are no
    // evidence against the filter
    first_rejected_t_.reset();
    if (rtk_check_.suspect()) FuseGnssVelocity(g);
    return;
  }
  if (!first_rejected_t_) first_rejected_t_ = g.t;
  // recovery: a long run of rejections means the filter, not the receiver, is wrong
  if (g.t - *first_rejected_t_ >= params_.reset_after_rejected) ResetToFix(g, p);
}

void Navigator::ResetToFix(const GnssSample& g, const Eigen::Vector3d& p_antenna_N_m) {
  const double vel_std = g.has_velocity ? 0.5 : 2.0;
  // the fix's white σ per axis; its height also carries the datum's (geoid model, as the updates)
  Eigen::Vector3d pos_std_N_m = g.pos_std_enu_m;
  pos_std_N_m.z() = std::hypot(g.pos_std_enu_m.z(), g.height_datum_std_m);
  ekf_.ResetPositionVelocity(p_antenna_N_m, g.has_velocity ? g.vel_enu_mps : ekf_.state().v_N_mps,
                             pos_std_N_m, vel_std);
  ekf_.ResetSetSpeed(vel_std);
  ++stats_.gnss_resets;
  rtk_frames_.Restart();  // the filter is on this fix's frame now
  rtk_check_.EndSuspicion();
  RecordRtkFrames();
  first_rejected_t_.reset();
  glitch_since_.reset();
  step_.Remember(g.t, p_antenna_N_m, g.pos_std_enu_m, ekf_.AntennaPosition());
  last_gnss_fused_t_ = g.t;
  status_ |= kStatusReset;
}

void Navigator::GnssOnlyFix(const GnssSample& g) {
  EnsureFrame(g.position);
  direct_.t = g.t;
  direct_.valid = g.fix_quality > 0;
  direct_.position = g.position;
  direct_.p_N_m = frame_.ToLocal(g.position);
  direct_.v_N_mps = g.has_velocity ? g.vel_enu_mps : Eigen::Vector3d::Zero();
  direct_.has_velocity = g.has_velocity;
  direct_.ground_speed_mps = g.ground_speed_mps;
  direct_.pos_std_enu_m = g.pos_std_enu_m;
  direct_.pos_std_enu_m.z() = std::hypot(g.pos_std_enu_m.z(), g.height_datum_std_m);
  direct_.vel_std_enu_mps = g.vel_std_enu_mps;
  direct_.has_attitude = false;
  if (g.has_velocity && g.vel_enu_mps.head<2>().norm() >= params_.align_min_speed_mps) {
    direct_.q_NB = Eigen::AngleAxisd(std::atan2(g.vel_enu_mps.y(), g.vel_enu_mps.x()),
                                     Eigen::Vector3d::UnitZ());
    direct_.has_attitude = true;
  }
  direct_.status = kStatusGnssFused;
}

// The fix as the solution while the IMU is lost: moved from the antenna to the body point by the
// filter's last attitude (the filter's output is the body point; seed 000's antenna is 0.84 m ahead
// of it), and its σ the fix's white σ with the receiver's correlated error the filter models (the
// white σ alone claimed 4 cm for a NEO-5M fix 0.7 m off: horizontal NEES above 1000).
void Navigator::FallbackFix(const GnssSample& g) {
  GnssOnlyFix(g);
  if (!aligned_ || params_.mode != NavMode::kEkf) return;
  direct_.p_N_m -= ekf_.state().q_NB * params_.ekf.lever_arm_B_m;
  direct_.position = frame_.ToLla(direct_.p_N_m);
  direct_.pos_std_enu_m =
      (direct_.pos_std_enu_m.cwiseAbs2() + ekf_.GnssErrorModelVariance()).cwiseSqrt();
}

void Navigator::MultiGnssFix(const GnssSample& g) {
  const int n = std::clamp(params_.multi_antenna_count, 1, kMaxGnssAntennas);
  if (g.antenna < 0 || g.antenna >= n) {
    ++stats_.bad_input;
    return;
  }
  EnsureFrame(g.position);
  // keep the receiver's fix; an epoch is complete when every receiver has a fix of that time
  // (within 1 ms). Completing it drops every older fix: epochs are combined in time order.
  multi_[g.antenna].Push(g);
  GnssSample epoch[kMaxGnssAntennas];
  for (int i = 0; i < n; ++i) {
    bool found = false;
    for (std::size_t k = 0; k < multi_[i].size() && !found; ++k) {
      if (std::chrono::abs(multi_[i][k].t - g.t) <= std::chrono::milliseconds(1)) {
        epoch[i] = multi_[i][k];
        found = true;
      }
    }
    if (!found) return;
  }
  for (int i = 0; i < n; ++i) {
    while (!multi_[i].empty() && multi_[i].front().t <= g.t + std::chrono::milliseconds(1))
      multi_[i].PopFront();
  }
  // centroid of the antennas minus the body-frame centroid; heading by a 2-D Procrustes fit
  const double w = 1.0 / n;
  Eigen::Vector3d p[kMaxGnssAntennas];
  Eigen::Vector3d c_N = Eigen::Vector3d::Zero(), c_B = Eigen::Vector3d::Zero();
  for (int i = 0; i < n; ++i) {
    p[i] = frame_.ToLocal(epoch[i].position);
    c_N += p[i] * w;
    c_B += params_.multi_antenna_B_m.col(i) * w;
  }
  double sxx = 0, sxy = 0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d a = (params_.multi_antenna_B_m.col(i) - c_B).head<2>();
    const Eigen::Vector2d b = (p[i] - c_N).head<2>();
    sxx += a.dot(b);
    sxy += a.x() * b.y() - a.y() * b.x();
  }
  const double yaw = std::atan2(sxy, sxx);
  const Eigen::Quaterniond q(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  direct_.t = g.t;
  direct_.valid = true;
  direct_.p_N_m = c_N - q * c_B;
  direct_.position = frame_.ToLla(direct_.p_N_m);
  direct_.v_N_mps.setZero();
  for (int i = 0; i < n; ++i) direct_.v_N_mps += epoch[i].vel_enu_mps * w;
  direct_.pos_std_enu_m = g.pos_std_enu_m * std::sqrt(w);
  // the geoid separation's rounding is the same in every receiver's height: not averaged away
  direct_.pos_std_enu_m.z() = std::hypot(direct_.pos_std_enu_m.z(), g.height_datum_std_m);
  direct_.q_NB = q;
  direct_.has_attitude = true;
  direct_.status = kStatusGnssFused;
}

bool UsesImu(NavMode m) {
  return m == NavMode::kEkf || m == NavMode::kImuOnly || m == NavMode::kPlanar2d;
}

// not in imu_only: a dead-reckoning comparison never shows a fix
bool Navigator::FallsBackToFixes() const {
  return params_.mode == NavMode::kEkf || params_.mode == NavMode::kPlanar2d;
}

bool Navigator::ImuLost() const {
  constexpr int kFixesBeforeImuLost = 4;
  return FallsBackToFixes() && have_imu_ && aligned_ && newest_gnss_t_ &&
         fixes_since_imu_ >= kFixesBeforeImuLost &&
         *newest_gnss_t_ - newest_imu_t_ > params_.imu_timeout;
}

NavOutput Navigator::Output() const {
  if (params_.mode == NavMode::kGnssOnly || params_.mode == NavMode::kMultiGnss) return direct_;
  // while the IMU is lost, and after it returns until the filter has restarted at a fix
  if ((ImuLost() || restart_at_next_fix_) && direct_.valid) {
    NavOutput o = direct_;
    o.status = (status_ | kStatusImuLost) & ~kStatusGnssFused;
    return o;
  }
  if (UsesVehicleModel()) return VehicleModelOutput();
  NavOutput o;
  o.status = status_ | (ekf_.repairs() > 0 ? kStatusCovarianceRepaired : 0u);
  if (!aligned_) return o;
  o.valid = true;
  o.t = filter_t_;
  if (params_.mode == NavMode::kPlanar2d) {
    o.p_N_m << planar_.position(), 0.0;
    o.v_N_mps << planar_.velocity(), 0.0;
    o.q_NB = Eigen::AngleAxisd(planar_.yaw_rad(), Eigen::Vector3d::UnitZ());
    o.has_attitude = true;
    o.pos_std_enu_m << std::sqrt(planar_.covariance()(0, 0)), std::sqrt(planar_.covariance()(1, 1)),
        0.0;
    o.vel_std_enu_mps << std::sqrt(planar_.covariance()(2, 2)),
        std::sqrt(planar_.covariance()(3, 3)), 0.0;
    o.position = frame_.ToLla(o.p_N_m);
    return o;
  }
  // output predictor: the delayed filter state carried through the IMU samples not yet fused
  NavState st = ekf_.state();
  MechanizationMemory mem;
  const EarthModel& earth = ekf_.earth();  // the frame origin's (EnsureFrame)
  for (std::size_t i = 0; i < imu_.size(); ++i) {
    const ImuSample& s = imu_[i];
    if (s.t <= o.t) continue;
    // the IMU compensated as the filter's own prediction does (biases, z scale, z coupling, the
    // accelerometer's y scale and x coupling to f_y)
    Propagate(earth, ekf_.CompensatedAngle(s.delta_angle_B_rad, s.dt_s),
              ekf_.CompensatedVelocity(s.delta_velocity_B_mps, s.dt_s), s.dt_s, mem, st);
    o.t = s.t;
  }
  // the INS at its tag time is the vehicle the residual lag δ̂t earlier (ErrorStateEkf)
  const double lag_s = ekf_.imu_time_residual_s();
  o.p_N_m = st.p_N_m + st.v_N_mps * lag_s;
  o.v_N_mps = st.v_N_mps + ekf_.smoothed_acceleration_N() * lag_s;
  o.q_NB = st.q_NB;
  o.has_attitude = true;
  o.position = frame_.ToLla(o.p_N_m);
  const EkfMatrix& P = ekf_.covariance();
  for (int i = 0; i < 3; ++i) {
    o.pos_std_enu_m[i] = std::sqrt(P(ekf_index::kPos + i, ekf_index::kPos + i));
    o.vel_std_enu_mps[i] = std::sqrt(P(ekf_index::kVel + i, ekf_index::kVel + i));
    o.att_std_rad[i] = std::sqrt(P(ekf_index::kAtt + i, ekf_index::kAtt + i));
  }
  // the fixes' common height error (an NMEA geoid separation's rounding) is in the estimate too
  o.pos_std_enu_m.z() =
      std::sqrt(P(ekf_index::kPos + 2, ekf_index::kPos + 2) + height_datum_var_m2_);
  o.accel_bias_B = ekf_.accel_bias();
  o.gyro_bias_B = ekf_.gyro_bias();
  return o;
}

}  // namespace hil::estimator

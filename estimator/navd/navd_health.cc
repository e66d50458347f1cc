#include "hil/estimator/navd/navd_health.h"

#include <algorithm>
#include <cstdio>
#include <numbers>

namespace hil::estimator {
namespace {

constexpr Nanoseconds kRecent{5'000'000'000LL};
// a fix reaches the filter up to ~2.2 s after its time of validity at 9600 baud (the epoch is
// complete only when the next one starts), so "no fix" is judged with margin beyond that
constexpr Nanoseconds kMinOutage{3'500'000'000LL};
constexpr std::uint32_t kResetTickWindow =
    60'000'000;                                // a restarted 1 MHz tick is below one minute
constexpr std::uint16_t kResetSeqWindow = 64;  // a restarted sequence is small

void Add(std::string& s, const char* key, std::uint64_t v) {
  char b[96];
  std::snprintf(b, sizeof b, ",\"%s\":%llu", key, static_cast<unsigned long long>(v));
  s += b;
}

// the IMU's states the filter estimates (mounting angles, the gyro's scale and couplings, the tags'
// lag), each present only while it is estimated (or once it is found)
constexpr double kDeg = 180.0 / std::numbers::pi;  // rad → degrees

void AppendSensorStates(std::string& s, const NavigatorStats& n) {
  char b[256];
  // present while the IMU's mounting pitch and yaw are estimated (ErrorStateEkf): degrees of the
  // vehicle frame in the IMU frame, and their σ
  if (n.mount_estimated) {
    std::snprintf(b, sizeof b,
                  ",\"mount_deg\":{\"pitch\":%.3f,\"yaw\":%.3f,\"pitch_std\":%.3f,"
                  "\"yaw_std\":%.3f}",
                  n.mount_pitch_rad * kDeg, n.mount_yaw_rad * kDeg, n.mount_pitch_std_rad * kDeg,
                  n.mount_yaw_std_rad * kDeg);
    s += b;
  }
  // present while the z gyro's scale factor is estimated (ErrorStateEkf): its error and σ, ppm
  if (n.gyro_scale_z_estimated) {
    std::snprintf(b, sizeof b, ",\"gyro_scale_z_ppm\":%.0f,\"gyro_scale_z_std_ppm\":%.0f",
                  n.gyro_scale_z * 1e6, n.gyro_scale_z_std * 1e6);
    s += b;
  }
  // present while the x and y gyros' scale factors are estimated (ErrorStateEkf): ppm, and σ
  if (n.gyro_scale_xy_estimated) {
    std::snprintf(b, sizeof b,
                  ",\"gyro_scale_xy_ppm\":{\"x\":%.0f,\"y\":%.0f,\"x_std\":%.0f,\"y_std\":%.0f}",
                  n.gyro_scale_xy.x() * 1e6, n.gyro_scale_xy.y() * 1e6,
                  n.gyro_scale_xy_std.x() * 1e6, n.gyro_scale_xy_std.y() * 1e6);
    s += b;
  }
  // present while the x and y gyros' coupling to the z rate is estimated (ErrorStateEkf): degrees,
  // and their σ
  if (n.gyro_z_coupling_estimated) {
    std::snprintf(b, sizeof b,
                  ",\"gyro_z_coupling_deg\":{\"x\":%.3f,\"y\":%.3f,\"x_std\":%.3f,\"y_std\":%.3f}",
                  n.gyro_z_coupling_rad.x() * kDeg, n.gyro_z_coupling_rad.y() * kDeg,
                  n.gyro_z_coupling_std_rad.x() * kDeg, n.gyro_z_coupling_std_rad.y() * kDeg);
    s += b;
  }
  // present while the accelerometer's lateral-force errors are estimated (ErrorStateEkf): the y
  // scale in ppm, the x accelerometer's coupling to f_y in degrees, and their σ
  if (n.accel_y_force_estimated) {
    std::snprintf(b, sizeof b,
                  ",\"accel_y_force\":{\"scale_y_ppm\":%.0f,\"coupling_x_deg\":%.3f,"
                  "\"coupling_z_deg\":%.3f,\"scale_y_std_ppm\":%.0f,\"coupling_x_std_deg\":%.3f,"
                  "\"coupling_z_std_deg\":%.3f}",
                  n.accel_y_force.x() * 1e6, n.accel_y_force.y() * kDeg, n.accel_y_force.z() * kDeg,
                  n.accel_y_force_std.x() * 1e6, n.accel_y_force_std.y() * kDeg,
                  n.accel_y_force_std.z() * kDeg);
    s += b;
  }
  // present while the IMU tags' residual lag is estimated (ErrorStateEkf), once it is off zero
  if (n.imu_time_residual_s != 0) {
    std::snprintf(b, sizeof b, ",\"imu_tag_lag_residual_s\":%.4f", n.imu_time_residual_s);
    s += b;
  }
  // present once a lag was found and taken off the IMU tags (the line stays short otherwise)
  if (n.imu_tag_lag_s == 0) return;
  // with the estimate on the evidence so far and its σ (ImuTimeOffset), which the lag follows
  std::snprintf(
      b, sizeof b,
      ",\"imu_tag_lag_s\":%.4f,\"imu_tag_lag_estimate_s\":%.4f,\"imu_tag_lag_std_s\":%.4f",
      n.imu_tag_lag_s, n.imu_tag_lag_estimate_s, n.imu_tag_lag_std_s);
  s += b;
}

// the filter's consistency: each aid source's innovation window against its χ² band, the
// adapted process-noise scale, fadings, standstill
void AppendConsistency(std::string& s, const NavigatorStats& n) {
  char b[256];
  s += ",\"aid\":{";
  for (int i = 0; i < kNumAidSources; ++i) {
    const NavigatorStats::Aid& a = n.aid[i];
    std::snprintf(b, sizeof b,
                  "%s\"%s\":{\"accepted\":%llu,\"rejected\":%llu,\"last_nis\":%.3g,"
                  "\"window_nis_per_dof\":%.3g,\"window_count\":%d,\"band\":[%.3g,%.3g],"
                  "\"windows_above\":%llu,\"windows_below\":%llu}",
                  i ? "," : "", AidSourceName(i), static_cast<unsigned long long>(a.accepted),
                  static_cast<unsigned long long>(a.rejected), a.last_nis, a.window_nis_per_dof,
                  a.window_count, a.band_low, a.band_high,
                  static_cast<unsigned long long>(a.windows_above),
                  static_cast<unsigned long long>(a.windows_below));
    s += b;
  }
  std::snprintf(b, sizeof b, "},\"process_noise_scale\":%.4g", n.process_noise_scale);
  s += b;
  Add(s, "fadings", n.fadings);
  Add(s, "gap_fadings", n.gap_fadings);
  Add(s, "reject_fadings", n.reject_fadings);
  Add(s, "gap_recoveries", n.gap_recoveries);
  Add(s, "recovery_fixes", n.recovery_fixes);
  Add(s, "gnss_steps", n.gnss_steps);
  Add(s, "gnss_glitches", n.gnss_glitches);
  Add(s, "gnss_glitch_rejected", n.gnss_glitch_rejected);
  Add(s, "stationary_periods", n.stationary_periods);
  Add(s, "rtk_suspect_episodes", n.rtk_suspect_episodes);
  Add(s, "rtk_suspect_fixes", n.rtk_suspect_fixes);
  Add(s, "rtk_frame_switches", n.rtk_frame_switches);
  Add(s, "rtk_frame_episodes", n.rtk_frame_episodes);
  Add(s, "rtk_other_frames", n.rtk_other_frames);
  s += n.stationary ? ",\"stationary\":true" : ",\"stationary\":false";
  // present once the accelerometer was found far outside its noise model (the filter then
  // leans on the GNSS; the line stays short otherwise)
  if (n.accel_noise_raises > 0) {
    std::snprintf(b, sizeof b, ",\"accel_noise_scale\":%.4g,\"accel_noise_raises\":%llu",
                  n.accel_noise_scale, static_cast<unsigned long long>(n.accel_noise_raises));
    s += b;
  }
  // present once the vehicle was found outside the non-holonomic constraint (NhcNoiseParams)
  if (n.nhc_noise_raises > 0) {
    std::snprintf(b, sizeof b, ",\"nhc_noise_scale\":%.4g,\"nhc_noise_raises\":%llu",
                  n.nhc_noise_scale, static_cast<unsigned long long>(n.nhc_noise_raises));
    s += b;
  }
  // present once the IMU was found unusable (ImuUsabilityCheck; the solution is then GNSS + the
  // vehicle model): the test's statistic against its threshold
  if (n.imu_unusable_periods > 0) {
    std::snprintf(b, sizeof b,
                  ",\"imu_consistency\":{\"unusable\":%s,\"stat\":%.4g,\"threshold\":%.4g,"
                  "\"tests\":%llu,\"unusable_periods\":%llu}",
                  n.imu_unusable ? "true" : "false", n.imu_consistency_stat,
                  n.imu_consistency_threshold,
                  static_cast<unsigned long long>(n.imu_consistency_tests),
                  static_cast<unsigned long long>(n.imu_unusable_periods));
    s += b;
  }
  // present once the fix velocity's σ is learned below the configured one (GnssVelocityNoise)
  if (n.gnss_vel_std_learned) {
    std::snprintf(b, sizeof b, ",\"gnss_vel_std_mps\":%.3f", n.gnss_vel_std_mps);
    s += b;
  }
  AppendSensorStates(s, n);
}

}  // namespace

void NavdHealth::OnGnss(const GnssSample& g) {
  ++c_.gnss_epochs;
  if (last_gnss_t_) {
    if (g.t <= *last_gnss_t_) {
      ++c_.gnss_repeated_epochs;
      return;
    }
    const Nanoseconds dt = g.t - *last_gnss_t_;
    if (gnss_period_ == Nanoseconds{0} || dt < gnss_period_) gnss_period_ = dt;
  }
  last_gnss_t_ = g.t;
  if (g.fix_quality <= 0) {
    ++c_.gnss_no_fix_epochs;
    return;
  }
  if (last_fix_t_ && gnss_period_ > Nanoseconds{0} && (g.t - *last_fix_t_) * 2 > gnss_period_ * 3)
    ++c_.gnss_gaps;
  last_fix_t_ = g.t;
}

void NavdHealth::OnMcuFrame(const drivers::McuFrame& f) {
  if (f.type == drivers::McuFrame::Type::kStatus && f.nominal_imu_period_ticks > 0) {
    imu_period_ticks_ = f.nominal_imu_period_ticks;
  }
  if (have_frame_) {
    if (f.sequence == last_seq_ && f.tick == last_tick_) {
      ++c_.imu_repeated_frames;
      return;
    }
    // a reset restarts both the tick (near zero, below the last one) and the sequence
    if (f.tick < last_tick_ && f.tick < kResetTickWindow && f.sequence < last_seq_ &&
        f.sequence < kResetSeqWindow) {
      ++c_.mcu_resets;
      have_imu_tick_ = false;
    }
  }
  have_frame_ = true;
  last_seq_ = f.sequence;
  last_tick_ = f.tick;
  if (f.type != drivers::McuFrame::Type::kImu) return;
  if (have_imu_tick_) {
    const std::uint32_t dt = f.tick - last_imu_tick_;  // modulo 2^32: wraps are fine
    if (dt > 0 && dt < 0x80000000u) {
      if (imu_period_ticks_ == 0) imu_period_ticks_ = dt;
      if (static_cast<std::uint64_t>(dt) * 2 > static_cast<std::uint64_t>(imu_period_ticks_) * 5)
        ++c_.imu_gaps;
    }
  }
  have_imu_tick_ = true;
  last_imu_tick_ = f.tick;
}

std::uint64_t NavdHealth::GnssLinkErrors() const {
  std::uint64_t n = 0;
  if (src_.nmea)
    n += src_.nmea->bad_checksum + src_.nmea->malformed + src_.nmea->overlong +
         src_.nmea->garbage_bytes;
  if (src_.ubx) n += src_.ubx->bad_checksum + src_.ubx->overlong + src_.ubx->garbage_bytes;
  return n;
}

std::uint64_t NavdHealth::ImuLinkErrors() const {
  std::uint64_t n = c_.imu_repeated_frames;
  if (src_.mcu)
    n += src_.mcu->bad_crc + src_.mcu->bad_header + src_.mcu->garbage_bytes +
         src_.mcu->sequence_gaps;
  if (src_.j1939) n += src_.j1939->unpaired + src_.j1939->bad_length + src_.j1939->out_of_order;
  return n;
}

bool NavdHealth::Rose(Recent& r, std::uint64_t value, GpsTime t) {
  if (value > r.seen) r.last_rise = t;
  r.seen = value;
  return r.last_rise && t - *r.last_rise <= kRecent;
}

std::string NavdHealth::Field(GpsTime t) {
  // outage: no fix for longer than a few receiver periods (judged at the solution's time)
  const Nanoseconds limit = std::max(kMinOutage, 3 * gnss_period_ + Nanoseconds{500'000'000});
  const Nanoseconds since =
      last_fix_t_ ? t - *last_fix_t_ : (last_gnss_t_ ? t - *last_gnss_t_ : Nanoseconds{0});
  const bool outage = (last_fix_t_ || last_gnss_t_) && since > limit;
  if (outage && !outage_) ++c_.gnss_outages;
  outage_ = outage;

  std::string flags;
  const auto flag = [&](bool on, const char* name) {
    if (!on) return;
    flags += flags.empty() ? "\"" : ",\"";
    flags += name;
    flags += "\"";
  };
  flag(outage_, "gnss_outage");
  flag(Rose(gnss_errors_, GnssLinkErrors(), t), "gnss_link_errors");
  flag(Rose(imu_errors_, ImuLinkErrors(), t), "imu_link_errors");
  flag(Rose(rejected_, src_.nav ? src_.nav->gnss_rejected : 0, t), "gnss_rejected");
  flag(Rose(imu_gap_, c_.imu_gaps, t), "imu_gap");
  flag(Rose(mcu_reset_, c_.mcu_resets, t), "mcu_reset");
  flag(src_.nav != nullptr && src_.nav->imu_lost, "imu_lost");
  flag(src_.nav != nullptr && src_.nav->imu_unusable, "imu_unusable");

  std::string s = ",\"health\":{\"flags\":[" + flags + "]";
  const auto* n = src_.nmea;
  const auto* u = src_.ubx;
  Add(s, "gnss_checksum_errors", (n ? n->bad_checksum : 0) + (u ? u->bad_checksum : 0));
  Add(s, "gnss_malformed", (n ? n->malformed + n->overlong : 0) + (u ? u->overlong : 0));
  Add(s, "gnss_garbage_bytes", (n ? n->garbage_bytes : 0) + (u ? u->garbage_bytes : 0));
  Add(s, "gnss_epochs", c_.gnss_epochs);
  Add(s, "gnss_no_fix_epochs", c_.gnss_no_fix_epochs);
  Add(s, "gnss_repeated_epochs", c_.gnss_repeated_epochs);
  Add(s, "gnss_gaps", c_.gnss_gaps);
  Add(s, "gnss_outages", c_.gnss_outages);
  Add(s, "gnss_rejected", src_.nav ? src_.nav->gnss_rejected : 0);
  Add(s, "gnss_late", src_.nav ? src_.nav->gnss_late : 0);
  Add(s, "gnss_resets", src_.nav ? src_.nav->gnss_resets : 0);
  Add(s, "imu_crc_errors", src_.mcu ? src_.mcu->bad_crc : 0);
  Add(s, "imu_bad_headers", src_.mcu ? src_.mcu->bad_header : 0);
  Add(s, "imu_garbage_bytes", src_.mcu ? src_.mcu->garbage_bytes : 0);
  Add(s, "imu_sequence_gaps", src_.mcu ? src_.mcu->sequence_gaps : 0);
  Add(s, "imu_repeated_frames", c_.imu_repeated_frames);
  Add(s, "imu_gaps", c_.imu_gaps);
  Add(s, "mcu_resets", c_.mcu_resets);
  const auto* a = src_.mcu_adapter;
  Add(s, "imu_samples_dropped", a ? a->imu_gap + a->imu_no_time + a->imu_no_scale : 0);
  Add(s, "imu_losses", src_.nav ? src_.nav->imu_losses : 0);
  const auto* j = src_.j1939;
  Add(s, "imu_can_unpaired", j ? j->unpaired : 0);
  Add(s, "imu_can_bad_length", j ? j->bad_length : 0);
  Add(s, "imu_can_out_of_order", j ? j->out_of_order : 0);
  if (src_.nav != nullptr) AppendConsistency(s, *src_.nav);
  s += "}";
  return s;
}

void NavdHealth::AppendTo(std::string& line, GpsTime t) {
  std::size_t end = line.size();
  while (end > 0 && (line[end - 1] == '\n' || line[end - 1] == '\r')) --end;
  if (end == 0 || line[end - 1] != '}') return;
  line.insert(end - 1, Field(t));
}

}  // namespace hil::estimator

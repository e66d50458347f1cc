// The issue-41 keys of the scenario's `mcu:` section: `imu_profile` (a named field profile,
// firmware_emu/mcu/field_profiles.h) and `rough` (vibration front end, sensor error terms,
// temperature profile, time tag). Format in vectors/mcu/imu_error_model.md.
#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/mcu/field_profiles.h"
#include "hil/firmware_emu/truth_sample.h"

#include "mcu.h"

namespace hil::harness {
namespace {

constexpr double kG0Rough = kStandardGravity_mps2;
constexpr double kDegPerHrRough = kDeg / 3600.0;

Eigen::Vector3d Vec3(const YamlReader& r, const std::string& key, const Eigen::Vector3d& fb) {
  const auto v = r.Doubles(key, 3, {fb.x(), fb.y(), fb.z()});
  return {v[0], v[1], v[2]};
}

// [{t_s, <value_key>}, …] in strictly increasing time
std::vector<mcu::ProfilePoint> ReadProfile(const YamlReader& r, const char* value_key, double lo,
                                           double hi) {
  std::vector<mcu::ProfilePoint> out;
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"t_s", value_key});
    mcu::ProfilePoint p{e.DoubleIn("t_s", 0, 0, 7 * 86400), e.DoubleIn(value_key, 0, lo, hi)};
    if (!e.Has(value_key)) e.Fail(value_key, "missing");
    if (!out.empty() && p.t_s <= out.back().t_s) e.Fail("t_s", "times must increase");
    out.push_back(p);
  }
  return out;
}

void ReadOrders(const YamlReader& r, std::vector<mcu::EngineOrder>& orders) {
  orders.clear();
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"order", "accel_amplitude_mps2", "gyro_amplitude_dps"});
    mcu::EngineOrder o;
    o.order = e.DoubleIn("order", 1, 0.25, 32);
    o.accel_amplitude_mps2 = Vec3(e, "accel_amplitude_mps2", Eigen::Vector3d::Zero());
    o.gyro_amplitude_radps = Vec3(e, "gyro_amplitude_dps", Eigen::Vector3d::Zero()) * kDeg;
    orders.push_back(o);
  }
}

void ReadRide(const YamlReader& r, std::vector<mcu::RideBand>& bands) {
  bands.clear();
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"band_hz", "accel_psd_mps2_sq_per_hz", "gyro_psd_dps_sq_per_hz"});
    mcu::RideBand b;
    const auto band = e.Doubles("band_hz", 2, {1, 20});
    if (!(band[0] > 0 && band[0] < band[1])) e.Fail("band_hz", "needs 0 < low < high");
    b.f_low_hz = band[0];
    b.f_high_hz = band[1];
    b.accel_psd_mps2_sq_per_hz = Vec3(e, "accel_psd_mps2_sq_per_hz", Eigen::Vector3d::Zero());
    b.gyro_psd_radps_sq_per_hz =
        Vec3(e, "gyro_psd_dps_sq_per_hz", Eigen::Vector3d::Zero()) * (kDeg * kDeg);
    if (b.accel_psd_mps2_sq_per_hz.minCoeff() < 0 || b.gyro_psd_radps_sq_per_hz.minCoeff() < 0)
      e.Fail("a PSD must be >= 0");
    bands.push_back(b);
  }
}

// Scales of one triad's keys: accelerometer in µg / mg / g, gyro in °/s and °/h.
struct TriadUnits {
  double density, instability, rrw, turn_on, temp_bias, range, lsb;
  const char* density_key;
  const char* instability_key;
  const char* rrw_key;
  const char* turn_on_key;
  const char* temp_bias_key;
  const char* range_key;
  const char* lsb_key;
};

const TriadUnits kAccelUnits{1e-6 * kG0Rough,
                             1e-6 * kG0Rough,
                             1e-6 * kG0Rough,
                             1e-3 * kG0Rough,
                             1e-3 * kG0Rough,
                             kG0Rough,
                             1e-3 * kG0Rough,
                             "noise_density_ug_rthz",
                             "bias_instability_ug",
                             "rate_random_walk_ug_rts",
                             "turn_on_bias_mg",
                             "bias_temperature_mg_per_c",
                             "range_g",
                             "lsb_mg"};
const TriadUnits kGyroUnits{kDeg,
                            kDegPerHrRough,
                            kDegPerHrRough / 60.0,
                            kDeg,
                            kDeg,
                            kDeg,
                            kDeg,
                            "noise_density_dps_rthz",
                            "bias_instability_degph",
                            "rate_random_walk_degph_rthr",
                            "turn_on_bias_dps",
                            "bias_temperature_dps_per_c",
                            "range_dps",
                            "lsb_dps"};

// Optional key: value × scale, else the current value.
double Scaled(const YamlReader& r, const char* key, double current, double scale, double hi) {
  return r.Has(key) ? r.DoubleIn(key, 0, 0, hi) * scale : current;
}

void ReadTriadTerms(const YamlReader& r, const TriadUnits& u, bool gyro, mcu::TriadSpec& t) {
  std::vector<std::string> keys{u.density_key,
                                u.instability_key,
                                u.rrw_key,
                                u.turn_on_key,
                                u.temp_bias_key,
                                u.range_key,
                                u.lsb_key,
                                "flicker_terms",
                                "flicker_tau_s",
                                "scale_factor_ppm",
                                "scale_temperature_ppm_per_c",
                                "misalignment_deg",
                                "bandwidth_hz"};
  if (gyro) keys.emplace_back("g_sensitivity_dps_per_g");
  r.CheckKeys(keys);
  mcu::TriadErrorSpec& e = t.error;
  if (r.Has(u.density_key))
    e.noise_density = Eigen::Vector3d::Constant(r.DoubleIn(u.density_key, 0, 0, 1e6) * u.density);
  e.bias_instability = Scaled(r, u.instability_key, e.bias_instability, u.instability, 1e6);
  e.bias_random_walk = Scaled(r, u.rrw_key, e.bias_random_walk, u.rrw, 1e6);
  if (r.Has(u.turn_on_key))
    e.turn_on_bias_sigma =
        Eigen::Vector3d::Constant(r.DoubleIn(u.turn_on_key, 0, 0, 1e6) * u.turn_on);
  if (r.Has(u.temp_bias_key))
    e.bias_temperature_coeff_per_c = r.DoubleIn(u.temp_bias_key, 0, -1e3, 1e3) * u.temp_bias;
  e.flicker_terms = static_cast<int>(r.Int("flicker_terms", e.flicker_terms, 0, 8));
  const auto tau = r.Doubles("flicker_tau_s", 2, {e.flicker_tau_min_s, e.flicker_tau_max_s});
  if (!(tau[0] > 0 && tau[0] <= tau[1])) r.Fail("flicker_tau_s", "needs 0 < min <= max");
  e.flicker_tau_min_s = tau[0];
  e.flicker_tau_max_s = tau[1];
  e.scale_factor_sigma_ppm = r.DoubleIn("scale_factor_ppm", e.scale_factor_sigma_ppm, 0, 1e5);
  e.scale_temperature_ppm_per_c =
      r.DoubleIn("scale_temperature_ppm_per_c", e.scale_temperature_ppm_per_c, -1e4, 1e4);
  e.misalignment_sigma_rad = Scaled(r, "misalignment_deg", e.misalignment_sigma_rad, kDeg, 10);
  e.bandwidth_hz = r.DoubleIn("bandwidth_hz", e.bandwidth_hz, 0, 20000);
  if (gyro && r.Has("g_sensitivity_dps_per_g"))
    e.g_sensitivity_radps_per_mps2 =
        r.DoubleIn("g_sensitivity_dps_per_g", 0, -100, 100) * kDeg / kG0Rough;
  t.counts.range = Scaled(r, u.range_key, t.counts.range, u.range, 1e6);
  t.counts.count_lsb =
      r.Has(u.lsb_key) ? r.DoubleIn(u.lsb_key, 0, 1e-9, 1e6) * u.lsb : t.counts.count_lsb;
}

}  // namespace

void ReadMcuRough(const YamlReader& r, mcu::McuConfig& c) {
  r.CheckKeys({"internal_rate_hz", "accel_aaf_hz", "gyro_aaf_hz", "rpm", "engine_orders", "ride",
               "mount", "temperature_profile", "time_tag", "accel", "gyro"});
  mcu::RoughImuSpec& s = c.rough;
  s.internal_rate_hz = r.DoubleIn("internal_rate_hz", s.internal_rate_hz, 0, 20000);
  s.accel_aaf_hz = r.DoubleIn("accel_aaf_hz", s.accel_aaf_hz, 0, 10000);
  s.gyro_aaf_hz = r.DoubleIn("gyro_aaf_hz", s.gyro_aaf_hz, 0, 10000);
  if (auto p = r.OptionalChild("rpm")) s.rpm_profile = ReadProfile(*p, "rpm", 0, 30000);
  if (auto o = r.OptionalChild("engine_orders")) ReadOrders(*o, s.engine_orders);
  if (auto b = r.OptionalChild("ride")) ReadRide(*b, s.ride);
  if (auto m = r.OptionalChild("mount")) {
    m->CheckKeys({"frequency_hz", "damping_ratio"});
    s.mount.frequency_hz = m->DoubleIn("frequency_hz", s.mount.frequency_hz, 0, 10000);
    s.mount.damping_ratio = m->DoubleIn("damping_ratio", s.mount.damping_ratio, 0.005, 2);
  }
  if (auto p = r.OptionalChild("temperature_profile"))
    s.temperature_profile = ReadProfile(*p, "c", -40, 85);
  if (auto t = r.OptionalChild("time_tag")) {
    t->CheckKeys({"latency_s", "jitter_s", "imu_clock_ppm"});
    s.time_tag.latency_s = t->DoubleIn("latency_s", s.time_tag.latency_s, 0, 1);
    s.time_tag.jitter_s = t->DoubleIn("jitter_s", s.time_tag.jitter_s, 0, 0.1);
    s.time_tag.imu_clock_ppm = t->DoubleIn("imu_clock_ppm", s.time_tag.imu_clock_ppm, -1e4, 1e4);
  }
  if (auto a = r.OptionalChild("accel")) ReadTriadTerms(*a, kAccelUnits, false, c.profile.accel);
  if (auto g = r.OptionalChild("gyro")) ReadTriadTerms(*g, kGyroUnits, true, c.profile.gyro);
  const bool vibrates = !s.engine_orders.empty() || !s.ride.empty();
  if (vibrates && !(s.internal_rate_hz > 0))
    r.Fail("internal_rate_hz", "engine orders and ride vibration need internal_rate_hz > 0");
  if (s.internal_rate_hz > 0 && s.internal_rate_hz < 4 * c.imu_rate_hz)
    r.Fail("internal_rate_hz", "must be at least 4 x mcu.imu_rate_hz");
  const double half = 0.5 * s.internal_rate_hz;
  const double accel_aaf = s.accel_aaf_hz > 0 ? s.accel_aaf_hz : c.profile.accel.error.bandwidth_hz;
  const double gyro_aaf = s.gyro_aaf_hz > 0 ? s.gyro_aaf_hz : c.profile.gyro.error.bandwidth_hz;
  if (s.internal_rate_hz > 0 && !(accel_aaf > 0 && accel_aaf < half))
    r.Fail("accel_aaf_hz",
           "the accelerometer's anti-alias cutoff must be in (0, internal_rate_hz/2)");
  if (s.internal_rate_hz > 0 && !(gyro_aaf > 0 && gyro_aaf < half))
    r.Fail("gyro_aaf_hz", "the gyro's anti-alias cutoff must be in (0, internal_rate_hz/2)");
  for (const mcu::RideBand& b : s.ride)
    if (b.f_high_hz >= half) r.Fail("ride", "a ride band must end below internal_rate_hz/2");
  if (s.mount.frequency_hz >= half && s.mount.frequency_hz > 0)
    r.Fail("mount", "the mount resonance must lie below internal_rate_hz/2");
}

}  // namespace hil::harness

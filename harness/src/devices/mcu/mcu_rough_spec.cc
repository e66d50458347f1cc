// The issue-41 keys of the scenario's `mcu:` section: `imu_profile` (a named field profile,
// firmware_emu/mcu/field_profiles.h) and `rough` (vibration front end, sensor error terms,
// temperature profile, time tag). Every key: mcu_keys.h (docs/scenario_reference.md); the terms
// and their sources: vectors/mcu/imu_error_model.md.
#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/mcu/field_profiles.h"
#include "hil/firmware_emu/truth_sample.h"

#include "mcu.h"
#include "mcu_keys.h"

namespace hil::harness {
namespace {

using mcu_keys::kAccel;
using mcu_keys::kEngineOrder;
using mcu_keys::kGyro;
using mcu_keys::kMount;
using mcu_keys::kRideBand;
using mcu_keys::kRough;
using mcu_keys::kRpmPoint;
using mcu_keys::kTemperaturePoint;
using mcu_keys::kTimeTag;

constexpr double kG0Rough = kStandardGravity_mps2;
constexpr double kDegPerHrRough = kDeg / 3600.0;

template <const auto& T>
Eigen::Vector3d Vec3(const KeyedReader<T>& r, typename KeyedReader<T>::Key key,
                     const Eigen::Vector3d& fb) {
  const auto v = r.Doubles(key, 3, {fb.x(), fb.y(), fb.z()});
  return {v[0], v[1], v[2]};
}

// [{t_s, <value>}, …] in strictly increasing time; the value's key is the table's second row
template <const auto& T>
std::vector<mcu::ProfilePoint> ReadProfile(const YamlReader& r) {
  const typename KeyedReader<T>::Key value_key(T[1].name.data());
  std::vector<mcu::ProfilePoint> out;
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<T> e(y);
    e.CheckKeys();
    mcu::ProfilePoint p{e.Number("t_s", 0), e.Number(value_key, 0)};
    if (!e.Has(value_key)) e.Fail(value_key, "missing");
    if (!out.empty() && p.t_s <= out.back().t_s) e.Fail("t_s", "times must increase");
    out.push_back(p);
  }
  return out;
}

void ReadOrders(const YamlReader& r, std::vector<mcu::EngineOrder>& orders) {
  orders.clear();
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kEngineOrder> e(y);
    e.CheckKeys();
    mcu::EngineOrder o;
    o.order = e.Number("order", 1);
    o.accel_amplitude_mps2 = Vec3(e, "accel_amplitude_mps2", Eigen::Vector3d::Zero());
    o.gyro_amplitude_radps = Vec3(e, "gyro_amplitude_dps", Eigen::Vector3d::Zero()) * kDeg;
    orders.push_back(o);
  }
}

void ReadRide(const YamlReader& r, std::vector<mcu::RideBand>& bands) {
  bands.clear();
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kRideBand> e(y);
    e.CheckKeys();
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

// One triad's keys in its table and their scales to SI: accelerometer in µg / mg / g, gyro in °/s
// and °/h.
template <const auto& T>
struct TriadUnits {
  using Key = typename KeyedReader<T>::Key;
  double density, instability, rrw, turn_on, temp_bias, range, lsb;
  Key density_key, instability_key, rrw_key, turn_on_key, temp_bias_key, range_key, lsb_key;
};

const TriadUnits<kAccel> kAccelUnits{1e-6 * kG0Rough,
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
const TriadUnits<kGyro> kGyroUnits{kDeg,
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
template <const auto& T>
double Scaled(const KeyedReader<T>& r, typename KeyedReader<T>::Key key, double current,
              double scale) {
  return r.Has(key) ? r.Number(key, 0) * scale : current;
}

template <const auto& T>
void ReadTriadTerms(const KeyedReader<T>& r, const TriadUnits<T>& u, mcu::TriadSpec& t) {
  r.CheckKeys();
  mcu::TriadErrorSpec& e = t.error;
  if (r.Has(u.density_key))
    e.noise_density = Eigen::Vector3d::Constant(r.Number(u.density_key, 0) * u.density);
  e.bias_instability = Scaled(r, u.instability_key, e.bias_instability, u.instability);
  e.bias_random_walk = Scaled(r, u.rrw_key, e.bias_random_walk, u.rrw);
  if (r.Has(u.turn_on_key))
    e.turn_on_bias_sigma = Eigen::Vector3d::Constant(r.Number(u.turn_on_key, 0) * u.turn_on);
  if (r.Has(u.temp_bias_key))
    e.bias_temperature_coeff_per_c = r.Number(u.temp_bias_key, 0) * u.temp_bias;
  e.flicker_terms = static_cast<int>(r.Integer("flicker_terms", e.flicker_terms));
  const auto tau = r.Doubles("flicker_tau_s", 2, {e.flicker_tau_min_s, e.flicker_tau_max_s});
  if (!(tau[0] > 0 && tau[0] <= tau[1])) r.Fail("flicker_tau_s", "needs 0 < min <= max");
  e.flicker_tau_min_s = tau[0];
  e.flicker_tau_max_s = tau[1];
  e.scale_factor_sigma_ppm = r.Number("scale_factor_ppm", e.scale_factor_sigma_ppm);
  e.scale_temperature_ppm_per_c =
      r.Number("scale_temperature_ppm_per_c", e.scale_temperature_ppm_per_c);
  e.misalignment_sigma_rad = Scaled(r, "misalignment_deg", e.misalignment_sigma_rad, kDeg);
  e.bandwidth_hz = r.Number("bandwidth_hz", e.bandwidth_hz);
  t.counts.range = Scaled(r, u.range_key, t.counts.range, u.range);
  t.counts.count_lsb = Scaled(r, u.lsb_key, t.counts.count_lsb, u.lsb);
}

void ReadGyroTerms(const YamlReader& y, mcu::TriadSpec& t) {
  const KeyedReader<kGyro> r(y);
  ReadTriadTerms(r, kGyroUnits, t);
  if (r.Has("g_sensitivity_dps_per_g"))
    t.error.g_sensitivity_radps_per_mps2 = r.Number("g_sensitivity_dps_per_g", 0) * kDeg / kG0Rough;
}

void ReadMount(const YamlReader& y, mcu::MountResonance& m) {
  const KeyedReader<kMount> r(y);
  r.CheckKeys();
  m.frequency_hz = r.Number("frequency_hz", m.frequency_hz);
  m.damping_ratio = r.Number("damping_ratio", m.damping_ratio);
}

void ReadTimeTag(const YamlReader& y, mcu::TimeTagSpec& t) {
  const KeyedReader<kTimeTag> r(y);
  r.CheckKeys();
  t.latency_s = r.Number("latency_s", t.latency_s);
  t.jitter_s = r.Number("jitter_s", t.jitter_s);
  t.imu_clock_ppm = r.Number("imu_clock_ppm", t.imu_clock_ppm);
}

// The rough model's rates and cutoffs against each other and the output rate.
void CheckRates(const KeyedReader<kRough>& r, const mcu::McuConfig& c) {
  const mcu::RoughImuSpec& s = c.rough;
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

}  // namespace

void ReadMcuRough(const YamlReader& y, mcu::McuConfig& c) {
  const KeyedReader<kRough> r(y);
  r.CheckKeys();
  mcu::RoughImuSpec& s = c.rough;
  s.internal_rate_hz = r.Number("internal_rate_hz", s.internal_rate_hz);
  s.accel_aaf_hz = r.Number("accel_aaf_hz", s.accel_aaf_hz);
  s.gyro_aaf_hz = r.Number("gyro_aaf_hz", s.gyro_aaf_hz);
  if (auto p = r.OptionalChild("rpm")) s.rpm_profile = ReadProfile<kRpmPoint>(*p);
  if (auto o = r.OptionalChild("engine_orders")) ReadOrders(*o, s.engine_orders);
  if (auto b = r.OptionalChild("ride")) ReadRide(*b, s.ride);
  s.ride_reference_speed_mps = r.Number("ride_reference_speed_mps", s.ride_reference_speed_mps);
  if (auto m = r.OptionalChild("mount")) ReadMount(*m, s.mount);
  if (auto p = r.OptionalChild("temperature_profile"))
    s.temperature_profile = ReadProfile<kTemperaturePoint>(*p);
  if (auto t = r.OptionalChild("time_tag")) ReadTimeTag(*t, s.time_tag);
  if (auto a = r.OptionalChild("accel"))
    ReadTriadTerms(KeyedReader<kAccel>(*a), kAccelUnits, c.profile.accel);
  if (auto g = r.OptionalChild("gyro")) ReadGyroTerms(*g, c.profile.gyro);
  CheckRates(r, c);
}

extern const KeySection kMcuRoughSection{
    "mcu.rough",
    "the field-rough IMU model (vectors/mcu/imu_error_model.md): a key replaces the profile's "
    "value, a list the whole list",
    kRough};
extern const KeySection kMcuRpmSection{"mcu.rough.rpm[]", "a point of the crank speed profile",
                                       kRpmPoint};
extern const KeySection kMcuEngineOrderSection{"mcu.rough.engine_orders[]", "one engine order",
                                               kEngineOrder};
extern const KeySection kMcuRideSection{"mcu.rough.ride[]", "one band of ride vibration",
                                        kRideBand};
extern const KeySection kMcuMountSection{
    "mcu.rough.mount", "the mount as a base-excited single-degree-of-freedom oscillator", kMount};
extern const KeySection kMcuTemperaturePointSection{"mcu.rough.temperature_profile[]",
                                                    "a point of the board temperature profile",
                                                    kTemperaturePoint};
extern const KeySection kMcuTimeTagSection{
    "mcu.rough.time_tag", "the sample's time tag: the MCU tags a sample later than it measured",
    kTimeTag};
extern const KeySection kMcuAccelSection{"mcu.rough.accel", "the accelerometer's error terms",
                                         kAccel};
extern const KeySection kMcuGyroSection{"mcu.rough.gyro", "the gyro's error terms", kGyro};

}  // namespace hil::harness

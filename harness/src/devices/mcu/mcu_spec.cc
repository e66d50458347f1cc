// The scenario's `mcu:` section: the IMU board's microcontroller (firmware_emu/mcu). Every key with
// its default and source: mcu_keys.h (docs/scenario_reference.md); examples in
// vectors/mcu/README.md.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/mcu/field_profiles.h"

#include "mcu.h"
#include "mcu_keys.h"

namespace hil::harness {
namespace {

using mcu_keys::kCan;
using mcu_keys::kMagnetic;
using mcu_keys::kMcu;
using mcu_keys::kMcuFault;
using mcu_keys::kTemperature;
using mcu_keys::kVibrationTone;

template <const auto& T>
Eigen::Vector3d Vec(const KeyedReader<T>& r, typename KeyedReader<T>::Key key,
                    const Eigen::Vector3d& fallback) {
  const auto v = r.Doubles(key, 3, {fallback.x(), fallback.y(), fallback.z()});
  return {v[0], v[1], v[2]};
}

void ReadCan(const YamlReader& y, mcu::CanOutputConfig& c) {
  const KeyedReader<kCan> r(y);
  r.CheckKeys();
  c.enabled = r.Bool("enabled", true);
  c.address.source_address =
      static_cast<std::uint8_t>(r.Integer("source_address", c.address.source_address));
  c.address.priority = static_cast<std::uint8_t>(r.Integer("priority", c.address.priority));
  c.ari_every = static_cast<int>(r.Integer("ari_every", c.ari_every));
  c.accs_every = static_cast<int>(r.Integer("accs_every", c.accs_every));
  c.ssi2_every = static_cast<int>(r.Integer("ssi2_every", c.ssi2_every));
  c.time_pulse = r.Bool("time_pulse", c.time_pulse);
  c.latency_s = r.Number("latency_s", c.latency_s);
}

void ReadFaults(const YamlReader& r, std::vector<mcu::McuFault>& faults) {
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kMcuFault> e(y);
    e.CheckKeys();
    if (!e.Has("kind"))
      e.Fail("kind", "required: drop_frames, sequence_jump, corrupt_bytes, stuck_sensor or reset");
    mcu::McuFault f;
    f.kind = e.Choice("kind", mcu::FaultKind::kDropFrames);  // the table's order is the enum's
    f.start = TimeFromSeconds(e.Number("start_s", 0));
    f.duration = DurationFromSeconds(e.Number("duration_s", 0));
    f.probability = e.Number("probability", 1);
    f.amount = static_cast<int>(e.Integer("amount", 1));
    f.sensor = e.Choice("sensor", "all");
    const bool needs_duration = f.kind == mcu::FaultKind::kDropFrames ||
                                f.kind == mcu::FaultKind::kCorruptBytes ||
                                f.kind == mcu::FaultKind::kStuckSensor;
    if (needs_duration && f.duration <= Duration{0})
      e.Fail("duration_s", "this fault needs a positive duration_s");
    faults.push_back(f);
  }
}

void ReadVibration(const YamlReader& r, std::vector<mcu::VibrationTone>& tones) {
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kVibrationTone> e(y);
    e.CheckKeys();
    mcu::VibrationTone t;
    t.frequency_hz = e.Number("frequency_hz", 0);
    t.accel_amplitude_mps2 = Vec(e, "accel_amplitude_mps2", Eigen::Vector3d::Zero());
    t.gyro_amplitude_radps = Vec(e, "gyro_amplitude_dps", Eigen::Vector3d::Zero()) * kDeg;
    tones.push_back(t);
  }
}

void ReadMagnetic(const YamlReader& y, mcu::MagneticSpec& m) {
  const KeyedReader<kMagnetic> g(y);
  g.CheckKeys();
  m.field_N_uT = Vec(g, "field_enu_uT", m.field_N_uT);
  m.hard_iron_I_uT = Vec(g, "hard_iron_uT", m.hard_iron_I_uT);
  const auto s = g.Doubles("soft_iron", 9, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  for (int i = 0; i < 9; ++i) m.soft_iron(i / 3, i % 3) = s[static_cast<std::size_t>(i)];
}

void ReadTemperature(const YamlReader& y, mcu::McuConfig& c) {
  const KeyedReader<kTemperature> t(y);
  t.CheckKeys();
  c.temperature_c = t.Number("start_c", c.temperature_c);
  c.temperature_rate_c_per_h = t.Number("rate_c_per_h", c.temperature_rate_c_per_h);
}

// profile or imu_profile (issue 41: a named field profile: sensor + its rough terms + the
// vehicle's vibration)
void ReadProfile(const KeyedReader<kMcu>& r, mcu::McuConfig& c) {
  if (r.Has("imu_profile")) {
    if (r.Has("profile")) r.Fail("imu_profile", "give either profile or imu_profile, not both");
    const mcu::FieldProfile fp = mcu::FieldProfileByName(r.Choice("imu_profile", ""));
    c.profile = fp.sensor;
    c.rough = fp.rough;
  } else {
    c.profile = mcu::ProfileByName(r.Choice("profile", "razor-v13"));
  }
}

void ReadMcu(const YamlReader& y, McuDeviceSpec& m) {
  const KeyedReader<kMcu> r(y);
  r.CheckKeys();
  m.enabled = true;
  mcu::McuConfig& c = m.config;
  ReadProfile(r, c);
  c.baud = static_cast<int>(r.Integer("baud", c.profile.default_baud));
  m.link = r.String("link", m.link);
  if (m.link.empty() || m.link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as ttyIMU");
  c.format = r.Choice("format", mcu::SerialFormat::kBinary);  // the table's order is the enum's
  m.imu_rate_is_default = !r.Has("imu_rate_hz");
  c.imu_rate_hz = r.Number("imu_rate_hz", c.imu_rate_hz);
  c.mag_rate_hz = r.Number("mag_rate_hz", c.profile.mag_rate_hz);
  c.crystal_ppm = r.Number("crystal_ppm", c.crystal_ppm);
  c.mag_oscillator_ppm = r.Number("mag_oscillator_ppm", c.mag_oscillator_ppm);
  c.jitter_us = r.Number("jitter_us", c.jitter_us);
  c.output_lag = DurationFromSeconds(r.Number("output_latency_s", ToSeconds(c.output_lag)));
  c.reboot = DurationFromSeconds(r.Number("reboot_s", ToSeconds(c.reboot)));
  c.time_pulse = r.Bool("time_pulse", c.time_pulse);
  m.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(m.tx_buffer_bytes)));
  c.mounting.p_BI_B_m = Vec(r, "lever_arm_m", c.mounting.p_BI_B_m);
  const Eigen::Vector3d rpy = Vec(r, "mounting_rpy_deg", Eigen::Vector3d::Zero()) * kDeg;
  c.mounting.q_BI = Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX());
  if (auto g = r.OptionalChild("magnetic")) ReadMagnetic(*g, c.magnetic);
  if (auto v = r.OptionalChild("vibration")) ReadVibration(*v, c.vibration);
  if (auto t = r.OptionalChild("temperature")) ReadTemperature(*t, c);
  if (auto cn = r.OptionalChild("can")) ReadCan(*cn, c.can);
  if (auto f = r.OptionalChild("faults")) ReadFaults(*f, c.faults);
  if (auto rough = r.OptionalChild("rough")) ReadMcuRough(*rough, c);
}

}  // namespace

void ReadMcuSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("mcu")) ReadMcu(*r, s.mcu);
  s.mcu.config.start_utc = s.start_utc;
  // seed 000: the IMU runs 10 times as fast as the GPS (the gnss row is read before this one)
  if (s.mcu.imu_rate_is_default) s.mcu.config.imu_rate_hz = 10.0 * s.gnss.rate_hz;
}

extern const KeySection kMcuSection{
    "mcu", "the IMU board's microcontroller (firmware_emu/mcu, vectors/mcu/README.md)", kMcu};
extern const KeySection kMcuMagneticSection{"mcu.magnetic", "the compass's magnetic environment",
                                            kMagnetic};
extern const KeySection kMcuVibrationSection{
    "mcu.vibration[]", "one sinusoid the board feels, in its frame", kVibrationTone};
extern const KeySection kMcuTemperatureSection{"mcu.temperature", "the board's temperature",
                                               kTemperature};
extern const KeySection kMcuCanSection{
    "mcu.can", "the J1939 IMU frames on the scenario's can bus (vectors/can/README.md)", kCan};
extern const KeySection kMcuFaultSection{"mcu.faults[]", "one fault of the firmware", kMcuFault};

}  // namespace hil::harness

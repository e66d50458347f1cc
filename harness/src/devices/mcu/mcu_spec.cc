// The scenario's `mcu:` section: the IMU board's microcontroller (firmware_emu/mcu). Format in
// vectors/scenarios/README.md and vectors/mcu/README.md.
#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

#include "hil/firmware_emu/angles.h"
#include "hil/firmware_emu/mcu/field_profiles.h"

#include "mcu.h"

namespace hil::harness {
namespace {

Eigen::Vector3d Vec(const YamlReader& r, const std::string& key, const Eigen::Vector3d& fallback) {
  const auto v = r.Doubles(key, 3, {fallback.x(), fallback.y(), fallback.z()});
  return {v[0], v[1], v[2]};
}

mcu::FaultKind FaultKindOf(const std::string& s) {
  if (s == "drop_frames") return mcu::FaultKind::kDropFrames;
  if (s == "sequence_jump") return mcu::FaultKind::kSequenceJump;
  if (s == "corrupt_bytes") return mcu::FaultKind::kCorruptBytes;
  if (s == "stuck_sensor") return mcu::FaultKind::kStuckSensor;
  return mcu::FaultKind::kReset;
}

void ReadCan(const YamlReader& r, mcu::CanOutputConfig& c) {
  r.CheckKeys({"enabled", "source_address", "priority", "ari_every", "accs_every", "ssi2_every",
               "time_pulse", "latency_s"});
  c.enabled = r.Bool("enabled", true);
  c.address.source_address =
      static_cast<std::uint8_t>(r.Int("source_address", c.address.source_address, 0, 253));
  c.address.priority = static_cast<std::uint8_t>(r.Int("priority", c.address.priority, 0, 7));
  c.ari_every = static_cast<int>(r.Int("ari_every", c.ari_every, 1, 1000));
  c.accs_every = static_cast<int>(r.Int("accs_every", c.accs_every, 1, 1000));
  c.ssi2_every = static_cast<int>(r.Int("ssi2_every", c.ssi2_every, 1, 1000));
  c.time_pulse = r.Bool("time_pulse", c.time_pulse);
  c.latency_s = r.DoubleIn("latency_s", c.latency_s, 0, 0.125);
}

void ReadFaults(const YamlReader& r, std::vector<mcu::McuFault>& faults) {
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"kind", "start_s", "duration_s", "probability", "amount", "sensor"});
    mcu::McuFault f;
    f.kind = FaultKindOf(e.Choice(
        "kind", "", {"drop_frames", "sequence_jump", "corrupt_bytes", "stuck_sensor", "reset"}));
    f.start = TimeFromSeconds(e.DoubleIn("start_s", 0, 0, 7 * 86400));
    f.duration = DurationFromSeconds(e.DoubleIn("duration_s", 0, 0, 7 * 86400));
    f.probability = e.DoubleIn("probability", 1, 0, 1);
    f.amount = static_cast<int>(e.Int("amount", 1, 1, 65535));
    f.sensor = e.Choice("sensor", "all", {"accel", "gyro", "mag", "all"});
    const bool needs_duration = f.kind == mcu::FaultKind::kDropFrames ||
                                f.kind == mcu::FaultKind::kCorruptBytes ||
                                f.kind == mcu::FaultKind::kStuckSensor;
    if (needs_duration && f.duration <= Duration{0})
      e.Fail("duration_s", "this fault needs a positive duration_s");
    faults.push_back(f);
  }
}

void ReadVibration(const YamlReader& r, std::vector<mcu::VibrationTone>& tones) {
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"frequency_hz", "accel_amplitude_mps2", "gyro_amplitude_dps"});
    mcu::VibrationTone t;
    t.frequency_hz = e.DoubleIn("frequency_hz", 0, 0, 5000);
    t.accel_amplitude_mps2 = Vec(e, "accel_amplitude_mps2", Eigen::Vector3d::Zero());
    t.gyro_amplitude_radps = Vec(e, "gyro_amplitude_dps", Eigen::Vector3d::Zero()) * kDeg;
    tones.push_back(t);
  }
}

void ReadMcu(const YamlReader& r, McuDeviceSpec& m) {
  r.CheckKeys({"profile",
               "imu_profile",
               "rough",
               "baud",
               "link",
               "format",
               "imu_rate_hz",
               "mag_rate_hz",
               "crystal_ppm",
               "mag_oscillator_ppm",
               "jitter_us",
               "output_latency_s",
               "reboot_s",
               "time_pulse",
               "tx_buffer_bytes",
               "lever_arm_m",
               "mounting_rpy_deg",
               "magnetic",
               "vibration",
               "temperature",
               "can",
               "faults"});
  m.enabled = true;
  mcu::McuConfig& c = m.config;
  if (r.Has("imu_profile")) {
    // issue 41: a named field profile (sensor + its rough terms + the vehicle's vibration)
    if (r.Has("profile")) r.Fail("imu_profile", "give either profile or imu_profile, not both");
    const mcu::FieldProfile fp =
        mcu::FieldProfileByName(r.Choice("imu_profile", "",
                                         {"razor_small_engine_robot", "consumer_mems_car",
                                          "consumer_mems_tractor_cab", "industrial_mems_tractor"}));
    c.profile = fp.sensor;
    c.rough = fp.rough;
  } else {
    const std::string profile = r.Choice(
        "profile", "razor-v13", {"razor-v13", "consumer-mems", "industrial-mems", "tactical"});
    c.profile = mcu::ProfileByName(profile);
  }
  c.baud = static_cast<int>(r.Int("baud", c.profile.default_baud, 1200, 4000000));
  m.link = r.String("link", m.link);
  if (m.link.empty() || m.link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as ttyIMU");
  const std::string format = r.Choice("format", "binary", {"binary", "razor-raw", "razor-v19"});
  c.format = format == "binary"      ? mcu::SerialFormat::kBinary
             : format == "razor-raw" ? mcu::SerialFormat::kRazorRaw
                                     : mcu::SerialFormat::kRazorV19;
  m.imu_rate_is_default = !r.Has("imu_rate_hz");
  c.imu_rate_hz = r.DoubleIn("imu_rate_hz", c.imu_rate_hz, 0.1, 2000);
  c.mag_rate_hz = r.DoubleIn("mag_rate_hz", c.profile.mag_rate_hz, 0.1, 200);
  c.crystal_ppm = r.DoubleIn("crystal_ppm", c.crystal_ppm, -1000, 1000);
  c.mag_oscillator_ppm = r.DoubleIn("mag_oscillator_ppm", c.mag_oscillator_ppm, -50000, 50000);
  c.jitter_us = r.DoubleIn("jitter_us", c.jitter_us, 0, 10000);
  c.output_lag =
      DurationFromSeconds(r.DoubleIn("output_latency_s", ToSeconds(c.output_lag), 0, 0.5));
  c.reboot = DurationFromSeconds(r.DoubleIn("reboot_s", ToSeconds(c.reboot), 0.001, 60));
  c.time_pulse = r.Bool("time_pulse", c.time_pulse);
  m.tx_buffer_bytes = static_cast<std::size_t>(
      r.Int("tx_buffer_bytes", static_cast<std::int64_t>(m.tx_buffer_bytes), 64, 1 << 20));
  c.mounting.p_BI_B_m = Vec(r, "lever_arm_m", c.mounting.p_BI_B_m);
  const Eigen::Vector3d rpy = Vec(r, "mounting_rpy_deg", Eigen::Vector3d::Zero()) * kDeg;
  c.mounting.q_BI = Eigen::AngleAxisd(rpy.z(), Eigen::Vector3d::UnitZ()) *
                    Eigen::AngleAxisd(rpy.y(), Eigen::Vector3d::UnitY()) *
                    Eigen::AngleAxisd(rpy.x(), Eigen::Vector3d::UnitX());
  if (auto g = r.OptionalChild("magnetic")) {
    g->CheckKeys({"field_enu_uT", "hard_iron_uT", "soft_iron"});
    c.magnetic.field_N_uT = Vec(*g, "field_enu_uT", c.magnetic.field_N_uT);
    c.magnetic.hard_iron_I_uT = Vec(*g, "hard_iron_uT", c.magnetic.hard_iron_I_uT);
    const auto s = g->Doubles("soft_iron", 9, {1, 0, 0, 0, 1, 0, 0, 0, 1});
    for (int i = 0; i < 9; ++i) c.magnetic.soft_iron(i / 3, i % 3) = s[static_cast<std::size_t>(i)];
  }
  if (auto v = r.OptionalChild("vibration")) ReadVibration(*v, c.vibration);
  if (auto t = r.OptionalChild("temperature")) {
    t->CheckKeys({"start_c", "rate_c_per_h"});
    c.temperature_c = t->DoubleIn("start_c", c.temperature_c, -40, 85);
    c.temperature_rate_c_per_h = t->DoubleIn("rate_c_per_h", c.temperature_rate_c_per_h, -100, 100);
  }
  if (auto cn = r.OptionalChild("can")) ReadCan(*cn, c.can);
  if (auto f = r.OptionalChild("faults")) ReadFaults(*f, c.faults);
  if (auto rough = r.OptionalChild("rough")) ReadMcuRough(*rough, c);
}

}  // namespace

void ReadMcuSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("mcu")) ReadMcu(*r, s.mcu);
  s.mcu.config.start_unix_ns = s.start_unix_ns;
  // seed 000: the IMU runs 10 times as fast as the GPS (the gnss row is read before this one)
  if (s.mcu.imu_rate_is_default) s.mcu.config.imu_rate_hz = 10.0 * s.gnss.rate_hz;
}

}  // namespace hil::harness

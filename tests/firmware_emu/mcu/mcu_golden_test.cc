// Golden vectors of the MCU: the binary frame stream, the Razor text streams and the J1939 CAN
// log, each with the engineering values a decoder must read back (within one LSB). The test
// re-creates them byte for byte from a fixed seed; HIL_REGEN_VECTORS=1 rewrites them.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/mcu/mcu_device.h"

#include "frame_reader.h"
#include "golden_file.h"
#include "truth_driver.h"

namespace hil::mcu {
namespace {

constexpr std::uint64_t kSeed = 20130610;
constexpr double kRollAmplitudeRad = 0.05;
constexpr double kRadToDeg = 180.0 / std::numbers::pi;
const char* const kStartUtc = "2013-06-10T08:00:00.300Z";

std::string Fmt(const char* f, double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, f, v);
  return buf;
}
std::string G(double v) { return Fmt("%.9g", v + 0.0); }  // + 0.0: no "-0"

McuConfig VectorConfig() {
  McuConfig c;
  c.start_utc = gnss::ParseIsoUtc(kStartUtc);
  c.crystal_ppm = 37.5;
  c.jitter_us = 20;
  c.mounting.p_BI_B_m = Eigen::Vector3d(0.3, 0.0, 1.2);  // on a tube above the rear axle
  c.vibration.push_back(
      {23.0, Eigen::Vector3d(0.3, 0.2, 0.8), Eigen::Vector3d(0.002, 0.002, 0.001)});
  return c;
}

std::string Header(const std::string& what, const McuConfig& c) {
  std::ostringstream h;
  h << "# " << what
    << "\n# Generator: tests/firmware_emu/mcu/mcu_golden_test.cc (HIL_REGEN_VECTORS=1 rewrites)\n"
    << "# Seed: " << kSeed << "  Profile: " << c.profile.name << "  start_utc: " << kStartUtc
    << "  crystal_ppm: " << c.crystal_ppm << "  imu_rate_hz: " << c.imu_rate_hz << "\n"
    << "# Truth: level vehicle turning left at 0.1 rad/s, 0.45 m/s, rolling 0.05 rad at 0.5 Hz; "
       "board lever arm "
       "(0.3, 0, 1.2) m; 23 Hz vibration\n";
  return h.str();
}

// ---- binary frame protocol ----
struct BinaryVector {
  std::string bin;
  std::string csv;
};

BinaryVector MakeBinary(const McuConfig& c, double seconds) {
  McuDevice dev(c, kSeed);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(seconds), kRollAmplitudeRad);
  BinaryVector v;
  v.csv = Header(
      "MCU frame protocol v1 (vectors/mcu/mcu_frame_protocol.md): one row per frame in the .bin",
      c);
  v.csv +=
      "# columns: offset,sequence,type,tick,crc_ok,values...\n"
      "#  IMU_SAMPLE(1): ax_mps2,ay_mps2,az_mps2,gx_radps,gy_radps,gz_radps (raw x STATUS scale)\n"
      "#  MAG_SAMPLE(2): mx_uT,my_uT,mz_uT\n"
      "#  TIME_PULSE(3): gps_week,tow_ms,valid\n"
      "#  STATUS(4): "
      "reset_cause,flags,reset_count,tick_hz,imu_period_ticks,accel_scale,gyro_scale,mag_scale,"
      "profile\n"
      "#  corrupted frames (crc_ok 0) have no values; their sequence/type/tick are the bytes as "
      "read (maybe corrupted)\n"
      "#  dropped frames do not appear (the sequence numbers show the gap)\n";
  double sa = 0, sg = 0, sm = 0;
  for (const SerialMessage& m : out.serial) {
    const test::ReadFrame f = test::ParseFrame(m.bytes);
    std::string row = std::to_string(v.bin.size()) + "," + std::to_string(f.sequence) + "," +
                      std::to_string(f.type) + "," + std::to_string(f.tick) + "," +
                      (f.crc_ok ? "1" : "0");
    v.bin += m.bytes;
    if (!f.crc_ok) {
      v.csv += row + "\n";
      continue;
    }
    switch (f.type) {
      case 4:
        sa = f.F32(12), sg = f.F32(16), sm = f.F32(20);
        row += "," + std::to_string(f.payload[0]) + "," + std::to_string(f.payload[1]) + "," +
               std::to_string(f.U16(2)) + "," + std::to_string(f.U32(4)) + "," +
               std::to_string(f.U32(8)) + "," + G(sa) + "," + G(sg) + "," + G(sm) + "," +
               std::to_string(f.payload[24]);
        break;
      case 1:
        for (int i = 0; i < 3; ++i) row += "," + G(f.I16(2 * static_cast<std::size_t>(i)) * sa);
        for (int i = 0; i < 3; ++i) row += "," + G(f.I16(6 + 2 * static_cast<std::size_t>(i)) * sg);
        break;
      case 2:
        for (int i = 0; i < 3; ++i) row += "," + G(f.I16(2 * static_cast<std::size_t>(i)) * sm);
        break;
      case 3:
        row += "," + std::to_string(f.U16(0)) + "," + std::to_string(f.U32(2)) + "," +
               std::to_string(f.payload[6]);
        break;
      default:
        break;
    }
    v.csv += row + "\n";
  }
  return v;
}

// ---- Razor text ----
BinaryVector MakeText(McuConfig c, SerialFormat format, double seconds) {
  c.format = format;
  McuDevice dev(c, kSeed);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(seconds), kRollAmplitudeRad);
  const ImuProfile& p = c.profile;
  BinaryVector v;
  v.csv = Header(std::string("Razor v13 stock text output, ") +
                     (format == SerialFormat::kRazorRaw ? "raw `$,...,#`" : "v19 `!Data:...#`") +
                     " (vectors/mcu/razor_text_formats.md): one row per line",
                 c);
  v.csv +=
      "# columns: ax_mps2,ay_mps2,az_mps2,gx_radps,gy_radps,gz_radps,mx_uT,my_uT,mz_uT\n"
      "# accel = count x 9.80665/256; gyro = (adc - 382) x (3.3/1024 V)/(3.33 mV/(deg/s)); mag = "
      "count x 100/1300\n";
  for (const SerialMessage& m : out.serial) {
    v.bin += m.bytes;
    std::string body = m.bytes.substr(m.bytes.find_first_of(":,") + 1);
    std::vector<int> n;
    std::size_t pos = 0;
    while (n.size() < 9) {
      std::size_t used = 0;
      n.push_back(std::stoi(body.substr(pos), &used));
      pos += used + 1;
    }
    std::string row;
    for (int i = 0; i < 9; ++i) {
      double x;
      if (i < 3)
        x = n[static_cast<std::size_t>(i)] * p.accel.counts.count_lsb;
      else if (i < 6)
        x = (n[static_cast<std::size_t>(i)] - p.gyro.counts.nominal_zero_count) *
            p.gyro.counts.count_lsb;
      else
        x = n[static_cast<std::size_t>(i)] * p.mag.counts.count_lsb;
      row += (i ? "," : "") + G(x);
    }
    v.csv += row + "\n";
  }
  return v;
}

// ---- CAN (candump -l) ----
std::string CandumpLine(std::int64_t unix_ns, const CanFrame& f) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "(%010llu.%06llu) vcan0 %08X#",
                static_cast<unsigned long long>(unix_ns / 1000000000),
                static_cast<unsigned long long>((unix_ns % 1000000000) / 1000), f.id);
  std::string s = buf;
  for (int i = 0; i < f.len; ++i) {
    std::snprintf(buf, sizeof buf, "%02X", f.data[static_cast<std::size_t>(i)]);
    s += buf;
  }
  return s + "\n";
}

BinaryVector MakeCan(McuConfig c, double seconds) {
  c.can.enabled = true;
  c.can.ssi2_every = 5;
  McuDevice dev(c, kSeed);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(seconds), kRollAmplitudeRad);
  const double sa = c.profile.accel.counts.output_lsb();
  const double sg = c.profile.gyro.counts.output_lsb();
  // serial IMU samples by sample time, for the engineering values behind each CAN frame
  std::vector<std::pair<Time, test::ReadFrame>> imu;
  for (const SerialMessage& m : out.serial) {
    const test::ReadFrame f = test::ParseFrame(m.bytes);
    if (f.type == 1) imu.emplace_back(m.t_ready - c.output_lag, f);
  }
  BinaryVector v;
  v.csv = Header(
      "MCU J1939 CAN frames (vectors/can/README.md, hil_imu.dbc): one row per line of the .candump",
      c);
  v.csv +=
      "# columns: timestamp,id_hex,pgn,values... (engineering values the MCU encoded; decoders "
      "agree within one LSB)\n"
      "#  61482 ARI: pitch_rate_dps,roll_rate_dps,yaw_rate_dps,latency_ms\n"
      "#  61485 ACCS: lateral_mps2,longitudinal_mps2,vertical_mps2,latency_ms\n"
      "#  61481 SSI2: pitch_deg,roll_deg,latency_ms\n"
      "#  65360 HIL_TIME_PULSE: tick,gps_tow_s,gps_week_mod4096\n";
  for (const CanFrame& f : out.can) {
    const std::int64_t unix_ns = ToNs(UtcAt(c.start_utc, f.t));
    v.bin += CandumpLine(unix_ns, f);
    const std::uint32_t pgn = (f.id >> 8) & 0x3FFFF;
    char head[96];
    std::snprintf(head, sizeof head, "%lld.%06lld,%08X,%u",
                  static_cast<long long>(unix_ns / 1000000000),
                  static_cast<long long>((unix_ns % 1000000000) / 1000), f.id, pgn);
    std::string row = head;
    const double latency_ms = f.data[7] * 0.5;
    if (pgn == kPgnHilTimePulse) {
      const std::uint32_t tick = f.data[0] | (f.data[1] << 8) | (f.data[2] << 16) |
                                 (static_cast<std::uint32_t>(f.data[3]) << 24);
      const std::uint32_t hi = f.data[4] | (f.data[5] << 8) | (f.data[6] << 16) |
                               (static_cast<std::uint32_t>(f.data[7]) << 24);
      const gnss::GpsWeekTime g =
          gnss::GpsFrom(UnixTimeFromNs(unix_ns) - DurationFromSeconds(c.can.latency_s));
      row += "," + std::to_string(tick) + "," + std::to_string(g.tow_ns / 1000000000) + "," +
             std::to_string(g.week % 4096);
      EXPECT_EQ(hi & 0xFFFFF, g.tow_ns / 1000000000);
    } else {
      const Time t_sample = f.t - DurationFromSeconds(c.can.latency_s);
      const test::ReadFrame* s = nullptr;
      for (const auto& [t, fr] : imu)
        if (t == t_sample) s = &fr;
      if (s == nullptr) {
        ADD_FAILURE() << "CAN frame without serial sample";
        continue;
      }
      const Eigen::Vector3d acc(s->I16(0) * sa, s->I16(2) * sa, s->I16(4) * sa);
      const Eigen::Vector3d w(s->I16(6) * sg, s->I16(8) * sg, s->I16(10) * sg);
      if (pgn == kPgnAri) {
        row +=
            "," + G(-w.y() * kRadToDeg) + "," + G(w.x() * kRadToDeg) + "," + G(w.z() * kRadToDeg);
      } else if (pgn == kPgnAccs) {
        row += "," + G(acc.y()) + "," + G(acc.x()) + "," + G(acc.z());
      } else {
        const Eigen::Vector2d pr = PitchRollDegFromSpecificForce(acc);
        row += "," + G(pr[0]) + "," + G(pr[1]);
      }
      row += "," + G(latency_ms);
    }
    v.csv += row + "\n";
  }
  return v;
}

// ---- compare or regenerate (tests/support/golden_file.h) ----
void CheckOrWrite(const std::string& rel, const std::string& content) {
  hil::test::CheckOrWriteGolden(rel, content);
}

TEST(McuGoldenTest, RazorBinaryStream) {
  const BinaryVector v = MakeBinary(VectorConfig(), 5.0);
  CheckOrWrite("vectors/mcu/razor_v13_binary.bin", v.bin);
  CheckOrWrite("vectors/mcu/razor_v13_binary.expected.csv", v.csv);
}

TEST(McuGoldenTest, RazorBinaryStreamWithFirmwareFaults) {
  McuConfig c = VectorConfig();
  c.faults.push_back(
      {FaultKind::kDropFrames, TimeFromSeconds(1.0), DurationFromSeconds(0.3), 1.0, 1, "all"});
  c.faults.push_back(
      {FaultKind::kSequenceJump, TimeFromSeconds(2.0), DurationFromSeconds(0), 1.0, 1000, "all"});
  c.faults.push_back(
      {FaultKind::kCorruptBytes, TimeFromSeconds(2.5), DurationFromSeconds(0.5), 0.5, 1, "all"});
  c.faults.push_back(
      {FaultKind::kStuckSensor, TimeFromSeconds(3.0), DurationFromSeconds(0.5), 1.0, 1, "accel"});
  c.faults.push_back(
      {FaultKind::kReset, TimeFromSeconds(4.0), DurationFromSeconds(0), 1.0, 1, "all"});
  const BinaryVector v = MakeBinary(c, 6.0);
  CheckOrWrite("vectors/mcu/razor_v13_faults.bin", v.bin);
  CheckOrWrite("vectors/mcu/razor_v13_faults.expected.csv", v.csv);
}

TEST(McuGoldenTest, TacticalBinaryStream) {
  McuConfig c = VectorConfig();
  c.profile = ProfileByName("tactical");
  c.imu_rate_hz = 100;
  c.baud = 115200;
  const BinaryVector v = MakeBinary(c, 2.0);
  CheckOrWrite("vectors/mcu/tactical_100hz_binary.bin", v.bin);
  CheckOrWrite("vectors/mcu/tactical_100hz_binary.expected.csv", v.csv);
}

TEST(McuGoldenTest, RazorTextStreams) {
  const BinaryVector raw = MakeText(VectorConfig(), SerialFormat::kRazorRaw, 3.0);
  CheckOrWrite("vectors/mcu/razor_v13_raw.txt", raw.bin);
  CheckOrWrite("vectors/mcu/razor_v13_raw.expected.csv", raw.csv);
  const BinaryVector v19 = MakeText(VectorConfig(), SerialFormat::kRazorV19, 3.0);
  CheckOrWrite("vectors/mcu/razor_v13_v19.txt", v19.bin);
  CheckOrWrite("vectors/mcu/razor_v13_v19.expected.csv", v19.csv);
}

TEST(McuGoldenTest, J1939CanLog) {
  const BinaryVector v = MakeCan(VectorConfig(), 3.0);
  CheckOrWrite("vectors/can/mcu_j1939.candump", v.bin);
  CheckOrWrite("vectors/can/mcu_j1939.expected.csv", v.csv);
}

}  // namespace
}  // namespace hil::mcu

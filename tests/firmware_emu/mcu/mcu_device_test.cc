// Behaviour of the emulated microcontroller: clock and sampling, GPS time-pulse latching, the
// frame sequence, CAN output, Razor text output and the firmware fault timeline.
#include "hil/firmware_emu/mcu/mcu_device.h"

#include <cmath>
#include <regex>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"

#include "frame_reader.h"
#include "truth_driver.h"

namespace hil::mcu {
namespace {

using test::ParseFrame;
using test::ReadFrame;

const UnixTime kStartUtc = gnss::ParseIsoUtc("2013-06-10T08:00:00.300Z");

McuConfig BaseConfig() {
  McuConfig c;
  c.start_utc = kStartUtc;
  return c;
}

struct Received {
  ReadFrame frame;
  Time t_ready;
};

std::vector<Received> Frames(const DeviceOutput& out) {
  std::vector<Received> r;
  for (const SerialMessage& m : out.serial) r.push_back({ParseFrame(m.bytes), m.t_ready});
  return r;
}

std::vector<Received> OfType(const std::vector<Received>& all, MessageType type) {
  std::vector<Received> r;
  for (const Received& x : all)
    if (x.frame.type == static_cast<std::uint8_t>(type)) r.push_back(x);
  return r;
}

TEST(McuDeviceTest, StartsWithPowerOnStatusAndCountsEveryFrame) {
  McuDevice dev(BaseConfig(), 1);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(3.0)));
  ASSERT_GT(frames.size(), 30u);
  const ReadFrame& s = frames.front().frame;
  ASSERT_EQ(s.type, static_cast<std::uint8_t>(MessageType::kStatus));
  EXPECT_EQ(s.sequence, 0);
  EXPECT_EQ(s.payload[0], 0);  // power-on
  EXPECT_EQ(s.U16(2), 0);      // reset count
  EXPECT_EQ(s.U32(4), 1000000u);
  EXPECT_EQ(s.U32(8), 100000u);  // 10 Hz
  EXPECT_FLOAT_EQ(s.F32(12), static_cast<float>(9.80665 / 256.0));
  EXPECT_EQ(s.payload[24], 0);  // razor-v13
  for (std::size_t i = 0; i < frames.size(); ++i) {
    EXPECT_TRUE(frames[i].frame.crc_ok);
    EXPECT_EQ(frames[i].frame.sequence, i);
  }
  EXPECT_EQ(OfType(frames, MessageType::kImuSample).size(), 30u);
  EXPECT_EQ(OfType(frames, MessageType::kMagSample).size(), 30u);
}

TEST(McuDeviceTest, SamplesRunOnTheCrystalAndLatchTheTimePulse) {
  McuConfig c = BaseConfig();
  c.crystal_ppm = 100;
  McuDevice dev(c, 2);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(5.0)));
  const auto imu = OfType(frames, MessageType::kImuSample);
  ASSERT_GE(imu.size(), 40u);
  for (std::size_t i = 1; i < imu.size(); ++i) {
    // 100 000 ticks of a 1.0001 MHz crystal = 99 990.001 µs of true time
    EXPECT_NEAR(static_cast<double>((imu[i].t_ready - imu[i - 1].t_ready).count()), 99990001.0,
                1.0);
    EXPECT_NEAR(static_cast<double>(imu[i].frame.tick - imu[i - 1].frame.tick), 100000.0, 1.0);
  }
  const auto pulses = OfType(frames, MessageType::kTimePulse);
  ASSERT_EQ(pulses.size(), 5u);  // at 0.7, 1.7, … 4.7 s
  for (std::size_t i = 0; i < pulses.size(); ++i) {
    const Time t_edge = pulses[i].t_ready - c.output_lag;
    EXPECT_EQ(ToNs(t_edge), 700000000 + static_cast<std::int64_t>(i) * 1000000000);
    const gnss::GpsWeekTime g = gnss::GpsFrom(UtcAt(kStartUtc, t_edge));
    EXPECT_EQ(g.tow_ns % 1000000000, 0);
    EXPECT_EQ(pulses[i].frame.U16(0), g.week);
    EXPECT_EQ(pulses[i].frame.U32(2), g.tow_ns / 1000000);
    EXPECT_EQ(pulses[i].frame.payload[6], 1);
    EXPECT_EQ(pulses[i].frame.tick, dev.TickAt(t_edge));
    if (i > 0) {
      EXPECT_NEAR(static_cast<double>(pulses[i].frame.tick - pulses[i - 1].frame.tick), 1000100.0,
                  1.0);
      EXPECT_EQ(pulses[i].frame.U32(2) - pulses[i - 1].frame.U32(2), 1000u);
    }
  }
  // a STATUS follows each pulse and reports it
  const auto status = OfType(frames, MessageType::kStatus);
  ASSERT_EQ(status.size(), 6u);
  EXPECT_EQ(status[1].frame.payload[1] & 1, 1);
}

TEST(McuDeviceTest, JitterDelaysSamplesWithinItsBound) {
  McuConfig c = BaseConfig();
  c.jitter_us = 50;
  McuDevice dev(c, 3);
  const auto imu =
      OfType(Frames(test::RunDevice(dev, TimeFromSeconds(3.0))), MessageType::kImuSample);
  bool any_late = false;
  for (std::size_t i = 0; i < imu.size(); ++i) {
    const std::int64_t nominal = 10000000 + static_cast<std::int64_t>(i) * 100000000 + 500000;
    const std::int64_t late = ToNs(imu[i].t_ready) - nominal;
    EXPECT_GE(late, 0);
    EXPECT_LE(late, 50000);
    any_late = any_late || late > 1000;
  }
  EXPECT_TRUE(any_late);
}

TEST(McuDeviceTest, ResetRestartsTickAndSequence) {
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kReset, TimeFromSeconds(2.05), DurationFromSeconds(0), 1, 1, "all"});
  McuDevice dev(c, 4);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(4.0)));
  std::size_t boot = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const double t = ToSeconds(frames[i].t_ready);
    EXPECT_FALSE(t > 2.0506 && t < 2.25) << "frame while the MCU reboots at " << t;
    if (frames[i].frame.sequence == 0) boot = i;
  }
  ASSERT_GT(boot, 0u);
  const ReadFrame& s = frames[boot].frame;
  EXPECT_EQ(s.type, static_cast<std::uint8_t>(MessageType::kStatus));
  EXPECT_EQ(s.payload[0], 3);  // external reset
  EXPECT_EQ(s.U16(2), 1);
  EXPECT_LT(s.tick, 10u);
  EXPECT_EQ(frames[boot + 1].frame.sequence, 1);
  EXPECT_EQ(frames[boot + 1].frame.type, static_cast<std::uint8_t>(MessageType::kImuSample));
  EXPECT_NEAR(frames[boot + 1].frame.tick, 10000.0, 1.0);
  EXPECT_EQ(dev.stats().resets, 1u);
  const Device& as_device = dev;  // what the run's report reads, through the Device interface
  EXPECT_EQ(as_device.statistics().resets, 1u);
}

TEST(McuDeviceTest, AResetWithADurationStaysSilentThatLong) {
  // the scenario's global mcu_reset {start_s, end_s}: a brown-out of end - start seconds
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kReset, TimeFromSeconds(2.05), DurationFromSeconds(1.5), 1, 1, "all"});
  McuDevice dev(c, 4);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(5.0)));
  std::size_t boot = 0;
  double last_before = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const double t = ToSeconds(frames[i].t_ready);
    EXPECT_FALSE(t > 2.0506 && t < 3.55) << "frame while the MCU is down at " << t;
    if (t < 2.06) last_before = t;
    if (frames[i].frame.sequence == 0 && boot == 0) boot = i;
  }
  ASSERT_GT(boot, 0u);
  EXPECT_NEAR(ToSeconds(frames[boot].t_ready), 3.55, 0.001)
      << "boot STATUS right after the silent gap";
  EXPECT_GT(last_before, 1.9);
  EXPECT_LT(frames[boot].frame.tick, 10u);
  EXPECT_EQ(dev.stats().resets, 1u);
}

TEST(McuDeviceTest, DroppedFramesLeaveASequenceGap) {
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kDropFrames, TimeFromSeconds(1.0), DurationFromSeconds(0.5), 1.0, 1, "all"});
  McuDevice dev(c, 5);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(3.0)));
  std::uint64_t missing = 0;
  for (std::size_t i = 1; i < frames.size(); ++i)
    missing +=
        static_cast<std::uint16_t>(frames[i].frame.sequence - frames[i - 1].frame.sequence - 1);
  EXPECT_EQ(missing, dev.stats().frames_dropped);
  EXPECT_GE(missing, 10u);  // 5 IMU + 5 MAG + pulse + status
}

TEST(McuDeviceTest, SequenceJumpAdvancesTheCounter) {
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kSequenceJump, TimeFromSeconds(1.5), DurationFromSeconds(0), 1, 100, "all"});
  McuDevice dev(c, 6);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(3.0)));
  int jumps = 0;
  for (std::size_t i = 1; i < frames.size(); ++i) {
    const int d =
        static_cast<std::uint16_t>(frames[i].frame.sequence - frames[i - 1].frame.sequence);
    if (d == 101)
      ++jumps;
    else
      EXPECT_EQ(d, 1);
  }
  EXPECT_EQ(jumps, 1);
}

TEST(McuDeviceTest, CorruptedBytesFailTheCrc) {
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kCorruptBytes, TimeFromSeconds(1.0), DurationFromSeconds(1.0), 1.0, 1, "all"});
  McuDevice dev(c, 7);
  const auto frames = Frames(test::RunDevice(dev, TimeFromSeconds(3.0)));
  std::uint64_t bad = 0;
  for (const Received& r : frames) bad += r.frame.crc_ok ? 0 : 1;
  EXPECT_EQ(bad, dev.stats().frames_corrupted);
  EXPECT_GE(bad, 20u);
}

TEST(McuDeviceTest, StuckGyroRepeatsItsCounts) {
  McuConfig c = BaseConfig();
  c.faults.push_back(
      {FaultKind::kStuckSensor, TimeFromSeconds(1.0), DurationFromSeconds(1.0), 1.0, 1, "gyro"});
  McuDevice dev(c, 8);
  const auto imu =
      OfType(Frames(test::RunDevice(dev, TimeFromSeconds(3.0), 0.2)), MessageType::kImuSample);
  std::vector<std::vector<std::uint8_t>> gyro_in_window;
  int accel_changes = 0;
  for (std::size_t i = 0; i < imu.size(); ++i) {
    const double t = ToSeconds(imu[i].t_ready);
    if (t > 1.0 && t < 2.0) {
      gyro_in_window.emplace_back(imu[i].frame.payload.begin() + 6, imu[i].frame.payload.end());
      if (i > 0 && !std::equal(imu[i].frame.payload.begin(), imu[i].frame.payload.begin() + 6,
                               imu[i - 1].frame.payload.begin()))
        ++accel_changes;
    }
  }
  ASSERT_GE(gyro_in_window.size(), 9u);
  for (const auto& g : gyro_in_window) EXPECT_EQ(g, gyro_in_window.front());
  EXPECT_GT(accel_changes, 5);
}

TEST(McuDeviceTest, CanFramesCarryTheSerialSampleAtSampleTimePlusLatency) {
  McuConfig c = BaseConfig();
  c.profile = ProfileByName("tactical");
  c.can.enabled = true;
  c.can.ssi2_every = 2;
  McuDevice dev(c, 9);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(3.0));
  const auto imu = OfType(Frames(out), MessageType::kImuSample);
  int ari = 0, accs = 0, ssi2 = 0, tp = 0;
  for (const CanFrame& f : out.can) {
    ASSERT_TRUE(f.extended);
    ASSERT_EQ(f.len, 8);
    const std::uint32_t pgn = (f.id >> 8) & 0x3FFFF;
    EXPECT_EQ(f.id & 0xFF, 0xE2u);
    if (pgn == kPgnHilTimePulse) {
      ++tp;
      continue;
    }
    // the matching serial sample: same true time (serial ready at +0.5 ms, CAN at +1 ms)
    const Time t_sample = f.t - DurationFromSeconds(c.can.latency_s);
    const Received* match = nullptr;
    for (const Received& r : imu)
      if (r.t_ready - c.output_lag == t_sample) match = &r;
    ASSERT_NE(match, nullptr);
    const double acc_lsb = 9.80665 / 8000.0, gyro_lsb_deg = 0.01;
    auto u16 = [&](int at) { return f.data[at] | (f.data[at + 1] << 8); };
    if (pgn == kPgnAri) {
      ++ari;
      EXPECT_NEAR(u16(4) / 128.0 - 250.0, match->frame.I16(10) * gyro_lsb_deg, 0.5 / 128.0 + 1e-9);
      EXPECT_NEAR(u16(0) / 128.0 - 250.0, -match->frame.I16(8) * gyro_lsb_deg, 0.5 / 128.0 + 1e-9);
      EXPECT_NEAR(u16(4) / 128.0 - 250.0, 0.1 * 180 / 3.141592653589793,
                  0.1);  // yaw rate of the truth
    } else if (pgn == kPgnAccs) {
      ++accs;
      EXPECT_NEAR(u16(4) * 0.01 - 320.0, match->frame.I16(4) * acc_lsb, 0.005 + 1e-9);
      EXPECT_NEAR(u16(0) * 0.01 - 320.0, match->frame.I16(2) * acc_lsb, 0.005 + 1e-9);
    } else if (pgn == kPgnSsi2) {
      ++ssi2;
    } else {
      ADD_FAILURE() << "unexpected PGN " << pgn;
    }
  }
  EXPECT_EQ(ari, 30);
  EXPECT_EQ(accs, 30);
  EXPECT_EQ(ssi2, 15);
  EXPECT_EQ(tp, 3);
}

TEST(McuDeviceTest, RazorRawTextLinesCarryRegisterAndAdcCounts) {
  McuConfig c = BaseConfig();
  c.format = SerialFormat::kRazorRaw;
  McuDevice dev(c, 10);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(2.0));
  ASSERT_EQ(out.serial.size(), 20u);  // text lines only: no pulse or status frames
  const std::regex line(
      R"(^\$,(-?\d+),(-?\d+),(-?\d+),(\d+),(\d+),(\d+),(-?\d+),(-?\d+),(-?\d+),#\r\n$)");
  for (std::size_t i = 1; i < out.serial.size(); ++i) {
    std::smatch m;
    ASSERT_TRUE(std::regex_match(out.serial[i].bytes, m, line)) << out.serial[i].bytes;
    EXPECT_NEAR(std::stoi(m[3]), 256, 60);  // +1 g on z in 3.9 mg counts
    for (int k = 4; k <= 6; ++k)
      EXPECT_NEAR(std::stoi(m[k]), 382, 25);                     // 10-bit ADC near zero rate
    EXPECT_NEAR(std::stoi(m[9]), -40.0 / (100.0 / 1300.0), 40);  // 40 µT down → −520 counts
  }
}

TEST(McuDeviceTest, RazorV19TextUsesItsFraming) {
  McuConfig c = BaseConfig();
  c.format = SerialFormat::kRazorV19;
  McuDevice dev(c, 10);
  const DeviceOutput out = test::RunDevice(dev, TimeFromSeconds(1.0));
  ASSERT_FALSE(out.serial.empty());
  EXPECT_TRUE(
      std::regex_match(out.serial.back().bytes, std::regex(R"(^!Data:(-?\d+,){8}-?\d+#\n\r$)")));
}

TEST(McuDeviceTest, SameSeedSameBytesOtherSeedOtherBytes) {
  McuConfig c = BaseConfig();
  c.can.enabled = true;
  McuDevice a(c, 11), b(c, 11), d(c, 12);
  const auto oa = test::RunDevice(a, TimeFromSeconds(2.0));
  const auto ob = test::RunDevice(b, TimeFromSeconds(2.0));
  const auto od = test::RunDevice(d, TimeFromSeconds(2.0));
  ASSERT_EQ(oa.serial.size(), ob.serial.size());
  bool differs = false;
  for (std::size_t i = 0; i < oa.serial.size(); ++i) {
    EXPECT_EQ(oa.serial[i].bytes, ob.serial[i].bytes);
    differs = differs || oa.serial[i].bytes != od.serial[i].bytes;
  }
  EXPECT_TRUE(differs);
}

TEST(McuDeviceTest, RejectsInvalidRates) {
  McuConfig c = BaseConfig();
  c.imu_rate_hz = 0;
  EXPECT_THROW(McuDevice(c, 1), std::invalid_argument);
}

}  // namespace
}  // namespace hil::mcu

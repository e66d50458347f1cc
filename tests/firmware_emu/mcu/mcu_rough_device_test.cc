// The MCU with issue 41's rough model: the time tag (a sample tagged and sent `latency` after it
// was sensed, its counts unchanged), the IMU's own oscillator, every field profile running and
// deterministic, and the vibration front end reaching the frames.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/mcu/field_profiles.h"
#include "hil/firmware_emu/mcu/mcu_device.h"

#include "frame_reader.h"
#include "truth_driver.h"

namespace hil::mcu {
namespace {

using test::ParseFrame;
using test::ReadFrame;

struct Imu {
  ReadFrame frame;
  Time t_ready;
};

std::vector<Imu> ImuFrames(const DeviceOutput& out) {
  std::vector<Imu> r;
  for (const SerialMessage& m : out.serial) {
    const ReadFrame f = ParseFrame(m.bytes);
    if (f.type == static_cast<std::uint8_t>(MessageType::kImuSample)) r.push_back({f, m.t_ready});
  }
  return r;
}

McuConfig Config() {
  McuConfig c;
  c.start_utc = gnss::ParseIsoUtc("2019-05-14T02:00:00Z");
  c.imu_rate_hz = 100;
  return c;
}

TEST(McuRoughDeviceTest, ALaggedTimeTagCarriesTheSameCountsLater) {
  McuConfig c = Config();
  McuDevice plain(c, 4);
  c.rough.time_tag.latency_s = 0.1;
  McuDevice lagged(c, 4);
  const auto a = ImuFrames(test::RunDevice(plain, TimeFromSeconds(3.0), 0.05));
  const auto b = ImuFrames(test::RunDevice(lagged, TimeFromSeconds(3.0), 0.05));
  ASSERT_GT(a.size(), 250u);
  ASSERT_GT(b.size(), 250u);
  for (std::size_t i = 0; i < b.size(); ++i) {
    EXPECT_EQ(a[i].frame.payload, b[i].frame.payload)
        << i;  // the sample sensed at the same instant
    EXPECT_NEAR(static_cast<double>(b[i].frame.tick - a[i].frame.tick), 100000.0, 1.0);
    EXPECT_EQ((b[i].t_ready - a[i].t_ready).count(), 100000000);
  }
}

TEST(McuRoughDeviceTest, TagJitterOnlyDelaysAndNeverReorders) {
  McuConfig c = Config();
  McuDevice plain(c, 5);
  c.rough.time_tag.latency_s = 0.02;
  c.rough.time_tag.jitter_s = 0.015;  // longer than a sample period: tags must stay in order
  McuDevice lagged(c, 5);
  const auto a = ImuFrames(test::RunDevice(plain, TimeFromSeconds(2.0)));
  const auto b = ImuFrames(test::RunDevice(lagged, TimeFromSeconds(2.0)));
  ASSERT_GT(b.size(), 150u);
  for (std::size_t i = 0; i < b.size(); ++i) {
    const double lag_us = static_cast<double>(b[i].frame.tick - a[i].frame.tick);
    EXPECT_GE(lag_us, 20000.0 - 1);
    EXPECT_LE(lag_us, 45000.0 + 1);
    if (i > 0) {
      EXPECT_GE(b[i].frame.tick, b[i - 1].frame.tick);
    }
  }
}

TEST(McuRoughDeviceTest, TheImuOscillatorSetsTheSampleSpacing) {
  McuConfig c = Config();
  c.rough.time_tag.imu_clock_ppm = -2000;  // the IMU's ODR 0.2 % slow against the MCU's crystal
  McuDevice dev(c, 6);
  const auto f = ImuFrames(test::RunDevice(dev, TimeFromSeconds(2.0)));
  ASSERT_GT(f.size(), 100u);
  // 10 000 µs nominal of an oscillator 0.2 % slow = 10 020.04 µs, tagged by the MCU's 1 MHz tick
  EXPECT_NEAR(static_cast<double>(f.back().frame.tick - f.front().frame.tick) /
                  static_cast<double>(f.size() - 1),
              10020.04, 1.0);
}

TEST(McuRoughDeviceTest, EveryFieldProfileRunsAndIsDeterministic) {
  for (const std::string& name : FieldProfileNames()) {
    McuConfig c = Config();
    const FieldProfile p = FieldProfileByName(name);
    c.profile = p.sensor;
    c.rough = p.rough;
    McuDevice d1(c, 8), d2(c, 8), d3(c, 9);
    const auto a = test::RunDevice(d1, TimeFromSeconds(1.0));
    const auto b = test::RunDevice(d2, TimeFromSeconds(1.0));
    const auto o = test::RunDevice(d3, TimeFromSeconds(1.0));
    ASSERT_EQ(a.serial.size(), b.serial.size()) << name;
    bool other_differs = false;
    for (std::size_t i = 0; i < a.serial.size(); ++i) {
      EXPECT_EQ(a.serial[i].bytes, b.serial[i].bytes) << name;
      if (i < o.serial.size() && o.serial[i].bytes != a.serial[i].bytes) other_differs = true;
    }
    EXPECT_TRUE(other_differs) << name;
  }
}

TEST(McuRoughDeviceTest, EngineVibrationReachesTheAccelerometerSamples) {
  McuConfig c = Config();
  const FieldProfile p = FieldProfileByName("industrial_mems_tractor");
  c.profile = p.sensor;
  McuDevice still(c, 10);  // same sensor, no front end
  c.rough = p.rough;
  McuDevice shaking(c, 10);
  auto spread = [](const std::vector<Imu>& f) {
    double m = 0, ss = 0;
    for (const Imu& x : f) m += x.frame.I16(4) / static_cast<double>(f.size());
    for (const Imu& x : f) ss += (x.frame.I16(4) - m) * (x.frame.I16(4) - m);
    return std::sqrt(ss / static_cast<double>(f.size()));
  };
  const auto a = ImuFrames(test::RunDevice(still, TimeFromSeconds(5.0)));
  const auto b = ImuFrames(test::RunDevice(shaking, TimeFromSeconds(5.0)));
  const double lsb = 9.80665 / 4000.0;
  // order 2 at 2000 RPM (66.7 Hz), 3 m/s² on z, decimated to 100 Hz: an alias at 33.3 Hz of
  // about 3/√2 m/s² r.m.s., far above the sensor's noise
  EXPECT_LT(spread(a) * lsb, 0.05);
  EXPECT_GT(spread(b) * lsb, 1.5);
}

}  // namespace
}  // namespace hil::mcu

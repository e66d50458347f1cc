// The RPLIDAR emulator: the rotation and sample rates measured from its nodes, ranges against
// hand-computed rays in the greenhouse and the request session (the emulation speed:
// paper001_emulation_benchmark).
#include "hil/firmware_emu/lidar/rplidar_device.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "aisle_truth.h"

namespace hil::lidar {
namespace {

// A vehicle standing at (10, 0.9 + offset) facing east in aisle 0 of the small greenhouse.
TruthSample StandingAt(Time t, double offset_m = 0) {
  TruthSample x;
  x.t = t;
  x.p_NB_N_m = Eigen::Vector3d(10, 0.9 + offset_m, 0);
  return x;
}

std::vector<LidarSample> RunSamples(RplidarDevice& dev, double until_s, std::size_t* nodes_sent,
                                    double offset_m = 0) {
  std::vector<LidarSample> all;
  DeviceOutput out;
  while (dev.next_event_time() <= TimeFromSeconds(until_s)) {
    dev.OnEvent(StandingAt(dev.next_event_time(), offset_m), out);
    all.insert(all.end(), dev.last_samples().begin(), dev.last_samples().end());
  }
  if (nodes_sent != nullptr) {
    *nodes_sent = 0;
    for (const auto& m : out.serial) *nodes_sent += m.bytes.size() / kNodeSize;
  }
  return all;
}

TEST(RplidarDevice, ScanRateAndSampleRateFromTheNodes) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  RplidarDevice dev(RplidarConfig{}, w, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.0), EncodeRequest(0x20), out);
  ASSERT_EQ(out.serial.size(), 1u);  // the descriptor
  std::size_t nodes = 0;
  const auto s = RunSamples(dev, 10.5, &nodes);
  // the first samples come when the motor is stable (0.5 s after power-on)
  EXPECT_EQ(s.front().t, TimeFromSeconds(0.5));
  std::vector<double> starts;
  for (const auto& x : s) {
    if (x.start) starts.push_back(ToSeconds(x.t));
  }
  ASSERT_GE(starts.size(), 50u);
  const double scan_hz = static_cast<double>(starts.size() - 1) / (starts.back() - starts.front());
  const double sample_hz = static_cast<double>(s.size() - 1) / ToSeconds(s.back().t - s.front().t);
  std::printf("A1 default: %.3f scans/s, %.1f samples/s, %.1f samples per turn, %zu nodes sent\n",
              scan_hz, sample_hz, sample_hz / scan_hz, nodes);
  EXPECT_NEAR(scan_hz, 5.5, 0.01);
  EXPECT_NEAR(sample_hz, 2000, 1e-6);
  EXPECT_EQ(nodes, s.size());
}

TEST(RplidarDevice, RangesOfHandComputedBeams) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  RplidarConfig c;
  c.mount.z_m = 0.2;  // below the 0.3 m ridges
  c.range_sigma_fraction = 0;
  c.rotation_hz = 5;  // 400 samples per turn: 0.9° apart
  RplidarDevice dev(c, w, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.0), EncodeRequest(0x21), out);  // force scan: at once
  const auto s = RunSamples(dev, 0.25, nullptr);
  int checked = 0;
  for (const auto& x : s) {
    // θ = 90° clockwise = to the right: ridge 0's side 0.6 m away; 270° = left, ridge 1, 0.6 m;
    // at θ = 63° the beam meets y = 0.3 at 0.6 / sin 63° (samples at 1.8° + k·0.9°)
    for (const double a : {90.0, 270.0, 63.0}) {
      if (std::abs(x.angle_deg - a) < 1e-9) {
        EXPECT_NEAR(x.true_range_m,
                    0.6 / std::sin(a * 3.14159265358979323846 / 180) * (a > 180 ? -1 : 1), 1e-9);
        EXPECT_NEAR(x.measured_m, x.true_range_m, 1e-12);
        EXPECT_GT(x.quality, 0);
        ++checked;
      }
    }
  }
  EXPECT_GE(checked, 3);  // 1.25 turns: 90° comes twice
}

TEST(RplidarDevice, RequestSessionAndReset) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  RplidarDevice dev(RplidarConfig{}, w, 1);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.0), EncodeRequest(0x52) + EncodeRequest(0x50), out);
  ASSERT_EQ(out.serial.size(), 2u);
  EXPECT_EQ(out.serial[0].bytes.size(), 7u + 3u);
  EXPECT_EQ(out.serial[1].bytes.size(), 7u + 20u);
  EXPECT_EQ(static_cast<unsigned char>(out.serial[1].bytes[7]), 0x18);  // A1M8 model
  out.clear();
  dev.OnHostBytes(0, TimeFromSeconds(1.0), EncodeRequest(0x20), out);
  dev.OnHostBytes(0, TimeFromSeconds(1.1), EncodeRequest(0x50), out);  // ignored while scanning
  EXPECT_EQ(dev.stats().ignored, 1u);
  dev.OnHostBytes(0, TimeFromSeconds(1.2), EncodeRequest(0x40), out);  // reset
  EXPECT_EQ(dev.next_event_time(), Time::max());
  EXPECT_EQ(out.serial.back().bytes,
            "RP LIDAR System.\r\nFirmware Ver 1.29 - rc0, HW Ver 7\r\nModel: 18\r\n");
  EXPECT_EQ(out.serial.back().t_ready, TimeFromSeconds(1.21));
  EXPECT_EQ(dev.statistics().resets, 1u);
}

}  // namespace
}  // namespace hil::lidar

// The TF-Luna emulator against its manual: range noise against strength (measured from the
// emitted frames), resolution, invalid readings, output rate and the command session.
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rangefinder/benewake_codec.h"

#include "aisle_truth.h"

namespace hil::rangefinder {
namespace {

// A vehicle standing still at (10, 0.9 + offset) facing east: the right-looking beam from
// y = 0.9 + offset meets ridge 0's side (y = 0.3) square on.
struct StandStill {
  double offset_m = 0;
  TruthSample At(Time t) const {
    TruthSample x;
    x.t = t;
    x.p_NB_N_m = Eigen::Vector3d(10, 0.9 + offset_m, 0);
    return x;
  }
};

struct NoiseFigures {
  double mean_m = 0, std_m = 0, sigma_cfg_m = 0;
  std::size_t n = 0;
};

NoiseFigures MeasureNoise(double side_range_m, std::uint16_t rate_hz) {
  // one ridge (sides y = ±0.3) in a wide house: nothing between the beam and its side
  world::GreenhouseConfig g = test::SmallGreenhouse();
  g.ridge_count = 1;
  g.side_margin_m = 5;
  const world::GreenhouseWorld w(g);
  TfLunaConfig c;
  c.mount = {0, 0, 0.15, -90};
  c.settings.format = OutputFormat::kMm9Byte;
  c.settings.frame_rate_hz = rate_hz;
  TfLunaDevice dev(c, w, 7);
  const StandStill truth{side_range_m - 0.6};  // from y = 0.3 + range
  DeviceOutput out;
  double sum = 0, sum2 = 0;
  NoiseFigures f;
  while (dev.next_event_time() <= TimeFromSeconds(20)) {
    dev.OnEvent(truth.At(dev.next_event_time()), out);
    const DataFields d = DecodeDataFields(out.serial.back().bytes);
    const double e = d.dist * 1e-3 - side_range_m;
    sum += e, sum2 += e * e, ++f.n;
    f.sigma_cfg_m = dev.last_reading().sigma_m;
    out.clear();
  }
  f.mean_m = sum / static_cast<double>(f.n);
  f.std_m = std::sqrt(sum2 / static_cast<double>(f.n) - f.mean_m * f.mean_m);
  return f;
}

TEST(TfLunaDevice, RangeNoiseFollowsTheStrengthTable) {
  // 0.5 m on soil (ρ 0.25): Amp ≈ 8545 → σ 5 mm; 3 m: Amp ≈ 249 → 26.8 mm (log-interpolated
  // between 30 mm at 200 and 20 mm at 400)
  for (const auto& [range, sigma] : {std::pair{0.5, 0.005}, std::pair{3.0, 0.02684}}) {
    const NoiseFigures f = MeasureNoise(range, 100);
    std::printf("range %.2f m at 100 Hz: %zu frames, bias %+.5f m, std %.5f m (configured %.5f)\n",
                range, f.n, f.mean_m, f.std_m, f.sigma_cfg_m);
    EXPECT_NEAR(f.sigma_cfg_m, sigma, 2e-4);
    EXPECT_NEAR(f.std_m, f.sigma_cfg_m, 0.06 * f.sigma_cfg_m);  // 2000 frames: ±3 % (1σ)
    EXPECT_NEAR(f.mean_m, 0, 3 * f.sigma_cfg_m / std::sqrt(static_cast<double>(f.n)) + 5e-4);
  }
  // 250 Hz: two internal samples per output instead of five → σ × √2.5
  const NoiseFigures fast = MeasureNoise(0.5, 250);
  std::printf("range 0.50 m at 250 Hz: std %.5f m (configured %.5f)\n", fast.std_m,
              fast.sigma_cfg_m);
  EXPECT_NEAR(fast.sigma_cfg_m, 0.005 * std::sqrt(2.5), 1e-6);
  EXPECT_NEAR(fast.std_m, fast.sigma_cfg_m, 0.06 * fast.sigma_cfg_m);
}

TEST(TfLunaDevice, CentimetreResolutionAndChipTemperature) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  TfLunaConfig c;
  c.mount = {0, 0, 0.15, -90};
  TfLunaDevice dev(c, w, 3);
  DeviceOutput out;
  dev.OnEvent(StandStill{}.At(dev.next_event_time()), out);
  ASSERT_EQ(out.serial.size(), 1u);
  const DataFields d = DecodeDataFields(out.serial[0].bytes);
  EXPECT_EQ(d.dist, std::lround(dev.last_reading().measured_m * 100));
  EXPECT_NEAR(d.dist, 60, 3);
  EXPECT_DOUBLE_EQ(TemperatureFromRaw(d.temp_raw), 40.0);
  EXPECT_EQ(out.serial[0].t_ready, TimeFromSeconds(0.01));
}

TEST(TfLunaDevice, InvalidReadingsAsTheManualSays) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  TfLunaConfig c;
  c.mount = {0, 0, 0.5, -90};  // above the ridges: the beam reaches the film wall (ρ 0.05) at 2.7 m
  TfLunaDevice luna(c, w, 1);
  DeviceOutput out;
  luna.OnEvent(StandStill{}.At(luna.next_event_time()), out);
  EXPECT_FALSE(luna.last_reading().valid);
  EXPECT_LT(luna.last_reading().fields.amp, 100);
  EXPECT_EQ(DecodeDataFields(out.serial.back().bytes).dist, 0);  // TF-Luna dummy_dist
  c.model.model = ModuleModel::kTfminiS;
  TfLunaDevice tfmini(c, w, 1);
  tfmini.OnEvent(StandStill{}.At(tfmini.next_event_time()), out);
  EXPECT_EQ(DecodeDataFields(out.serial.back().bytes).dist, 0xFFFF);  // TFmini-S −1
  // the blind zone: 0.15 m from the ridge side
  c.model.model = ModuleModel::kTfLuna;
  c.mount.z_m = 0.15;
  TfLunaDevice close(c, w, 1);
  close.OnEvent(StandStill{-0.45}.At(close.next_event_time()), out);
  EXPECT_NEAR(close.last_target().range_m, 0.15, 1e-12);
  EXPECT_FALSE(close.last_reading().valid);
  // nothing within 12 m (looking along the aisle to the end wall 13 m away): ambient Amp
  c.mount.yaw_deg = 0;
  TfLunaDevice ahead(c, w, 1);
  ahead.OnEvent(StandStill{}.At(ahead.next_event_time()), out);
  EXPECT_FALSE(ahead.last_target().present);
  EXPECT_EQ(ahead.last_reading().fields.amp, 12);
}

TEST(TfLunaDevice, CommandsChangeRateFormatAndSurviveAReset) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  TfLunaDevice dev(TfLunaConfig{}, w, 5);
  DeviceOutput out;
  dev.OnHostBytes(0, TimeFromSeconds(0.001), FrameCommand(0x03, U16Payload(250)), out);
  ASSERT_EQ(out.serial.size(), 1u);
  EXPECT_EQ(out.serial[0].bytes, FrameCommand(0x03, U16Payload(250)));  // echo
  EXPECT_EQ(out.serial[0].t_ready, TimeFromSeconds(0.002));
  EXPECT_DOUBLE_EQ(dev.effective_rate_hz(), 250);
  EXPECT_EQ(dev.next_event_time(), TimeFromSeconds(0.005));
  dev.OnHostBytes(0, TimeFromSeconds(0.002), FrameCommand(0x03, U16Payload(30)), out);
  EXPECT_NEAR(dev.effective_rate_hz(), 500.0 / 17, 1e-12);  // 500/n: n = round(500/30) = 17
  dev.OnHostBytes(0, TimeFromSeconds(0.003), FrameCommand(0x05, std::string(1, '\x06')), out);
  EXPECT_EQ(dev.settings().format, OutputFormat::kMm9Byte);
  dev.OnHostBytes(0, TimeFromSeconds(0.004), FrameCommand(0x03, U16Payload(400)), out);  // > 250
  EXPECT_EQ(dev.stats().unsupported, 1u);
  dev.OnHostBytes(0, TimeFromSeconds(0.005), FrameCommand(0x02, ""), out);  // reset, unsaved
  EXPECT_EQ(out.serial.back().bytes, FrameCommand(0x02, std::string(1, '\0')));
  EXPECT_EQ(dev.settings().format, OutputFormat::kCm9Byte);
  EXPECT_DOUBLE_EQ(dev.effective_rate_hz(), 100);
  EXPECT_EQ(dev.next_event_time(), TimeFromSeconds(1.005));
  EXPECT_EQ(dev.statistics().resets, 1u);
}

}  // namespace
}  // namespace hil::rangefinder

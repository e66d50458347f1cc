#include "hil/firmware_emu/gnss/receiver_model.h"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace hil::gnss {
namespace {

TruthSample StationaryTruth(double t_s) {
  TruthSample s;
  s.t = TimeFromSeconds(t_s);
  s.lat_deg = 35.0;
  s.lon_deg = 50.0;
  return s;
}

TEST(ReceiverModelTest, ErrorStatisticsMatchConfiguration) {
  ReceiverModelConfig cfg;
  cfg.horizontal_sigma_m = 0.4;
  cfg.correlation_time_s = 4.5;
  ReceiverModel rx(cfg, 42);
  std::vector<double> east;
  for (int k = 0; k < 20000; ++k) {
    rx.Calc(StationaryTruth(k), UnixTime{}, k == 0 ? 0.0 : 1.0);
    east.push_back(rx.position_error_N_m().x());
  }
  double mean = 0, var = 0, lag1 = 0;
  for (double e : east) mean += e;
  mean /= static_cast<double>(east.size());
  for (std::size_t i = 0; i < east.size(); ++i) {
    var += (east[i] - mean) * (east[i] - mean);
    if (i > 0) lag1 += (east[i] - mean) * (east[i - 1] - mean);
  }
  lag1 /= var;
  var /= static_cast<double>(east.size());
  EXPECT_NEAR(std::sqrt(var), 0.4, 0.04);
  EXPECT_NEAR(lag1, std::exp(-1.0 / 4.5), 0.03);  // ≈ 0.80, as in the real captures
}

TEST(ReceiverModelTest, SameSeedSameFixes) {
  ReceiverModel a(ReceiverModelConfig{}, 7), b(ReceiverModelConfig{}, 7),
      c(ReceiverModelConfig{}, 8);
  for (int k = 0; k < 10; ++k) {
    const GnssFix fa = a.Calc(StationaryTruth(k), UnixTime{}, 1.0);
    const GnssFix fb = b.Calc(StationaryTruth(k), UnixTime{}, 1.0);
    const GnssFix fc = c.Calc(StationaryTruth(k), UnixTime{}, 1.0);
    EXPECT_EQ(fa.lat_deg, fb.lat_deg);
    EXPECT_NE(fa.lat_deg, fc.lat_deg);
  }
}

}  // namespace
}  // namespace hil::gnss

// The base's observations: the satellites are those the rover's sky shows above the mask, the
// pseudorange is the geometric range plus troposphere and ionosphere within the code noise, the
// carrier phase holds one integer ambiguity per satellite and signal across epochs, the lock time
// grows with the epochs, and the same seed gives the same values.
#include "hil/firmware_emu/rtk/base_observables.h"

#include <cmath>
#include <map>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/gps_time.h"

namespace hil::rtk {
namespace {

constexpr double kLat = 35.4796096, kLon = 50.5979765, kHeight = 1312.0;

double GpsSeconds() {
  const gnss::GpsWeekTime g = gnss::GpsFrom(gnss::ParseIsoUtc("2026-06-10T08:00:00Z"));
  return g.week * 604800.0 + g.tow_s();
}

TEST(BaseObservables, SatellitesAreTheRoversSkyAboveTheMask) {
  const gnss::Constellation sky(7);
  BaseObservables base({}, kLat, kLon, kHeight, 7);
  const double t = GpsSeconds();
  const auto obs = base.Observe(sky, t);
  gnss::SkyConditions cond;
  cond.max_channels = 64;
  std::vector<int> expected;
  for (const auto& v : sky.Sky(t, kLat, kLon, kHeight, cond)) {
    if (!v.sbas && v.elev_deg >= 10.0) expected.push_back(v.svid);
  }
  std::vector<int> got;
  for (const auto& o : obs) got.push_back(o.prn);
  EXPECT_EQ(got, expected);
  EXPECT_GE(got.size(), 5U);
  for (const auto& o : obs) {
    EXPECT_GT(o.geometric_range_m, 19.9e6);
    EXPECT_LT(o.geometric_range_m, 26e6);
    ASSERT_EQ(o.signals.size(), 2U);
    EXPECT_EQ(o.signals[0].msm_signal_id, 2);
    EXPECT_EQ(o.signals[1].msm_signal_id, 10);
  }
}

TEST(BaseObservables, RangesAmbiguitiesAndLockTimes) {
  const gnss::Constellation sky(7);
  BaseObservablesConfig cfg;
  BaseObservables base(cfg, kLat, kLon, kHeight, 7);
  const double t0 = GpsSeconds();
  std::map<std::pair<int, int>, double> first_n;  // (prn, signal) → ambiguity estimate (cycles)
  for (int k = 0; k < 120; ++k) {
    for (const auto& o : base.Observe(sky, t0 + k)) {
      const double el = o.elevation_deg * M_PI / 180;
      const double s = std::sin(el);
      const double tropo = cfg.zenith_tropo_m * 1.001 / std::sqrt(0.002001 + s * s);
      const double x = 6378137.0 * std::cos(el) / (6378137.0 + cfg.iono_shell_height_m);
      const double iono_l1 = cfg.vertical_iono_l1_m / std::sqrt(1 - x * x);
      for (const auto& g : o.signals) {
        const double gamma = std::pow(1575.42e6 / (299792458.0 / g.wavelength_m), 2);
        const double code_res = g.pseudorange_m - (o.geometric_range_m + tropo + iono_l1 * gamma);
        EXPECT_LT(std::abs(code_res), 5 * 0.5 / std::max(s, 0.1)) << o.prn;
        const double n =
            g.carrier_cycles - (o.geometric_range_m + tropo - iono_l1 * gamma) / g.wavelength_m;
        EXPECT_NEAR(n, std::round(n), 5 * cfg.phase_noise_m / g.wavelength_m);
        EXPECT_LE(std::abs(std::round(n)), cfg.ambiguity_span_cycles);
        const auto [it, fresh] = first_n.try_emplace({o.prn, g.msm_signal_id}, std::round(n));
        if (fresh) {
          EXPECT_EQ(g.lock_time_s, 0.0);  // acquired at this epoch
        } else {
          EXPECT_EQ(std::round(n), it->second) << "ambiguity of PRN " << o.prn << " changed";
          EXPECT_GT(g.lock_time_s, 0.0);
        }
        EXPECT_GE(g.cnr_dbhz, 32.0);
        EXPECT_LE(g.cnr_dbhz, 50.0);
        // the range rate is the satellite's line-of-sight speed: below 1 km/s for GPS
        EXPECT_LT(std::abs(g.range_rate_mps), 1000.0);
      }
    }
  }
}

TEST(BaseObservables, RangeRateIsTheDerivativeOfTheRange) {
  const gnss::Constellation sky(7);
  BaseObservables base({}, kLat, kLon, kHeight, 7);
  const double t0 = GpsSeconds();
  const auto a = base.Observe(sky, t0);
  const auto b = base.Observe(sky, t0 + 1.0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double diff = b[i].geometric_range_m - a[i].geometric_range_m;
    const double mean_rate =
        0.5 * (a[i].signals[0].range_rate_mps + b[i].signals[0].range_rate_mps);
    EXPECT_NEAR(diff, mean_rate, 0.01) << a[i].prn;
  }
}

TEST(BaseObservables, SameSeedSameValues) {
  const gnss::Constellation sky(3);
  BaseObservables a({}, kLat, kLon, kHeight, 3), b({}, kLat, kLon, kHeight, 3),
      c({}, kLat, kLon, kHeight, 4);
  const double t = GpsSeconds();
  const auto oa = a.Observe(sky, t), ob = b.Observe(sky, t), oc = c.Observe(sky, t);
  ASSERT_EQ(oa.size(), ob.size());
  for (std::size_t i = 0; i < oa.size(); ++i) {
    EXPECT_EQ(oa[i].signals[0].pseudorange_m, ob[i].signals[0].pseudorange_m);
    EXPECT_EQ(oa[i].signals[1].carrier_cycles, ob[i].signals[1].carrier_cycles);
  }
  EXPECT_NE(oa[0].signals[0].carrier_cycles, oc[0].signals[0].carrier_cycles);
}

}  // namespace
}  // namespace hil::rtk

// GPS MSM4/MSM7 bodies: header fields and masks at their bit positions, every value round-trips
// within the message's resolution, fields that do not fit go out as the standard's invalid
// values, the body length follows the masks, and the lock time indicators follow the standard's
// tables (DF402, DF407).
#include "hil/firmware_emu/rtk/rtcm3_msm.h"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rtk/rtcm3_bits.h"

namespace hil::rtcm3 {
namespace {

MsmEpoch TwoSatellites() {
  MsmEpoch e;
  e.station_id = 17;
  e.epoch_time_ms = 345600000;  // Wednesday 00:00 GPS
  e.clock_steering = 1;
  MsmSignal l1{2, 21234567.891, 21234560.123, -512.3456, 100.0, false, 47.3125};
  MsmSignal l2{10, 21234570.456, 21234552.789, -512.3456, 100.0, false, 41.25};
  e.satellites.push_back({3, {l1, l2}});
  MsmSignal only{2, 24876543.21, 24876600.5, 700.2, 0.02, true, 38.0};
  e.satellites.push_back({31, {only}});
  return e;
}

TEST(Rtcm3Msm, HeaderAndMasks) {
  const std::string b = EncodeGpsMsm(TwoSatellites(), MsmKind::kMsm7);
  BitReader r(b);
  EXPECT_EQ(r.GetUnsigned(12), 1077U);
  EXPECT_EQ(r.GetUnsigned(12), 17U);
  EXPECT_EQ(r.GetUnsigned(30), 345600000U);
  EXPECT_EQ(r.GetUnsigned(1), 0U);  // DF393: the only MSM of the epoch
  r.GetUnsigned(3 + 7);
  EXPECT_EQ(r.GetUnsigned(2), 1U);  // DF411 clock steering
  r.GetUnsigned(2 + 1 + 3);
  EXPECT_EQ(r.GetUnsigned(64), (std::uint64_t{1} << 61) | (std::uint64_t{1} << 33));  // PRN 3, 31
  EXPECT_EQ(r.GetUnsigned(32), (1U << 30) | (1U << 22));  // signals 2 (1C) and 10 (2W)
  EXPECT_EQ(r.GetUnsigned(4), 0b1110U);                   // PRN 3: both; PRN 31: 1C only
  // 169 header bits + 4 cells; MSM7: 36 bits per satellite, 80 per cell
  EXPECT_EQ(b.size(), (169U + 4 + 2 * 36 + 3 * 80 + 7) / 8);
  EXPECT_EQ(EncodeGpsMsm(TwoSatellites(), MsmKind::kMsm4).size(),
            (169U + 4 + 2 * 18 + 3 * 48 + 7) / 8);
}

void ExpectRoundTrip(MsmKind kind, double pr_tol_m, double cp_tol_m) {
  const MsmEpoch in = TwoSatellites();
  MsmKind got{};
  const MsmEpoch out = DecodeGpsMsm(EncodeGpsMsm(in, kind), got);
  ASSERT_EQ(got, kind);
  EXPECT_EQ(out.station_id, 17);
  EXPECT_EQ(out.epoch_time_ms, 345600000U);
  ASSERT_EQ(out.satellites.size(), 2U);
  for (std::size_t i = 0; i < 2; ++i) {
    ASSERT_EQ(out.satellites[i].signals.size(), in.satellites[i].signals.size());
    EXPECT_EQ(out.satellites[i].id, in.satellites[i].id);
    for (std::size_t k = 0; k < in.satellites[i].signals.size(); ++k) {
      const MsmSignal &a = in.satellites[i].signals[k], &b = out.satellites[i].signals[k];
      EXPECT_EQ(b.signal_id, a.signal_id);
      EXPECT_NEAR(b.pseudorange_m, a.pseudorange_m, pr_tol_m);
      EXPECT_NEAR(b.phaserange_m, a.phaserange_m, cp_tol_m);
      EXPECT_EQ(b.half_cycle, a.half_cycle);
      EXPECT_LE(b.lock_time_s, a.lock_time_s);  // the indicator gives a minimum lock time
      if (kind == MsmKind::kMsm7) {
        EXPECT_NEAR(b.phaserange_rate_mps, a.phaserange_rate_mps, 0.00005 + 1e-9);
        EXPECT_NEAR(b.cnr_dbhz, a.cnr_dbhz, 1.0 / 32);
      } else {
        EXPECT_TRUE(std::isnan(b.phaserange_rate_mps));
        EXPECT_NEAR(b.cnr_dbhz, a.cnr_dbhz, 0.5);
      }
    }
  }
}

TEST(Rtcm3Msm, Msm4RoundTripAtItsResolution) {
  // 2^-24 ms = 1.79 cm (code), 2^-29 ms = 0.56 mm (phase): half a step
  ExpectRoundTrip(MsmKind::kMsm4, 0.0090, 0.00029);
}

TEST(Rtcm3Msm, Msm7RoundTripAtItsResolution) {
  // 2^-29 ms = 0.56 mm (code), 2^-31 ms = 0.14 mm (phase)
  ExpectRoundTrip(MsmKind::kMsm7, 0.00029, 0.00008);
}

TEST(Rtcm3Msm, FieldsThatDoNotFitAreSentInvalid) {
  MsmEpoch e = TwoSatellites();
  e.satellites[0].signals[0].phaserange_m += 2000.0;  // beyond ±1171 m of the rough range
  e.satellites[0].signals[1].pseudorange_m = std::nan("");
  e.satellites[1].signals[0].pseudorange_m = 300000.0 * 300;  // 300 ms: no rough range
  MsmKind k{};
  const MsmEpoch d = DecodeGpsMsm(EncodeGpsMsm(e, MsmKind::kMsm7), k);
  EXPECT_TRUE(std::isnan(d.satellites[0].signals[0].phaserange_m));
  EXPECT_FALSE(std::isnan(d.satellites[0].signals[0].pseudorange_m));
  EXPECT_TRUE(std::isnan(d.satellites[0].signals[1].pseudorange_m));
  EXPECT_TRUE(std::isnan(d.satellites[1].signals[0].pseudorange_m));
}

TEST(Rtcm3Msm, RejectsMalformedEpochs) {
  MsmEpoch e = TwoSatellites();
  std::swap(e.satellites[0], e.satellites[1]);
  EXPECT_THROW(EncodeGpsMsm(e, MsmKind::kMsm4), std::invalid_argument);
  MsmEpoch many;
  for (int p = 1; p <= 33; ++p) many.satellites.push_back({p, {{2}, {10}}});
  EXPECT_THROW(EncodeGpsMsm(many, MsmKind::kMsm4), std::invalid_argument);
}

TEST(Rtcm3Msm, LockTimeIndicators) {
  // DF402: 0 below 32 ms, then i for 2^(i+4) ms ≤ t < 2^(i+5) ms, 15 from 524.288 s
  EXPECT_EQ(LockIndicatorMsm4(0.031), 0);
  EXPECT_EQ(LockIndicatorMsm4(0.032), 1);
  EXPECT_EQ(LockIndicatorMsm4(1.0), 5);
  EXPECT_EQ(LockIndicatorMsm4(1.024), 6);
  EXPECT_EQ(LockIndicatorMsm4(600.0), 15);
  // DF407: 1 ms steps to 63, then blocks of 32 indicators doubling the step
  EXPECT_EQ(LockIndicatorMsm7(0.063), 63);
  EXPECT_EQ(LockIndicatorMsm7(0.064), 64);
  EXPECT_EQ(LockIndicatorMsm7(0.100), 82);  // (100 - 64) / 2 + 64
  EXPECT_EQ(LockIndicatorMsm7(0.128), 96);
  EXPECT_EQ(LockIndicatorMsm7(1.0), 190);  // 1000 ms in the 16 ms block: 160 + (1000 - 512) / 16
  EXPECT_EQ(LockIndicatorMsm7(1e6), 704);
  for (int i = 0; i <= 704; ++i) {
    EXPECT_EQ(LockIndicatorMsm7(LockTimeOfMsm7Indicator(i)), i) << i;
  }
}

}  // namespace
}  // namespace hil::rtcm3

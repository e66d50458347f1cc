#pragma once
// Two truth samples bit for bit: the fields the devices, the evaluation and truth.csv read.
#include <gtest/gtest.h>

#include "hil/firmware_emu/truth_sample.h"

namespace hil::harness::testing {

inline void ExpectSameSample(const TruthSample& a, const TruthSample& b) {
  ASSERT_EQ(a.t, b.t);
  EXPECT_EQ(a.lat_deg, b.lat_deg);
  EXPECT_EQ(a.lon_deg, b.lon_deg);
  EXPECT_EQ(a.height_m, b.height_m);
  EXPECT_EQ(a.p_NB_N_m, b.p_NB_N_m);
  EXPECT_EQ(a.v_NB_N_mps, b.v_NB_N_mps);
  EXPECT_EQ(a.q_NB.coeffs(), b.q_NB.coeffs());
  EXPECT_EQ(a.w_IB_B_radps, b.w_IB_B_radps);
  EXPECT_EQ(a.f_B_mps2, b.f_B_mps2);
  EXPECT_EQ(a.gravity_N_mps2, b.gravity_N_mps2);
  EXPECT_EQ(a.cross_track_m, b.cross_track_m);
}

}  // namespace hil::harness::testing

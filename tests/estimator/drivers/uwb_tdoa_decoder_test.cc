// The estimator's HIL-UWB-TDOA0 decoder against the emulator's golden session
// (vectors/uwb/uwb_tag_session.*, Tag_Frame0 and TDOA frames interleaved): every r_i1 within the
// frame's 1 ps (0.3 mm); the closed-form solver on the decoded differences returns the module's
// position (rows without NLOS; on an NLOS row the two solutions respond differently to the bias);
// garbage and bad sums counted and survived.
#include "hil/estimator/drivers/uwb_tdoa_decoder.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/estimator/drivers/linktrack_decoder.h"
#include "hil/estimator/uwb/tdoa_solver.h"

#include "vector_files.h"

namespace hil::estimator::drivers {
namespace {

std::string ReadBin() { return hil::test::ReadVectorBytes("vectors/uwb/uwb_tag_session.bin"); }

std::vector<std::vector<double>> ReadExpected() {
  return hil::test::ReadCsvNumbers("vectors/uwb/uwb_tag_session.expected.csv");
}

TEST(UwbTdoaDecoderTest, GoldenSessionDecodesAndSolves) {
  const std::string bin = ReadBin();
  const auto rows = ReadExpected();
  ASSERT_EQ(rows.size(), 10u);
  std::vector<UwbTdoaSample> got;
  UwbTdoaDecoder dec([&](const UwbTdoaSample& s) { got.push_back(s); });
  for (std::size_t i = 0; i < bin.size(); i += 7) dec.Feed(std::string_view(bin).substr(i, 7));
  ASSERT_EQ(got.size(), rows.size());
  EXPECT_EQ(dec.stats().bad_checksum, 0u);
  EXPECT_EQ(dec.stats().garbage_bytes, 10u * 128);  // the interleaved Tag_Frame0s
  uwb::TdoaSolverConfig sc;
  sc.p_W_anchor_m = {Eigen::Vector2d(-10, -10), Eigen::Vector2d(10, -10), Eigen::Vector2d(10, 10),
                     Eigen::Vector2d(-10, 10)};
  const uwb::TdoaSolver solver(sc);
  int nlos_rows = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const auto& r = rows[k];
    EXPECT_EQ(got[k].system_time_ms, static_cast<std::uint32_t>(r[0]));
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(got[k].r_i1_m[i], r[5 + i], 0.0003 + 1e-6) << k;
    const uwb::TdoaFix fix = solver.Solve(got[k].r_i1_m);
    ASSERT_TRUE(fix.ok()) << k;
    const Eigen::Vector2d module(r[3], r[4]);
    if (r[8] < 0) {
      EXPECT_LT((fix.p_W_m - module).norm(), 0.003) << k;  // 1 ps steps through the geometry
    } else {
      ++nlos_rows;
      // the module's position moves by the least-squares response over all four anchors; the
      // closed form (eqs. 4-5) uses BS1-BS3 only (BS4 picks the root), so the two differ by up
      // to the bias times the geometry's gain
      EXPECT_LT((fix.p_W_m - module).norm(), 1.0) << k;
    }
  }
  EXPECT_GT(nlos_rows, 0);  // the session drives through its NLOS zone
  // the Tag_Frame0s of the same stream carry the same positions (mm)
  std::vector<LinkTrackTagFrame> tags;
  LinkTrackDecoder tag_dec([&](const LinkTrackTagFrame& f) { tags.push_back(f); });
  tag_dec.Feed(bin);
  ASSERT_EQ(tags.size(), rows.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    EXPECT_NEAR(tags[k].p_m.x(), rows[k][3], 0.0005 + 1e-9);
    EXPECT_NEAR(tags[k].p_m.y(), rows[k][4], 0.0005 + 1e-9);
  }
}

TEST(UwbTdoaDecoderTest, BadSumsAndGarbageAreCountedAndSurvived) {
  std::string bin = ReadBin();
  const std::string frame = bin.substr(128, 24);  // the first TDOA frame
  std::string bad = frame;
  bad[10] = static_cast<char>(bad[10] ^ 0x40);
  std::string wrong_count = frame;
  wrong_count[3] = 4;
  wrong_count[23] = static_cast<char>(wrong_count[23] + 1);
  int n = 0;
  UwbTdoaDecoder dec([&](const UwbTdoaSample&) { ++n; });
  dec.Feed("\x55\x55zz" + bad + wrong_count + frame + "\x55");
  EXPECT_EQ(n, 1);
  EXPECT_EQ(dec.stats().bad_checksum, 1u);
  EXPECT_EQ(dec.stats().bad_count, 1u);
  EXPECT_GT(dec.stats().garbage_bytes, 40u);
}

}  // namespace
}  // namespace hil::estimator::drivers

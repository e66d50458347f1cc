#include "hil/estimator/drivers/razor_text_decoder.h"

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::estimator::drivers {
namespace {

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::vector<std::vector<double>> ExpectedRows(const std::string& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  for (std::string line; std::getline(in, line);) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<double> v;
    std::istringstream cells(line);
    for (std::string c; std::getline(cells, c, ',');) v.push_back(std::strtod(c.c_str(), nullptr));
    rows.push_back(v);
  }
  return rows;
}

std::string Vectors() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return src ? std::string(src) + "/vectors/mcu/" : std::string();
}

std::vector<RazorTextSample> Decode(const std::vector<std::string>& pieces,
                                    RazorTextStats* st = nullptr) {
  std::vector<RazorTextSample> out;
  RazorTextDecoder d([&](const RazorTextSample& s) { out.push_back(s); });
  for (const auto& p : pieces) d.Feed(p);
  if (st) *st = d.stats();
  return out;
}

TEST(RazorTextDecoderTest, BothFormats) {
  const auto s =
      Decode({"$,-1,-1,-1,264,266,255,-1,-1,-1,#\r\n!Data:-6,5,215,389,381,384,47,369,-528#\n\r"});
  ASSERT_EQ(s.size(), 2u);
  EXPECT_EQ(s[0].format, RazorTextSample::Format::kRaw);
  EXPECT_EQ(s[0].gyro_adc, (std::array<int, 3>{264, 266, 255}));
  EXPECT_EQ(s[1].format, RazorTextSample::Format::kV19);
  EXPECT_EQ(s[1].accel_counts, (std::array<int, 3>{-6, 5, 215}));
  EXPECT_EQ(s[1].mag_counts, (std::array<int, 3>{47, 369, -528}));
  EXPECT_NEAR(RazorAccel_mps2(s[1]).z(), 215 * 9.80665 / 256, 1e-12);
  EXPECT_NEAR(RazorGyro_radps(s[1]).x(),
              (389 - 382) * (3.3 / 1024 / 3.33e-3) * std::numbers::pi / 180, 1e-12);
  EXPECT_NEAR(RazorMag_uT(s[1]).z(), -528 * 100.0 / 1300, 1e-12);
}

TEST(RazorTextDecoderTest, SplitReadsGarbageAndBadLinesCounted) {
  const std::string stream =
      "noise$,1,2,3,400,401,402,4,5,6,#\r\n"  // garbage before a good line
      "$,1,2,3,400,401,#\r\n"                 // too few fields
      "$,1,2,3,400,401,402,4,5,6,7,#\r\n"     // too many
      "$,1,2,3,1024,401,402,4,5,6,#\r\n"      // gyro ADC out of range
      "$,1,2,x,400,401,402,4,5,6,#\r\n"       // not a number
      "$,1,2,3,400,4"                         // cut by a new line
      "!Data:7,8,9,380,381,382,-4096,0,2047#\n\r"
      "$,+1,2,3,400,401,402,4,5,6,#\r\n"   // plus sign
      "!Data:1,2,3,400,401,402,4,5,6\n\r"  // no '#'
      "$,-9,-8,-7,0,1023,5,1,2,3,#\r\n";
  std::vector<std::string> bytes;
  for (char c : stream) bytes.emplace_back(1, c);
  RazorTextStats st;
  const auto s = Decode(bytes, &st);
  ASSERT_EQ(s.size(), 3u);
  EXPECT_EQ(s[0].accel_counts, (std::array<int, 3>{1, 2, 3}));
  EXPECT_EQ(s[1].mag_counts, (std::array<int, 3>{-4096, 0, 2047}));
  EXPECT_EQ(s[2].gyro_adc, (std::array<int, 3>{0, 1023, 5}));
  EXPECT_EQ(st.lines_ok, 3u);
  EXPECT_EQ(st.bad_lines, 7u);
  EXPECT_EQ(st.garbage_bytes, 5u);
}

TEST(RazorTextDecoderTest, OverlongLineIsDropped) {
  RazorTextStats st;
  const auto s =
      Decode({"$," + std::string(200, '1') + ",#\r\n$,0,0,0,382,382,382,0,0,0,#\r\n"}, &st);
  ASSERT_EQ(s.size(), 1u);
  EXPECT_EQ(st.bad_lines, 1u);
}

// Golden: the text vectors decode to the engineering values of their .expected.csv within one LSB.
void CheckGolden(const std::string& text_file, const std::string& csv_file,
                 RazorTextSample::Format format) {
  const std::string text = ReadFile(Vectors() + text_file);
  const auto rows = ExpectedRows(Vectors() + csv_file);
  ASSERT_FALSE(text.empty());
  // feed in uneven pieces, as a serial port delivers them
  std::vector<std::string> pieces;
  for (std::size_t i = 0, n = 1; i < text.size(); i += n, n = n % 23 + 1)
    pieces.push_back(text.substr(i, n));
  RazorTextStats st;
  const auto s = Decode(pieces, &st);
  ASSERT_EQ(s.size(), rows.size());
  EXPECT_EQ(st.bad_lines, 0u);
  EXPECT_EQ(st.garbage_bytes, 0u);
  const RazorScales k;
  const double lsb_accel = k.accel_mps2_per_count,
               lsb_gyro = k.gyro_dps_per_adc * std::numbers::pi / 180, lsb_mag = k.mag_uT_per_count;
  double worst = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    ASSERT_EQ(rows[i].size(), 9u);
    EXPECT_EQ(s[i].format, format);
    const Eigen::Vector3d a = RazorAccel_mps2(s[i]), g = RazorGyro_radps(s[i]),
                          m = RazorMag_uT(s[i]);
    for (int j = 0; j < 3; ++j) {
      const auto u = static_cast<std::size_t>(j);
      const double ea = std::abs(a[j] - rows[i][u]) / lsb_accel,
                   eg = std::abs(g[j] - rows[i][3 + u]) / lsb_gyro,
                   em = std::abs(m[j] - rows[i][6 + u]) / lsb_mag;
      EXPECT_LE(ea, 1.0) << "line " << i;
      EXPECT_LE(eg, 1.0) << "line " << i;
      EXPECT_LE(em, 1.0) << "line " << i;
      worst = std::max({worst, ea, eg, em});
    }
  }
  std::printf("%s: %zu lines, worst error %.2e LSB\n", text_file.c_str(), s.size(), worst);
}

TEST(RazorTextDecoderTest, GoldenRawWithinOneLsb) {
  CheckGolden("razor_v13_raw.txt", "razor_v13_raw.expected.csv", RazorTextSample::Format::kRaw);
}

TEST(RazorTextDecoderTest, GoldenV19WithinOneLsb) {
  CheckGolden("razor_v13_v19.txt", "razor_v13_v19.expected.csv", RazorTextSample::Format::kV19);
}

}  // namespace
}  // namespace hil::estimator::drivers

#include "hil/estimator/drivers/razor_imu_adapter.h"

namespace hil::estimator::drivers {
namespace {

// lines at 10 Hz received on a host clock with an offset; GNSS fixes at 1 Hz arriving 0.1 s late
TEST(RazorImuAdapterTest, StampsLinesThroughGnssArrivals) {
  RazorImuAdapter adapter;
  const std::int64_t host0 = 5000000000LL;
  const GpsTime gps0 = GpsTimeFromNs(1000LL * kNsPerSecond);
  RazorTextSample line;
  line.accel_counts = {0, 0, 256};
  line.gyro_adc = {382, 382, 392};  // +10 ADC on z
  std::vector<ImuSample> out;
  for (int k = 0; k < 50; ++k) {
    const std::int64_t t_ns = k * 100000000LL + 30000000;  // lines 30 ms after the 0.1 s grid
    if (k % 10 == 0)
      adapter.AddGnssArrival(host0 + k * 100000000LL + 100000000,
                             gps0 + Nanoseconds{k * 100000000LL}, 0.1);
    if (auto s = adapter.Add(line, host0 + t_ns)) out.push_back(*s);
  }
  EXPECT_GT(adapter.stats().imu_no_time, 0u);  // before two fixes gave the map
  ASSERT_GT(out.size(), 25u);
  for (const ImuSample& s : out) {
    EXPECT_EQ(((s.t - gps0).count() - 30000000) % 100000000, 0);
    EXPECT_NEAR(s.dt_s, 0.1, 1e-9);
    EXPECT_NEAR(s.delta_velocity_B_mps.z(), 9.80665 * 0.1, 1e-9);
    EXPECT_NEAR(s.delta_angle_B_rad.z(), 10 * (3.3 / 1024 / 3.33e-3) * std::numbers::pi / 180 * 0.1,
                1e-9);
  }
}

}  // namespace
}  // namespace hil::estimator::drivers

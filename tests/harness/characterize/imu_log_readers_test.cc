// The IMU log readers of hil characterize: good files read to the right rates and times; bad
// input names the file, the line (or record) and the field; the hil command exits 2 on it.
#include "hil/harness/characterize/imu_log_readers.h"

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

#include <gtest/gtest.h>
#include <sys/wait.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

class ImuLogReadersTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("characterize_readers_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string Write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  static std::string Message(const std::function<void()>& f) {
    try {
      f();
    } catch (const std::runtime_error& e) {
      return e.what();
    }
    return "no error";
  }
  // an RTKLIB TIMETAG file: header, open time (t_s + frac), records of (tick ms, 4-byte fpos)
  std::string Tag(const std::string& name, std::uint32_t t_s, double frac,
                  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& records) {
    std::string b(64, '\0');
    std::memcpy(b.data(), "TIMETAG RTKLIB demo5", 20);
    const auto put = [&b](std::uint64_t v, int n) {
      for (int k = 0; k < n; ++k) b.push_back(static_cast<char>((v >> (8 * k)) & 0xff));
    };
    put(t_s, 4);
    std::uint64_t bits = 0;
    std::memcpy(&bits, &frac, 8);
    put(bits, 8);
    for (const auto& [tick, fpos] : records) put(tick, 4), put(fpos, 4);
    return Write(name, b);
  }
  fs::path dir_;
};

TEST_F(ImuLogReadersTest, KfginsIncrementsBecomeRatesOverTheirIntervals) {
  const std::string p = Write("imu.txt",
                              "# sow dtheta dvel\n"
                              "100.00 0 0 0 0 0 0\n"
                              "100.01 1e-4 2e-4 3e-4 0.01 0.02 0.0981\n"
                              "100.03,2e-4,0,0,0,0,0.1962,0\n");
  const ImuSeries s = ReadKfginsImuText(p);
  ASSERT_EQ(s.size(), 2u);
  EXPECT_DOUBLE_EQ(s.t_s[0], 100.0);
  EXPECT_NEAR(s.gyro_radps[0].y(), 0.02, 1e-12);
  EXPECT_NEAR(s.accel_mps2[0].z(), 9.81, 1e-9);
  EXPECT_NEAR(s.gyro_radps[1].x(), 0.01, 1e-12);
  EXPECT_NEAR(s.accel_mps2[1].z(), 9.81, 1e-9);
}

TEST_F(ImuLogReadersTest, KfginsBadInputNamesFileLineAndField) {
  const std::string a = Write("a.txt", "1 0 0 0 0 0 0\n2 0 0 x 0 0 0\n");
  EXPECT_EQ(Message([&] { ReadKfginsImuText(a); }),
            a + ":2: field dtheta_z: 'x' is not a finite number");
  const std::string b = Write("b.txt", "1 0 0 0 0 0 0\n2 0 0 0 0 0\n");
  EXPECT_NE(Message([&] { ReadKfginsImuText(b); }).find(b + ":2: expected 7 or 8 columns"),
            std::string::npos);
  const std::string c = Write("c.txt", "1 0 0 0 0 0 0\n2 0 0 0 0 0 0\n2 0 0 0 0 0 0\n");
  EXPECT_EQ(Message([&] { ReadKfginsImuText(c); }), c + ":3: field sow: time does not increase");
  const std::string d = Write("d.txt", "1 0 0 0 0 0 nan\n");
  EXPECT_NE(Message([&] { ReadKfginsImuText(d); }).find(":1: field dvel_z"), std::string::npos);
}

TEST_F(ImuLogReadersTest, CsvLinesAreTimedByTheirTickAndPutOnGpstByTheTag) {
  // GIVEN a fragment, three 10 ms samples and an unterminated fragment; the host wrote each
  // complete line 20 ms after its sample tick (open time 1000.5 s, ticks from the open)
  const std::string l1 = "0.5,0.010\n";
  const std::string l2 = "0.000,0.000,1.000,0.000,0.000,0.000,5000\n";
  const std::string l3 = "0.000,0.000,1.000,1.000,0.000,0.000,5010\n";
  const std::string l4 = "0.000,0.000,1.000,2.000,0.000,0.000,5020\n";
  const std::string csv = Write("imu.csv", l1 + l2 + l3 + l4 + "0.0,0.0");
  const auto end = [&](std::size_t n) {
    const std::string all[] = {l1, l2, l3, l4};
    std::size_t e = 0;
    for (std::size_t i = 0; i < n; ++i) e += all[i].size();
    return static_cast<std::uint32_t>(e);
  };
  // ticks since the open: sample 5000 ms is written at host tick 1000 + 20
  const std::string tag =
      Tag("imu.csv.tag", 1000, 0.5, {{5, end(1)}, {1020, end(2)}, {1030, end(3)}, {1040, end(4)}});
  const ImuSeries s = ReadImuLog(csv);
  EXPECT_EQ(s.format, "csv-timetag");
  ASSERT_EQ(s.size(), 2u);  // three samples: two held intervals
  // GPST = open time + host tick = 1000.5 + 1.020 for the tick 5.000 s: offset −3.98 s
  EXPECT_NEAR(s.t_s[0], 1001.52, 1e-9);
  EXPECT_NEAR(s.t_s[2], 1001.54, 1e-9);
  EXPECT_NEAR(s.accel_mps2[0].z(), kCsvG_mps2, 1e-12);
  EXPECT_NEAR(s.gyro_radps[1].x(), std::numbers::pi / 180, 1e-12);
  ASSERT_GE(s.notes.size(), 2u);
  EXPECT_NE(s.notes[0].find(":1: first line is a fragment"), std::string::npos);
  EXPECT_NE(s.notes[1].find(":5: unterminated last line is a fragment"), std::string::npos);
}

TEST_F(ImuLogReadersTest, CsvBadInputNamesFileLineAndField) {
  const std::string good = "0,0,1,0,0,0,1\n0,0,1,0,0,0,2\n";
  const std::string a = Write("a.csv", good + "0,0,1,0,zz,0,3\n0,0,1,0,0,0,4\n");
  Tag("a.csv.tag", 1, 0, {{1, 14}});
  EXPECT_EQ(Message([&] { ReadImuLog(a); }), a + ":3: field gy: 'zz' is not a finite number");
  const std::string b = Write("b.csv", good + "0,0,1,0,0,3\n0,0,1,0,0,0,4\n");
  Tag("b.csv.tag", 1, 0, {{1, 14}});
  EXPECT_NE(Message([&] { ReadImuLog(b); }).find(b + ":3: expected 7 comma-separated fields"),
            std::string::npos);
  const std::string c = Write("c.csv", good + "0,0,1,0,0,0,2\n");
  Tag("c.csv.tag", 1, 0, {{1, 14}});
  EXPECT_EQ(Message([&] { ReadImuLog(c); }), c + ":3: field tick: does not increase");
  const std::string d = Write("d.csv", good + "0,0,1,0,0,0,3\n");
  Write("d.csv.tag", "not a tag file, but long enough to hold the header and the time stamp...");
  EXPECT_NE(Message([&] { ReadImuLog(d); }).find("d.csv.tag: header: "), std::string::npos);
  const std::string e = Write("e.csv", good + "0,0,1,0,0,0,3\n");
  Tag("e.csv.tag", 1, 0, {{1, 30}, {2, 10}});
  EXPECT_NE(Message([&] { ReadImuLog(e); }).find("e.csv.tag: records:"), std::string::npos);
}

TEST_F(ImuLogReadersTest, HilCharacterizeExitsTwoOnBadInput) {
  const char* bin = std::getenv("HIL_BIN_DIR");
  if (!bin) GTEST_SKIP() << "HIL_BIN_DIR not set";
  const std::string a = Write("a.txt", "1 0 0 0 0 0 0\n2 0 0 0 0 0 0\n3 0 0 0 0 y 0\n");
  const std::string err = (dir_ / "err.txt").string();
  const int rc = std::system((std::string(bin) + "/hil characterize " + a + " 2>" + err).c_str());
  ASSERT_TRUE(WIFEXITED(rc));
  EXPECT_EQ(WEXITSTATUS(rc), 2);
  std::stringstream text;
  text << std::ifstream(err).rdbuf();
  EXPECT_NE(text.str().find(a + ":3: field dvel_y"), std::string::npos) << text.str();
}

}  // namespace
}  // namespace hil::harness

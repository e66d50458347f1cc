#include "hil/estimator/datasets/candump_log.h"

#include <cstdlib>

#include <gtest/gtest.h>

#include "datasets/kfgins_test_files.h"

namespace hil::estimator::datasets {
namespace {

std::string ErrorOf(const std::string& line) {
  try {
    ParseCandumpLine(line, "x.candump", 7);
  } catch (const DatasetError& e) {
    return e.what();
  }
  return "";
}

TEST(CandumpLog, ParsesExtendedStandardRemoteAndDirectionForms) {
  const CandumpRecord a = ParseCandumpLine("(1700000000.123456) vcan0 18FF1234#0102A0ff", "x", 1);
  EXPECT_EQ(a.frame.rx_ns, 1700000000123456000LL);
  EXPECT_EQ(a.interface, "vcan0");
  EXPECT_TRUE(a.frame.extended);
  EXPECT_EQ(a.frame.id, 0x18FF1234u);
  ASSERT_EQ(a.frame.len, 4);
  EXPECT_EQ(a.frame.data[2], 0xA0);
  EXPECT_EQ(a.frame.data[3], 0xFF);
  EXPECT_FALSE(a.remote);
  const CandumpRecord b = ParseCandumpLine("(0000000001.5) can1 123#", "x", 1);
  EXPECT_EQ(b.frame.rx_ns, 1500000000LL);
  EXPECT_FALSE(b.frame.extended);
  EXPECT_EQ(b.frame.id, 0x123u);
  EXPECT_EQ(b.frame.len, 0);
  const CandumpRecord c = ParseCandumpLine("(1.000001) can0 0CF02AE2#R3 R", "x", 1);
  EXPECT_TRUE(c.remote);
  EXPECT_EQ(c.frame.len, 3);
  const CandumpRecord d = ParseCandumpLine("(1.000001) can0 0CF02AE2#1122334455667788_9\r", "x", 1);
  EXPECT_EQ(d.frame.len, 8);
  EXPECT_EQ(d.frame.data[7], 0x88);
}

TEST(CandumpLog, BadLinesNameFileLineAndField) {
  EXPECT_EQ(ErrorOf("1.0 vcan0 123#00"), "x.candump:7: timestamp: '(SECONDS.FRACTION)' expected");
  EXPECT_EQ(ErrorOf("(1.0) vcan0"), "x.candump:7: frame: missing");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 12345#00"),
            "x.candump:7: identifier: 3 (11-bit) or 8 (29-bit) hex digits expected");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 3FFFFFFF#00"), "x.candump:7: identifier: out of range");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 123#0G"), "x.candump:7: data: not hex");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 123#001"), "x.candump:7: data: odd number of hex digits");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 123#000102030405060708"), "x.candump:7: data: more than 8 bytes");
  EXPECT_EQ(ErrorOf("(1.0) vcan0 123#00 extra"), "x.candump:7: unexpected field after the frame");
  EXPECT_NE(ErrorOf("(1.0) vcan0 18FF1234##1001122").find("CAN FD frame (##) not supported"),
            std::string::npos);
}

TEST(CandumpLog, ReadsAFileSkippingCommentsAndNamesTheBadLine) {
  const testing::ScopedTempDir tmp;
  const std::string ok = testing::WriteFile(
      tmp.path, "a.log", "# candump\n\n(1.0) vcan0 0CF02AE2#00\n(2.0) vcan0 0CF02DE2#01\n");
  const std::vector<CandumpRecord> v = ReadCandumpLog(ok);
  ASSERT_EQ(v.size(), 2u);
  EXPECT_EQ(v[1].frame.rx_ns, 2000000000LL);
  const std::string bad =
      testing::WriteFile(tmp.path, "b.log", "(1.0) vcan0 0CF02AE2#00\n(2.0) vcan0 0CF02DE2\n");
  EXPECT_THROW(
      {
        try {
          ReadCandumpLog(bad);
        } catch (const DatasetError& e) {
          EXPECT_EQ(std::string(e.what()), bad + ":2: frame: no '#' between identifier and data");
          throw;
        }
      },
      DatasetError);
  EXPECT_THROW(ReadCandumpLog(tmp.path + "/absent.log"), DatasetError);
}

TEST(CandumpLog, DetectsCandumpText) {
  EXPECT_TRUE(LooksLikeCandump("# c\n\n(1700000000.1) vcan0 123#00\n"));
  EXPECT_FALSE(LooksLikeCandump("$GPGGA,1,2\n"));
  EXPECT_FALSE(LooksLikeCandump("# hil capture v2\n"));
  EXPECT_FALSE(LooksLikeCandump(""));
}

// the golden J1939 log: every line parses, extended frames of the MCU's address, 8 bytes
TEST(CandumpLog, ReadsTheGoldenJ1939Log) {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  if (src == nullptr) GTEST_SKIP() << "HIL_SOURCE_DIR unset";
  const std::vector<CandumpRecord> v =
      ReadCandumpLog(std::string(src) + "/vectors/can/mcu_j1939.candump");
  ASSERT_EQ(v.size(), 69u);
  for (const CandumpRecord& r : v) {
    EXPECT_TRUE(r.frame.extended);
    EXPECT_EQ(r.frame.id & 0xFFu, 0xE2u);
    EXPECT_EQ(r.frame.len, 8);
  }
  EXPECT_EQ(v.front().frame.rx_ns, 1370851200311015000LL);
}

}  // namespace
}  // namespace hil::estimator::datasets

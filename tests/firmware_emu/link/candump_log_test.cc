#include "hil/firmware_emu/link/candump_log.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

namespace hil::link {
namespace {

CanWireFrame Classic(std::uint32_t id, bool ext, std::initializer_list<std::uint8_t> bytes) {
  CanWireFrame f;
  f.id = id;
  f.extended = ext;
  for (std::uint8_t b : bytes) f.data[f.len++] = b;
  return f;
}

// Frame strings as can-utils prints them (lib.h examples and the project's reference vectors).
struct FrameRow {
  const char* legend;
  const char* text;
  CanWireFrame frame;
};

std::vector<FrameRow> FrameRows() {
  std::vector<FrameRow> rows;
  rows.push_back(
      {"standard id, 4 bytes", "123#DEADBEEF", Classic(0x123, false, {0xDE, 0xAD, 0xBE, 0xEF})});
  rows.push_back({"extended id, 1 byte", "12345678#01", Classic(0x12345678, true, {0x01})});
  rows.push_back({"NMEA 2000 129025 (reference)", "09F80180#8868111FBFA49103",
                  Classic(0x09F80180, true, {0x88, 0x68, 0x11, 0x1F, 0xBF, 0xA4, 0x91, 0x03})});
  rows.push_back({"J1939 ACCS (reference)", "0CF02DE2#007D007DD580000A",
                  Classic(0x0CF02DE2, true, {0x00, 0x7D, 0x00, 0x7D, 0xD5, 0x80, 0x00, 0x0A})});
  rows.push_back({"no data", "7FF#", Classic(0x7FF, false, {})});
  rows.push_back({"extended id with leading zeros", "00000001#", Classic(0x1, true, {})});
  CanWireFrame rtr = Classic(0x123, false, {});
  rtr.rtr = true;
  rows.push_back({"remote request", "123#R", rtr});
  rtr.len = 5;
  rows.push_back({"remote request with a length", "123#R5", rtr});
  CanWireFrame err = Classic(0x004, true, {0x00, 0x01, 0, 0, 0, 0, 0, 0});
  err.error = true;
  rows.push_back({"error frame: controller RX overflow", "20000004#0001000000000000", err});
  CanWireFrame fd = Classic(0x123, false, {0x11, 0x22, 0x33});
  fd.fd = true;
  fd.fd_flags = 1;
  rows.push_back({"CAN FD with BRS", "123##1112233", fd});
  CanWireFrame fd64;
  fd64.id = 0x1ABCDEF0;
  fd64.extended = true;
  fd64.fd = true;
  fd64.fd_flags = 2;
  fd64.len = 64;
  for (int i = 0; i < 64; ++i)
    fd64.data[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i * 3);
  std::string t64 = "1ABCDEF0##2";
  for (int i = 0; i < 64; ++i) {
    char b[3];
    std::snprintf(b, sizeof b, "%02X", i * 3);
    t64 += b;
  }
  static std::string keep;
  keep = t64;
  rows.push_back({"CAN FD, 64 bytes, ESI", keep.c_str(), fd64});
  return rows;
}

TEST(CandumpLogTest, FormatsAndParsesEveryFrameKindExactly) {
  for (const FrameRow& row : FrameRows()) {
    SCOPED_TRACE(row.legend);
    EXPECT_EQ(FormatCanFrameText(row.frame), row.text);
    const auto parsed = ParseCanFrameText(row.text);
    ASSERT_TRUE(parsed.has_value());
    EXPECT_EQ(*parsed, row.frame);
  }
}

TEST(CandumpLogTest, ParserIsTolerantLikeCanUtils) {
  // dot separators and lower case
  EXPECT_EQ(ParseCanFrameText("123#de.ad.be.ef"), Classic(0x123, false, {0xDE, 0xAD, 0xBE, 0xEF}));
  // a len8_dlc suffix after 8 bytes
  EXPECT_EQ(ParseCanFrameText("123#1122334455667788_E"),
            Classic(0x123, false, {0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77, 0x88}));
}

TEST(CandumpLogTest, RejectsMalformedFrameStrings) {
  for (const char* bad :
       {"", "12#00", "1234#00", "123", "123#0", "123#GG", "123#112233445566778899", "800#00",
        "123#R9", "123##", "123##1AABBCC0", "20000004#R"}) {
    SCOPED_TRACE(bad);
    EXPECT_FALSE(ParseCanFrameText(bad).has_value());
  }
}

TEST(CandumpLogTest, LogLineMatchesCandumpExactly) {
  CandumpRecord r;
  r.t = UnixTimeFromNs(1699999999123456789LL);  // the log keeps microseconds, truncated
  r.iface = "vcan0";
  r.frame = Classic(0x123, false, {0xDE, 0xAD, 0xBE, 0xEF});
  EXPECT_EQ(FormatCandumpLine(r), "(1699999999.123456) vcan0 123#DEADBEEF");
  // seconds are zero-padded to ten digits; names right-aligned to a common width
  r.t = UnixTimeFromNs(5000001000LL);
  r.iface = "can0";
  EXPECT_EQ(FormatCandumpLine(r, 5), "(0000000005.000001)  can0 123#DEADBEEF");
}

TEST(CandumpLogTest, ParsesLinesOfEveryCandumpVariant) {
  const auto a = ParseCandumpLine("(1700000000.000000) vcan0 09F80180#8868111FBFA49103\n");
  ASSERT_TRUE(a.has_value());
  EXPECT_EQ(a->t, UnixTimeFromNs(1700000000000000000LL));
  EXPECT_EQ(a->iface, "vcan0");
  EXPECT_EQ(a->frame.id, 0x09F80180U);
  const auto padded = ParseCandumpLine("(1700000000.250000)  can0 123#01 R");  // -x direction flag
  ASSERT_TRUE(padded.has_value());
  EXPECT_EQ(padded->iface, "can0");
  EXPECT_EQ(padded->direction, 'R');
  EXPECT_EQ(padded->t, UnixTimeFromNs(1700000000250000000LL));
  const auto nanos = ParseCandumpLine("(1700000000.123456789) vcan0 123#");  // candump -N
  ASSERT_TRUE(nanos.has_value());
  EXPECT_EQ(nanos->t, UnixTimeFromNs(1700000000123456789LL));
  EXPECT_FALSE(
      ParseCandumpLine("DROPCOUNT: dropped 3 CAN frame(s) on 'can0' socket (total drops 3)"));
  EXPECT_FALSE(ParseCandumpLine("(1700000000.000000) vcan0"));
  EXPECT_FALSE(ParseCandumpLine("(17000x0000.000000) vcan0 123#"));
  EXPECT_FALSE(ParseCandumpLine("(1700000000.000000) vcan0 123#00 X"));
}

TEST(CandumpLogTest, WriterAndReaderRoundTripAFile) {
  const std::string path =
      std::filesystem::temp_directory_path() / ("hil_candump_" + std::to_string(getpid()) + ".log");
  std::vector<CandumpRecord> written;
  {
    CandumpLogWriter w(path);
    std::int64_t t = 1370851200000000000LL;
    for (const FrameRow& row : FrameRows()) {
      CandumpRecord r;
      r.t = UnixTimeFromNs(t);
      r.iface = "vcan0";
      r.frame = row.frame;
      w.Write(r);
      written.push_back(r);
      t += 10001000;  // whole microseconds survive the log
    }
    EXPECT_EQ(w.lines(), written.size());
  }
  {
    std::ofstream extra(path, std::ios::app);
    extra << "DROPCOUNT: dropped 1 CAN frame(s) on 'vcan0' socket (total drops 1)\n\n(1.0) vcan0 "
             "nonsense\n";
  }
  const CandumpLog log = ReadCandumpLog(path);
  EXPECT_EQ(log.records, written);
  EXPECT_EQ(log.skipped_lines, 2u);
  EXPECT_EQ(log.unreadable_lines, 1u);
  std::filesystem::remove(path);
}

TEST(CandumpLogTest, DeviceFramesConvertBothWays) {
  CanFrame f;
  f.t = TimeFromNs(42);
  f.id = 0x0CF02AE2;
  f.extended = true;
  f.len = 8;
  for (std::uint8_t i = 0; i < 8; ++i) f.data[i] = i;
  const CanWireFrame w = FromDeviceFrame(f);
  EXPECT_EQ(FormatCanFrameText(w), "0CF02AE2#0001020304050607");
  const CanFrame back = ToDeviceFrame(w, f.t);
  EXPECT_EQ(back.id, f.id);
  EXPECT_EQ(back.len, f.len);
  EXPECT_EQ(back.data, f.data);
  EXPECT_EQ(back.t, f.t);
}

}  // namespace
}  // namespace hil::link

namespace hil::link {
namespace {

// Found by candump_line_fuzz: a timestamp of 15 digits overflowed the nanosecond arithmetic.
TEST(CandumpLogTest, RejectsTimestampsBeyondTheNanosecondRange) {
  EXPECT_FALSE(ParseCandumpLine("(137085120851200.311015) vcan0 0CF02DE2#137DE97C3880C002"));
  const auto ok = ParseCandumpLine("(1370851200.311015) vcan0 0CF02DE2#137DE97C3880C002");
  ASSERT_TRUE(ok);
  EXPECT_EQ(ok->t, UnixTimeFromNs(1370851200311015000LL));
}

}  // namespace
}  // namespace hil::link

#include "hil/harness/links/capture_format.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/harness/core/run_diagnostics.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

fs::path Temp(const std::string& name) {
  return fs::temp_directory_path() / ("hil_capfmt_" + std::to_string(getpid()) + "_" + name);
}

TEST(CaptureFormatTest, LinesHaveTheDocumentedColumns) {
  CaptureRecord r;
  r.dir = CaptureDir::kTx;
  r.t_emu_ns = 100000000;
  r.byte_period_ns = 1041667;
  r.t_wall = WallTimeFromNs(5000);
  r.name = "NMEA-GGA";
  r.bytes = std::string("$G\r\n\x00\xff", 6);
  EXPECT_EQ(FormatCaptureLine(r), "tx 100000000 1041667 5000 NMEA-GGA 24470d0a00ff");
  r.wall_offsets_ns = {0, 1100, 2050, 3200, 4100, 5300};
  EXPECT_EQ(FormatCaptureLine(r),
            "tx 100000000 1041667 5000 NMEA-GGA 24470d0a00ff 0,1100,2050,3200,4100,5300");
  CaptureRecord f;
  f.dir = CaptureDir::kFrameTx;
  f.t_emu_ns = 7;
  f.name = "vcan0";
  f.frame = *link::ParseCanFrameText("09F80180#8868111FBFA49103");
  EXPECT_EQ(FormatCaptureLine(f), "ftx 7 0 0 vcan0 09F80180#8868111FBFA49103");
  CaptureRecord empty;
  empty.dir = CaptureDir::kDrop;
  EXPECT_EQ(FormatCaptureLine(empty), "drop 0 0 0 - -");
}

TEST(CaptureFormatTest, EveryKindOfRecordRoundTripsThroughAFile) {
  const auto path = Temp("rt.cap");
  std::vector<CaptureRecord> recs;
  for (CaptureDir d : {CaptureDir::kTx, CaptureDir::kRx, CaptureDir::kDrop, CaptureDir::kFrameTx,
                       CaptureDir::kFrameRx}) {
    CaptureRecord r;
    r.dir = d;
    r.t_emu_ns = 1000 * static_cast<int>(d) + 1;
    r.t_wall = WallTimeFromNs(99);
    r.name = "x";
    if (r.is_frame()) {
      r.frame = *link::ParseCanFrameText(d == CaptureDir::kFrameTx ? "123##1AABB"
                                                                   : "20000004#0001000000000000");
    } else {
      r.bytes = "ab\x01";
      r.byte_period_ns = d == CaptureDir::kTx ? 86806 : 0;
      if (d == CaptureDir::kTx) r.wall_offsets_ns = {0, 87000, 174000};
    }
    recs.push_back(r);
  }
  CaptureHeader h;
  h.link = "ttyIMU";
  h.kind = "serial";
  h.baud = 115200;
  h.start_utc = UnixTimeFromNs(1370851200000000000LL);
  {
    CaptureWriter w(path, h);
    for (const auto& r : recs) w.Write(r);
  }
  const Capture c = ReadCapture(path);
  EXPECT_EQ(c.header.version, 2);
  EXPECT_EQ(c.header.link, "ttyIMU");
  EXPECT_EQ(c.header.kind, "serial");
  EXPECT_EQ(c.header.baud, 115200);
  EXPECT_EQ(c.header.start_utc, UnixTimeFromNs(1370851200000000000LL));
  EXPECT_EQ(c.records, recs);
  EXPECT_EQ(c.unreadable_lines, 0u);
  EXPECT_EQ(c.records[0].t_byte(2), TimeFromNs(1 + 2 * 86806));
  fs::remove(path);
}

TEST(CaptureFormatTest, ReadsVersionOneCapturesAndCountsBadLines) {
  const auto path = Temp("v1.cap");
  {
    std::ofstream o(path);
    o << "# hil capture v1: link ttyGPS, baud 9600\n# dir t_emu_ns byte_period_ns t_wall_ns name "
         "hex_bytes\n"
         "tx 100000000 1041667 0 NMEA-GGA 2447\n"
         "rx 2000000000 0 123456 host b562\n"
         "tx 1 2 3 broken zz\n"
         "bogus line\n";
  }
  const Capture c = ReadCapture(path);
  EXPECT_EQ(c.header.version, 1);
  EXPECT_EQ(c.header.link, "ttyGPS");
  EXPECT_EQ(c.header.baud, 9600);
  ASSERT_EQ(c.records.size(), 2u);
  EXPECT_EQ(c.records[0].bytes, "$G");
  EXPECT_EQ(c.records[1].dir, CaptureDir::kRx);
  EXPECT_EQ(c.records[1].bytes, "\xb5\x62");
  EXPECT_EQ(c.unreadable_lines, 2u);
  fs::remove(path);
}

TEST(CaptureFormatTest, RejectsFilesThatAreNotCaptures) {
  const auto path = Temp("not.cap");
  std::ofstream(path) << "(1700000000.000000) vcan0 123#00\n";
  EXPECT_THROW(ReadCapture(path), std::runtime_error);
  EXPECT_THROW(ReadCapture(Temp("missing.cap")), std::runtime_error);
  fs::remove(path);
}

TEST(CaptureFormatTest, WallOffsetsMustCoverEveryByte) {
  EXPECT_FALSE(ParseCaptureLine("tx 0 10 5 n 414243 0,1").has_value());
  EXPECT_TRUE(ParseCaptureLine("tx 0 10 5 n 414243 0,1,2").has_value());
}

TEST(CaptureFormatTest, AFailedWriteIsNotedInTheDiagnosticsItWasGiven) {
  // /dev/full: every write fails with ENOSPC, the header's already (in the constructor)
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  CaptureHeader h;
  h.link = "ttyGPS";
  h.kind = "serial";
  h.baud = 9600;
  RunDiagnostics run, other;
  CaptureWriter full("/dev/full", h);
  full.ReportFailuresTo(&run);  // failed before: noted at once
  EXPECT_EQ(run.FirstWriteFailure().value_or(""), "/dev/full");
  EXPECT_FALSE(other.FirstWriteFailure());  // the run's own value, no process-wide register
  // a writer that fails after it was given the diagnostics notes then, and the first stays
  const fs::path path = Temp("diag.cap");
  {
    CaptureWriter ok(path.string(), h);
    ok.ReportFailuresTo(&other);
    CaptureRecord r;
    r.dir = CaptureDir::kTx;
    r.name = "GPGGA";
    r.bytes = "$G";
    ok.Write(r);
    ok.Flush();
    EXPECT_FALSE(other.FirstWriteFailure());
  }
  fs::remove(path);
}

}  // namespace
}  // namespace hil::harness

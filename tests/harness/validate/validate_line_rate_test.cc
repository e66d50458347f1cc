// hil validate judges a capture at the baud its header records (issue 43): captures at 9600 and
// 115200 baud, written with the capture writer, read back through ReadByteSource.
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/links/capture_format.h"
#include "hil/harness/validate/validate.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

std::string Sentence(const std::string& body) {
  unsigned x = 0;
  for (const char c : body) x ^= static_cast<unsigned char>(c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "*%02X\r\n", x);
  return "$" + body + buf;
}

// One NEO-5M epoch (firmware 6 layout) at time of day 08:00:ss.cc: 445 bytes.
std::string Epoch(int centis) {
  char t[32];
  std::snprintf(t, sizeof t, "0800%02d.%02d", centis / 100, centis % 100);
  const std::string hms = t;
  return Sentence("GPRMC," + hms + ",A,3528.77658,N,05035.87859,E,0.864,30.00,100613,,,A") +
         Sentence("GPVTG,30.00,T,,M,0.864,N,1.600,K,A") +
         Sentence("GPGGA," + hms + ",3528.77658,N,05035.87859,E,1,08,1.01,1312.0,M,-20.1,M,,") +
         Sentence("GPGSA,A,3,01,02,03,04,05,06,07,08,,,,,1.80,1.01,1.49") +
         Sentence("GPGSV,2,1,08,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45") +
         Sentence("GPGSV,2,2,08,05,40,083,46,06,17,308,41,07,07,344,39,08,22,228,45") +
         Sentence("GPGLL,3528.77658,N,05035.87859,E," + hms + ",A,A");
}

bool Has(const ValidationReport& r, const std::string& check) {
  for (const auto& f : r.findings)
    if (f.check == check) return true;
  return false;
}

class ValidateLineRateTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("hil_validate_baud_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // A capture of `epochs` NEO-5M epochs every `period_ms`, each epoch one tx record whose header
  // says `header_baud` and whose bytes go at `line_baud` (the byte period a UART at that rate has,
  // rounded to the nanosecond as the harness writes it).
  std::string Write(const std::string& name, int header_baud, int line_baud, int epochs,
                    int period_ms) {
    const std::string path = (dir_ / name).string();
    CaptureHeader h;
    h.link = "ttyGPS";
    h.kind = "serial";
    h.baud = header_baud;
    CaptureWriter w(path, h);
    for (int k = 0; k < epochs; ++k) {
      CaptureRecord r;
      r.t_emu_ns = static_cast<std::int64_t>(k) * period_ms * 1'000'000LL + 50'000'000LL;
      r.byte_period_ns = std::llround(LineCharacterNs(line_baud));
      r.name = "NMEA";
      r.bytes = Epoch(k * period_ms / 10);
      w.Write(r);
    }
    return path;
  }

  fs::path dir_;
};

TEST_F(ValidateLineRateTest, ACaptureIsJudgedAtTheBaudItsHeaderRecords) {
  // 4 Hz epochs of 445 bytes: 0.46 s of line time at 9600 baud, 0.04 s at 115200
  const ByteStream fast = ReadByteSource(Write("fast.cap", 115200, 115200, 8, 250), 1, 9600);
  EXPECT_EQ(fast.line_baud, 115200);
  EXPECT_NE(fast.description.find("115200 baud"), std::string::npos) << fast.description;
  // --baud not given: the capture's 115200, not the option's default 9600
  const int baud = ValidationBaud(fast, 9600, false);
  EXPECT_EQ(baud, 115200);
  const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, fast, baud);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_FALSE(Has(r, "line_budget")) << ValidationSummary(r);
  EXPECT_FALSE(Has(r, "line_rate")) << ValidationSummary(r);
  // a --baud that contradicts the header is bad input; the same rate is accepted
  EXPECT_THROW(ValidationBaud(fast, 9600, true), std::invalid_argument);
  EXPECT_EQ(ValidationBaud(fast, 115200, true), 115200);
}

TEST_F(ValidateLineRateTest, A9600CaptureConformsAtItsOwnRate) {
  const ByteStream s = ReadByteSource(Write("slow.cap", 9600, 9600, 6, 1000), 1, 0);
  EXPECT_EQ(s.line_baud, 9600);
  const ValidationReport r =
      ValidateStream(ValidateProtocol::kNeo5m, s, ValidationBaud(s, 0, false));
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_TRUE(r.findings.empty()) << ValidationSummary(r);
}

TEST_F(ValidateLineRateTest, BytesFasterThanTheRecordedBaudCouldNotHaveCrossedTheLine) {
  // a header of 9600 baud over bytes 86.8 us apart (115200): every byte after an epoch's first
  const ByteStream s = ReadByteSource(Write("lying.cap", 9600, 115200, 4, 1000), 1, 0);
  for (const auto p : {ValidateProtocol::kNmea, ValidateProtocol::kNeo5m}) {
    const ValidationReport r = ValidateStream(p, s, ValidationBaud(s, 0, false));
    EXPECT_FALSE(r.conforms()) << ValidationSummary(r);
    ASSERT_TRUE(Has(r, "line_rate")) << ValidationSummary(r);
    for (const auto& f : r.findings) {
      if (f.check != "line_rate") continue;
      EXPECT_NE(f.message.find(std::to_string(4 * (Epoch(0).size() - 1))), std::string::npos)
          << f.message;
      EXPECT_NE(f.message.find("9600 baud"), std::string::npos) << f.message;
      EXPECT_EQ(f.offset, 1);
    }
  }
  // 4 Hz epochs at 9600 baud overlap (0.46 s of bytes every 0.25 s): the second epoch's first
  // byte starts before the first epoch's last has left
  const ByteStream overlap = ReadByteSource(Write("overlap.cap", 9600, 9600, 4, 250), 1, 0);
  const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, overlap, 9600);
  EXPECT_TRUE(Has(r, "line_rate")) << ValidationSummary(r);
  EXPECT_TRUE(Has(r, "line_budget")) << ValidationSummary(r);
}

TEST_F(ValidateLineRateTest, StreamsWithoutARecordedRateAreNotTimedByIt) {
  // a raw log (no header, no times): --baud is the rate, and no line_rate check
  const std::string path = (dir_ / "raw.log").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    const std::string e = Epoch(0) + Epoch(100);
    std::fwrite(e.data(), 1, e.size(), f);
    std::fclose(f);
  }
  const ByteStream s = ReadByteSource(path, 1, 9600);
  EXPECT_EQ(s.line_baud, 0);
  EXPECT_EQ(ValidationBaud(s, 38400, true), 38400);
  ValidationReport r;
  CheckLineRate(s, r);
  EXPECT_TRUE(r.findings.empty());
}

}  // namespace
}  // namespace hil::harness

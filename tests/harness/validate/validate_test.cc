// hil validate's checks on the real u-blox 5 captures (which must conform), on a u-blox 7 UBX
// capture, and on deliberately broken streams.
#include "hil/harness/validate/validate.h"

#include <cstdlib>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

#include "shared_vectors.h"

namespace hil::harness {
namespace {

std::string Vector(const std::string& name) { return test::GpsdVector(name); }

bool HasFinding(const ValidationReport& r, const std::string& check, bool error) {
  for (const auto& f : r.findings) {
    if (f.check == check && f.error == error) return true;
  }
  return false;
}

std::string Sentence(const std::string& body) {
  unsigned x = 0;
  for (char c : body) x ^= static_cast<unsigned char>(c);
  char buf[8];
  std::snprintf(buf, sizeof buf, "*%02X\r\n", x);
  return "$" + body + buf;
}

// one NEO-5M epoch in the firmware 6 layout
std::string Epoch(const std::string& hhmmss) {
  return Sentence("GPRMC," + hhmmss + ".00,A,3528.77658,N,05035.87859,E,0.864,30.00,100613,,,A") +
         Sentence("GPVTG,30.00,T,,M,0.864,N,1.600,K,A") +
         Sentence("GPGGA," + hhmmss +
                  ".00,3528.77658,N,05035.87859,E,1,08,1.01,1312.0,M,-20.1,M,,") +
         Sentence("GPGSA,A,3,01,02,03,04,05,06,07,08,,,,,1.80,1.01,1.49") +
         Sentence("GPGSV,2,1,08,01,40,083,46,02,17,308,41,03,07,344,39,04,22,228,45") +
         Sentence("GPGSV,2,2,08,05,40,083,46,06,17,308,41,07,07,344,39,08,22,228,45") +
         Sentence("GPGLL,3528.77658,N,05035.87859,E," + hhmmss + ".00,A,A");
}

std::string Epochs(int n) {
  std::string s;
  for (int i = 0; i < n; ++i) {
    char t[16];
    std::snprintf(t, sizeof t, "0800%02d", i);
    s += Epoch(t);
  }
  return s;
}

ByteStream Bytes(const std::string& s) {
  ByteStream b;
  b.bytes = s;
  return b;
}

TEST(ValidateTest, RealUblox5CapturesConformToTheNmeaAndNeo5mChecks) {
  HIL_SKIP_WITHOUT_GPSD_VECTORS();
  for (const char* log : {"ublox-lea-5h.log", "nl551e.log", "nl402u.log", "ublox-lea-5q.log"}) {
    const ByteStream s = ReadByteSource(Vector(log), 1, 9600);
    ASSERT_GT(s.bytes.size(), 1000u) << log;
    for (const auto p : {ValidateProtocol::kNmea, ValidateProtocol::kNeo5m}) {
      const ValidationReport r = ValidateStream(p, s, 9600);
      EXPECT_TRUE(r.conforms()) << log << "\n" << ValidationSummary(r);
      EXPECT_EQ(r.bad_frames, 0u) << log;
      EXPECT_EQ(r.garbage_bytes, 0u) << log;
      ASSERT_TRUE(r.epoch_rate_hz) << log;
      EXPECT_NEAR(*r.epoch_rate_hz, 1.0, 1e-6) << log;
    }
  }
  // the counts the vectors' README gives for ublox-lea-5h.log
  const ValidationReport r =
      ValidateStream(ValidateProtocol::kNmea, ReadByteSource(Vector("ublox-lea-5h.log"), 1, 0), 0);
  EXPECT_EQ(r.frames, 164u);
  EXPECT_EQ(r.messages.at("GPGSV").count, 59u);
  EXPECT_EQ(r.messages.at("GPTXT").count, 14u);
  EXPECT_TRUE(HasFinding(r, "line_end", false)) << "LF-only lines are reported as a warning";
}

TEST(ValidateTest, Ublox7UbxCaptureConformsToTheUbxChecks) {
  HIL_SKIP_WITHOUT_GPSD_VECTORS();
  const ValidationReport r =
      ValidateStream(ValidateProtocol::kUbx, ReadByteSource(Vector("navisys-gr701w.log"), 1, 0), 0);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_EQ(r.frames, 423u);
  EXPECT_EQ(r.messages.at("UBX-NAV-SOL").count, 81u);
  EXPECT_EQ(r.messages.at("UBX-MON-HW").count, 21u);
  EXPECT_EQ(r.garbage_bytes, 0u);
}

TEST(ValidateTest, SyntheticNeo5mStreamConformsAndTimesItsEpochs) {
  ByteStream s = Bytes(Epochs(10));
  // per-byte times: epoch k starts 120 ms after second k, 9600 baud
  std::size_t k = 0, i = 0;
  for (const std::size_t per = Epoch("080000").size(); i < s.bytes.size(); ++i) {
    k = i / per;
    s.t_ns.push_back(static_cast<std::int64_t>(k) * 1'000'000'000LL + 120'000'000LL +
                     static_cast<std::int64_t>(i % per) * 1'041'667LL);
  }
  const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, s, 9600);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_EQ(r.epochs, 10u);
  ASSERT_TRUE(r.epoch_first_byte_offset_p50_ms);
  EXPECT_NEAR(*r.epoch_first_byte_offset_p50_ms, 120.0, 1e-3);
  EXPECT_NEAR(*r.epoch_first_byte_jitter_ms, 0.0, 1e-3);
  EXPECT_TRUE(r.findings.empty()) << ValidationSummary(r);
}

TEST(ValidateTest, BrokenNmeaStreamsFail) {
  const std::string good = Epochs(6);
  {  // one flipped bit inside a sentence: a checksum error
    std::string bad = good;
    bad[200] = static_cast<char>(bad[200] ^ 0x04);
    const ValidationReport r = ValidateStream(ValidateProtocol::kNmea, Bytes(bad), 0);
    EXPECT_FALSE(r.conforms());
    EXPECT_TRUE(HasFinding(r, "checksum", true)) << ValidationSummary(r);
  }
  {  // stray bytes between sentences
    std::string bad = good;
    bad.insert(Epoch("080000").size(), "\x01\x02garbage");
    const ValidationReport r = ValidateStream(ValidateProtocol::kNmea, Bytes(bad), 0);
    EXPECT_FALSE(r.conforms());
    EXPECT_EQ(r.garbage_bytes, 9u);
  }
  {  // a GGA with a field missing (checksum recomputed): layout error
    const std::string bad =
        Sentence("GPGGA,080000.00,3528.77658,N,05035.87859,E,1,08,1.01,1312.0,M,-20.1,M") + good;
    const ValidationReport r = ValidateStream(ValidateProtocol::kNmea, Bytes(bad), 0);
    EXPECT_TRUE(HasFinding(r, "layout", true)) << ValidationSummary(r);
  }
  {  // time going backwards
    const std::string bad = Epoch("080005") + Epoch("080004") + Epoch("080003");
    const ValidationReport r = ValidateStream(ValidateProtocol::kNmea, Bytes(bad), 0);
    EXPECT_TRUE(HasFinding(r, "time_monotonic", true)) << ValidationSummary(r);
  }
  {  // a missing epoch is a sequence gap (warning), still conforming
    const std::string gap = Epoch("080000") + Epoch("080001") + Epoch("080004") + Epoch("080005");
    const ValidationReport r = ValidateStream(ValidateProtocol::kNmea, Bytes(gap), 0);
    EXPECT_TRUE(HasFinding(r, "sequence_gap", false)) << ValidationSummary(r);
    EXPECT_TRUE(r.conforms());
  }
  {  // an empty stream does not conform
    EXPECT_FALSE(ValidateStream(ValidateProtocol::kNmea, Bytes(""), 0).conforms());
  }
}

TEST(ValidateTest, Neo5mProfileChecksOrderTalkerAndMessageSet) {
  {  // GGA before RMC inside an epoch
    std::string e = Epoch("080001");
    const std::size_t rmc_len = e.find("$GPVTG");
    const std::size_t gga = e.find("$GPGGA"), gsa = e.find("$GPGSA");
    const std::string swapped = e.substr(gga, gsa - gga) + e.substr(0, rmc_len) +
                                e.substr(rmc_len, gga - rmc_len) + e.substr(gsa);
    const std::string s = Epoch("080000") + swapped + Epoch("080002");
    const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, Bytes(s), 9600);
    EXPECT_TRUE(HasFinding(r, "epoch_order", true)) << ValidationSummary(r);
    EXPECT_TRUE(ValidateStream(ValidateProtocol::kNmea, Bytes(s), 0).conforms())
        << "plain NMEA has no order";
  }
  {  // a GN talker and a sentence a u-blox 5 does not send
    const std::string s =
        Epochs(3) + Sentence("GNGNS,080003.00,3528.77658,N,05035.87859,E,AN,08,1.0,1312.0,-20.1,,");
    const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, Bytes(s), 9600);
    EXPECT_TRUE(HasFinding(r, "talker", true)) << ValidationSummary(r);
    EXPECT_TRUE(HasFinding(r, "message_set", true)) << ValidationSummary(r);
  }
  {  // five epochs a second: above the u-blox 5 rate
    std::string s;
    for (int i = 0; i < 10; ++i) {
      char t[16];
      std::snprintf(t, sizeof t, "0800%02d.%02d", i / 5, (i % 5) * 20);
      std::string e = Epoch("080000");
      for (std::size_t p = 0; (p = e.find("080000.00", p)) != std::string::npos; p += 9)
        e.replace(p, 9, t);
      // recompute checksums
      std::string fixed;
      std::size_t start = 0;
      for (std::size_t nl; (nl = e.find("\r\n", start)) != std::string::npos; start = nl + 2) {
        const std::string line = e.substr(start, nl - start);
        fixed += Sentence(line.substr(1, line.find('*') - 1));
      }
      s += fixed;
    }
    const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, Bytes(s), 115200);
    ASSERT_TRUE(r.epoch_rate_hz);
    EXPECT_NEAR(*r.epoch_rate_hz, 5.0, 1e-6);
    EXPECT_TRUE(HasFinding(r, "rate", true)) << ValidationSummary(r);
  }
}

std::string Ubx(std::uint8_t cls, std::uint8_t id, const std::string& payload) {
  std::string f{'\xB5',
                '\x62',
                static_cast<char>(cls),
                static_cast<char>(id),
                static_cast<char>(payload.size() & 0xFF),
                static_cast<char>(payload.size() >> 8)};
  f += payload;
  std::uint8_t a = 0, b = 0;
  for (std::size_t i = 2; i < f.size(); ++i) {
    a = static_cast<std::uint8_t>(a + static_cast<unsigned char>(f[i]));
    b = static_cast<std::uint8_t>(b + a);
  }
  f += static_cast<char>(a);
  f += static_cast<char>(b);
  return f;
}

std::string NavSol(std::uint32_t itow) {
  std::string p(52, '\0');
  for (int i = 0; i < 4; ++i)
    p[static_cast<std::size_t>(i)] = static_cast<char>((itow >> (8 * i)) & 0xFF);
  return Ubx(0x01, 0x06, p);
}

TEST(ValidateTest, BrokenUbxStreamsFail) {
  std::string good;
  for (std::uint32_t i = 0; i < 5; ++i) good += NavSol(100000 + i * 1000);
  EXPECT_TRUE(ValidateStream(ValidateProtocol::kUbx, Bytes(good), 0).conforms());
  {
    std::string bad = good;
    bad[70] = static_cast<char>(bad[70] ^ 0x10);  // payload of the second frame
    const ValidationReport r = ValidateStream(ValidateProtocol::kUbx, Bytes(bad), 0);
    EXPECT_TRUE(HasFinding(r, "checksum", true)) << ValidationSummary(r);
    EXPECT_EQ(r.frames, 4u) << "the framer resynchronises on the next frame";
  }
  {  // NAV-SOL with a 40-byte payload, NAV-PVT on a u-blox 5, iTOW going backwards
    const std::string bad = good + Ubx(0x01, 0x06, std::string(40, '\0')) +
                            Ubx(0x01, 0x07, std::string(92, '\0')) + NavSol(50000);
    const ValidationReport r = ValidateStream(ValidateProtocol::kNeo5m, Bytes(bad), 0);
    EXPECT_TRUE(HasFinding(r, "payload_length", true)) << ValidationSummary(r);
    EXPECT_TRUE(HasFinding(r, "message_set", true)) << ValidationSummary(r);
    EXPECT_TRUE(HasFinding(r, "time_monotonic", true)) << ValidationSummary(r);
  }
  {  // a frame cut off by the end of the capture is only a warning
    const std::string cut = good + NavSol(105000).substr(0, 20);
    const ValidationReport r = ValidateStream(ValidateProtocol::kUbx, Bytes(cut), 0);
    EXPECT_TRUE(HasFinding(r, "truncated", false));
    EXPECT_TRUE(r.conforms());
  }
}

std::string CanLog(bool lose_frame_3) {
  // 129025 single frames at 10 Hz, then one 129029 fast packet (43 bytes: 7 frames, sequence 2)
  std::string log;
  char line[128];
  for (int i = 0; i < 20; ++i) {
    std::snprintf(line, sizeof line, "(%d.%06d) vcan0 09F80101#A0B3F2150AB5A61E\n",
                  1700000000 + i / 10, (i % 10) * 100000);
    log += line;
  }
  for (int f = 0; f < 7; ++f) {
    if (lose_frame_3 && f == 3) continue;
    std::snprintf(line, sizeof line, "(1700000002.%06d) vcan0 0DF80501#%02X%s\n", f * 1000,
                  (2 << 5) | f, f == 0 ? "2B000000000000" : "00000000000000");
    log += line;
  }
  return log;
}

TEST(ValidateTest, CanLogs) {
  ValidationReport r = ValidateCanLog(CanLog(false));
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_EQ(r.frames, 27u);
  EXPECT_NEAR(r.messages.at("09F80101").rate_hz, 10.0, 1e-6);
  r = ValidateCanLog(CanLog(true));
  EXPECT_TRUE(HasFinding(r, "fast_packet", true)) << ValidationSummary(r);
  // malformed lines and a timestamp going backwards
  r = ValidateCanLog(
      CanLog(false) +
      "(1700000001.000000) vcan0 09F80101#A0\nnonsense\n(1700000003.0) vcan0 123#00\n");
  EXPECT_TRUE(HasFinding(r, "time_monotonic", true));
  EXPECT_TRUE(HasFinding(r, "format", true));
  EXPECT_EQ(r.bad_frames, 2u);
}

// navd's 129029 at 1 Hz: seven frames back to back each second (issue 15.4: that warned
// sequence_gap on a clean log, the period taken between frames instead of packets)
std::string FastPacketsEverySecond(int seconds, int skip_second) {
  std::string log;
  char line[128];
  for (int s = 0; s < seconds; ++s) {
    if (s == skip_second) continue;
    for (int f = 0; f < 7; ++f) {
      std::snprintf(line, sizeof line, "(%d.%06d) vcan0 0DF80580#%02X%s\n", 1700000000 + s, f * 40,
                    ((s & 7) << 5) | f, f == 0 ? "2B000000000000" : "00000000000000");
      log += line;
    }
  }
  return log;
}

TEST(ValidateTest, FastPacketBurstsAreTimedPerPacket) {
  ValidationReport r = ValidateCanLog(FastPacketsEverySecond(10, -1));
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_FALSE(HasFinding(r, "sequence_gap", false)) << ValidationSummary(r);
  EXPECT_EQ(r.frames, 70u);
  EXPECT_EQ(r.messages.at("0DF80580").count, 70u);
  EXPECT_NEAR(r.messages.at("0DF80580").rate_hz, 1.0, 1e-9);  // packets per second
  // three packets missing (seconds 4 to 6) are still a gap
  const std::string three_missing =
      FastPacketsEverySecond(4, -1) +
      FastPacketsEverySecond(10, -1).substr(FastPacketsEverySecond(7, -1).size());
  r = ValidateCanLog(three_missing);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_TRUE(HasFinding(r, "sequence_gap", false)) << ValidationSummary(r);
}

}  // namespace
}  // namespace hil::harness

namespace hil::harness {
namespace {

std::string Hex(const std::string& spaced) {
  std::string out;
  std::istringstream in(spaced);
  for (std::string h; in >> h;) out += static_cast<char>(std::stoi(h, nullptr, 16));
  return out;
}

std::uint16_t Crc(const std::string& b, std::size_t from, std::size_t to) {
  std::uint16_t crc = 0xFFFF;
  for (std::size_t i = from; i < to; ++i) {
    crc = static_cast<std::uint16_t>(crc ^ (static_cast<unsigned char>(b[i]) << 8));
    for (int k = 0; k < 8; ++k)
      crc = static_cast<std::uint16_t>(crc & 0x8000 ? (crc << 1) ^ 0x1021 : crc << 1);
  }
  return crc;
}

std::string Le(std::uint32_t v, int n) {
  std::string s;
  for (int i = 0; i < n; ++i) s += static_cast<char>((v >> (8 * i)) & 0xFF);
  return s;
}

std::string McuFrame(int type, std::uint16_t seq, std::uint32_t tick, const std::string& payload) {
  std::string f = std::string("\xA5\x5A\x01", 3) + static_cast<char>(type) +
                  static_cast<char>(payload.size()) + Le(seq, 2) + Le(tick, 4) + payload;
  return f + Le(Crc(f, 2, f.size()), 2);
}

std::string Status(std::uint16_t reset_count) {
  return std::string(1, '\x03') + std::string(1, '\x00') + Le(reset_count, 2) + Le(1000000, 4) +
         Le(100000, 4) + std::string(14, '\0');
}

// 3 s of a 10 Hz IMU with 1 Hz time pulses (tick rate 1 MHz + 50 ppm), from sequence `seq0`
std::string McuStream(std::uint16_t& seq, std::uint16_t reset_count) {
  std::string s = McuFrame(4, seq++, 0, Status(reset_count));
  for (int k = 0; k < 30; ++k) {
    const auto tick = static_cast<std::uint32_t>(k * 100005);
    s += McuFrame(1, seq++, tick + 10, std::string(12, '\x01'));
    if (k % 10 == 0)
      s += McuFrame(
          3, seq++, tick,
          Le(1744, 2) + Le(86400000u + static_cast<std::uint32_t>(k / 10) * 1000u, 4) + '\x01');
  }
  return s;
}

TEST(ValidateMcuTest, TheSpecWorkedExamplesConform) {
  ByteStream s;
  s.bytes = Hex("A5 5A 01 01 0C 02 01 4E 61 BC 00 03 00 FB FF 00 01 FE FF 01 00 F0 FF A4 70");
  ValidationReport r = ValidateMcuStream(s);
  EXPECT_EQ(r.frames, 1u);
  EXPECT_EQ(r.bad_frames, 0u) << ValidationSummary(r);
  s.bytes = Hex("A5 5A 01 03 07 07 00 40 42 0F 00 D0 06 00 5C 26 05 01 20 C6") +
            Hex("A5 5A 01 02 06 08 00 90 05 10 00 2C 01 CE FF A8 FD A6 58");
  r = ValidateMcuStream(s);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_EQ(r.frames, 2u);
}

TEST(ValidateMcuTest, RatesResetsGapsAndCorruption) {
  std::uint16_t seq = 0;
  ByteStream s;
  s.bytes = McuStream(seq, 0);
  ValidationReport r = ValidateMcuStream(s);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  EXPECT_NEAR(r.messages.at("IMU_SAMPLE").rate_hz, 1e6 / 100005, 1e-6);
  // a reset: sequence and tick restart with a higher reset count
  seq = 0;
  s.bytes += McuStream(seq, 1);
  r = ValidateMcuStream(s);
  EXPECT_TRUE(r.conforms()) << ValidationSummary(r);
  // a restart without a reset count increase, a lost frame, a flipped bit
  std::uint16_t seq2 = 0;
  std::string bad = McuStream(seq2, 0);
  seq2 = 0;
  bad += McuStream(seq2, 0);
  s.bytes = bad;
  EXPECT_TRUE(HasFinding(ValidateMcuStream(s), "reset", true));
  seq2 = 0;
  std::string stream = McuStream(seq2, 0);
  const std::size_t imu = stream.find(std::string("\xA5\x5A\x01\x01", 4), 100);
  stream.erase(imu, 25);
  s.bytes = stream;
  r = ValidateMcuStream(s);
  EXPECT_TRUE(HasFinding(r, "sequence_gap", true)) << ValidationSummary(r);
  EXPECT_EQ(r.garbage_bytes, 0u);
  seq2 = 0;
  stream = McuStream(seq2, 0);
  stream[imu + 14] = static_cast<char>(stream[imu + 14] ^ 0x20);
  s.bytes = stream;
  EXPECT_TRUE(HasFinding(ValidateMcuStream(s), "checksum", true));
  // an IMU rate far from the STATUS period (every other sample lost, sequence intact)
  seq2 = 0;
  std::string slow = McuFrame(4, seq2++, 0, Status(0));
  for (int k = 0; k < 20; ++k)
    slow += McuFrame(1, seq2++, static_cast<std::uint32_t>(k * 200000), std::string(12, '\0'));
  s.bytes = slow;
  EXPECT_TRUE(HasFinding(ValidateMcuStream(s), "rate", true));
}

}  // namespace
}  // namespace hil::harness

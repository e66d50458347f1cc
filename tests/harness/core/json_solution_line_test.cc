#include "hil/harness/core/json_solution_line.h"

#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "hil/harness/dut/estimate_reader.h"
#include "hil/harness/faults/fault_report.h"

namespace hil::harness {
namespace {

constexpr std::int64_t kStartNs = 1557799200000000000LL;

// A line as navd writes it (estimator/navd/main.cc, navd_health.cc).
std::string NavdLine(double lat, const std::string& flags, int epochs) {
  return R"({"tov_utc_s":1557799205.250000000,"tov_unix_ns":1557799205250000000,"lat_deg":)" +
         std::to_string(lat) +
         R"(,"lon_deg":126.6300012261,"height_m":150.0996,"vel_enu_mps":[0.0316,1.0287,-0.0031],)"
         R"("speed_mps":1.0292,"pos_std_enu_m":[1.0000,1.0000,1.0000],"yaw_deg":1.7623,)"
         R"("roll_deg":-0.0794,"pitch_deg":-0.0194,"vel_std_enu_mps":[0.2000,0.2000,0.2000],)"
         R"("nis_pos":0.000,"mean_nis_pos":0.000,"mode":"ekf","status":1,"health":{"flags":[)" +
         flags + R"(],"gnss_checksum_errors":0,"gnss_malformed":0,"gnss_epochs":)" +
         std::to_string(epochs) + R"(,"imu_gaps":2,"mcu_resets":0}})";
}

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void ExpectSameRecord(const std::optional<EstimateRecord>& dom,
                      const std::optional<EstimateRecord>& scan, const std::string& line) {
  ASSERT_EQ(dom.has_value(), scan.has_value()) << line;
  if (!dom) return;
  EXPECT_EQ(dom->t_validity, scan->t_validity) << line;
  EXPECT_TRUE(SameBits(dom->lat_deg, scan->lat_deg)) << line;
  EXPECT_TRUE(SameBits(dom->lon_deg, scan->lon_deg)) << line;
  EXPECT_TRUE(SameBits(dom->height_m, scan->height_m)) << line;
  EXPECT_EQ(dom->vel_enu_mps.has_value(), scan->vel_enu_mps.has_value()) << line;
  if (dom->vel_enu_mps && scan->vel_enu_mps) {
    EXPECT_EQ(*dom->vel_enu_mps, *scan->vel_enu_mps) << line;
  }
  EXPECT_EQ(dom->pos_std_enu_m.has_value(), scan->pos_std_enu_m.has_value()) << line;
  if (dom->pos_std_enu_m && scan->pos_std_enu_m) {
    EXPECT_EQ(*dom->pos_std_enu_m, *scan->pos_std_enu_m) << line;
  }
  EXPECT_EQ(dom->yaw_deg.has_value(), scan->yaw_deg.has_value()) << line;
  if (dom->yaw_deg && scan->yaw_deg) {
    EXPECT_TRUE(SameBits(*dom->yaw_deg, *scan->yaw_deg)) << line;
  }
}

// Reads `line` both ways; returns whether the scanner answered. Where it did, the record and the
// health must be what the DOM gives.
bool CompareWithDom(JsonSolutionScanner& scanner, const std::string& line) {
  const auto reader = MakeEstimateReader(EstimatorOutput::kJsonStdout, UnixTimeFromNs(kStartNs));
  const auto scan = scanner.Scan(line);
  if (!scan) return false;
  const nlohmann::json dom = nlohmann::json::parse(line, nullptr, false);
  EXPECT_FALSE(dom.is_discarded()) << "the scanner answered a line that is no JSON: " << line;
  ExpectSameRecord(reader->JsonLine(dom, WallTimeFromNs(7)),
                   reader->ScannedLine(*scan, WallTimeFromNs(7)), line);
  EstimatorHealth from_dom, from_scan;
  from_dom.AddJson(dom);
  from_scan.AddScanned(*scan);
  EXPECT_EQ(from_dom.present, from_scan.present) << line;
  EXPECT_EQ(from_dom.counters, from_scan.counters) << line;
  EXPECT_EQ(from_dom.flags_seen, from_scan.flags_seen) << line;
  return true;
}

TEST(JsonSolutionLineTest, ReadsNavdsLinesAsTheDocumentDoes) {
  JsonSolutionScanner scanner;
  EXPECT_TRUE(CompareWithDom(scanner, NavdLine(45.7500474237, "", 3)));
  EXPECT_TRUE(CompareWithDom(scanner, NavdLine(-33.5, R"("gnss_outage","imu_gap")", 4)));
  const auto scan = scanner.Scan(NavdLine(45.75, R"("mcu_reset")", 5));
  ASSERT_TRUE(scan);
  EXPECT_EQ(*scan->tov_unix_ns, 1557799205250000000LL);
  EXPECT_EQ(*scan->lat_deg, 45.75);
  EXPECT_EQ(scan->vel_enu_mps->z(), -0.0031);
  ASSERT_TRUE(scan->health);
  EXPECT_EQ(scan->health_flags, std::vector<std::string>{"mcu_reset"});
  EXPECT_EQ((*scan->health_keys)[3], "gnss_epochs");
  EXPECT_EQ(*scan->health_values[3], 5.0);
  EXPECT_FALSE(scan->health_values[0]) << "flags is no number";
  // lines with the same health keys share one key list
  EXPECT_EQ(scanner.Scan(NavdLine(1, "", 1))->health_keys, scan->health_keys);
}

TEST(JsonSolutionLineTest, LeavesToTheDocumentWhatItDoesNotAnswerExactly) {
  JsonSolutionScanner scanner;
  for (const std::string line :
       {R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":5,"lat_deg":3})",  // a key used twice
        R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":5,"health":{"a":1,"a":"x"}})",
        R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":9223372036854775808})",         // beyond int64
        R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":5,"mode":"\u00e9"})",           // an escape
        "{\"lat_deg\":1,\"lon_deg\":2,\"tov_unix_ns\":5,\"mode\":\"\xc3\xa9\"}",  // UTF-8
        R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":5,})",                          // invalid JSON
        R"({"lat_deg":01,"lon_deg":2,"tov_unix_ns":5})", R"({"lat_deg":1.})",
        R"({"lat_deg":1,"lon_deg":2} x)", R"({"lat_deg":1e999,"lon_deg":2})", R"([{"lat_deg":1}])",
        R"({"a":[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]]})"}) {
    EXPECT_FALSE(scanner.Scan(line)) << line;
  }
  // what it answers, it answers as the DOM does, whatever the members' kinds
  for (
      const std::string line :
      {R"({"lat_deg":"1","lon_deg":2,"tov_unix_ns":5})", R"({"lat_deg":1,"lon_deg":2})",
       R"({"lat_deg":1,"lon_deg":-0,"tov_unix_ns":5.5,"tov_utc_s":7})",
       R"({"lat_deg":1,"lon_deg":2,"tov_utc_s":1e9,"vel_enu_mps":[1,2],"pos_std_enu_m":[1,"a",3]})",
       R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":-5,"health":[1],"yaw_deg":null})",
       R"({"lat_deg":1E+2,"lon_deg":2,"tov_unix_ns":5,"health":{"flags":["a",1,["b"],"c"],"flags2":{"x":[]}}})",
       R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":5,"health":{"flags":7,"n":true}})", "{}",
       " { \"lat_deg\" : 1 , \"lon_deg\" : 2 , \"tov_unix_ns\" : 5 }\r",
       // times no solution has (their nanoseconds beyond int64): no record either way
       R"({"lat_deg":1,"lon_deg":2,"tov_utc_s":15577799205.25})",
       R"({"lat_deg":1,"lon_deg":2,"tov_unix_ns":-9223372036854775807})"}) {
    EXPECT_TRUE(CompareWithDom(scanner, line)) << line;
  }
}

// Mutated navd lines (a byte changed, dropped or repeated): where the scanner answers, it answers
// as the DOM does, and it answers none that the DOM discards.
TEST(JsonSolutionLineTest, MutatedLinesReadAsTheDocumentReadsThem) {
  const std::string base = NavdLine(45.7500474237, R"("gnss_outage")", 3);
  const std::string alphabet = "{}[]:,\"-+.eE0123456789 \\tnfa_\x80\x01";
  std::mt19937 rng(15);
  int answered = 0;
  JsonSolutionScanner scanner;
  for (int k = 0; k < 20000; ++k) {
    std::string line = base;
    const int edits = 1 + static_cast<int>(rng() % 3);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % line.size();
      switch (rng() % 3) {
        case 0:
          line[at] = alphabet[rng() % alphabet.size()];
          break;
        case 1:
          line.erase(at, 1);
          break;
        default:
          line.insert(at, 1, line[at]);
      }
    }
    if (CompareWithDom(scanner, line)) ++answered;
    if (::testing::Test::HasFailure()) return;
  }
  EXPECT_GT(answered, 2000) << "most single edits inside numbers and names still make a line";
}

}  // namespace
}  // namespace hil::harness

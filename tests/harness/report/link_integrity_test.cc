// What the estimator says it received against what the run sent (issue 40.6): a navd that counts
// CRC errors on a link no fault touched is a problem of the run, never a silent pass.
#include "hil/harness/report/link_integrity.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace hil::harness {
namespace {

// navd's health object as its last solution line gave it.
EstimatorHealth Health(std::map<std::string, double> counters) {
  EstimatorHealth h;
  h.present = true;
  h.counters = std::move(counters);
  return h;
}

const std::vector<LinkSent> kSent = {{"ttyGPS", "gnss", 180000, 0}, {"ttyIMU", "imu", 7200000, 0}};

TEST(LinkIntegrityTest, ADutCountingCrcErrorsOnACleanLinkIsAProblem) {
  // the run: clean captures, navd damaged
  const EstimatorHealth h = Health({{"gnss_checksum_errors", 127},
                                    {"gnss_garbage_bytes", 0},
                                    {"imu_crc_errors", 520},
                                    {"imu_garbage_bytes", 3786},
                                    {"gnss_epochs", 17999}});
  const std::vector<LinkIntegrity> r = CheckLinkIntegrity(kSent, h, {}, FaultTimeline{});
  ASSERT_EQ(r.size(), 2u);
  EXPECT_FALSE(r[0].intact);
  EXPECT_FALSE(r[1].intact);
  EXPECT_NE(r[0].problem.find("ttyGPS"), std::string::npos) << r[0].problem;
  EXPECT_NE(r[0].problem.find("gnss_checksum_errors 127"), std::string::npos) << r[0].problem;
  EXPECT_NE(r[1].problem.find("imu_crc_errors 520"), std::string::npos) << r[1].problem;
  EXPECT_NE(r[1].problem.find("imu_garbage_bytes 3786"), std::string::npos) << r[1].problem;
  EXPECT_EQ(r[1].estimator_counters.count("gnss_epochs"), 0u) << "not a link counter";
  const nlohmann::json j = LinkIntegrityJson(r);
  EXPECT_FALSE(j[1]["intact"].get<bool>());
  EXPECT_EQ(j[1]["estimator_counters"]["imu_crc_errors"].get<double>(), 520);
}

TEST(LinkIntegrityTest, ZeroCountersOnEveryLinkAreIntact) {
  const EstimatorHealth h = Health({{"gnss_checksum_errors", 0},
                                    {"gnss_malformed", 0},
                                    {"gnss_garbage_bytes", 0},
                                    {"imu_crc_errors", 0},
                                    {"imu_sequence_gaps", 0}});
  for (const LinkIntegrity& r : CheckLinkIntegrity(kSent, h, {}, FaultTimeline{})) {
    EXPECT_TRUE(r.intact) << r.role;
    EXPECT_TRUE(r.problem.empty());
  }
}

TEST(LinkIntegrityTest, AFaultThatDamagesALinkExcusesItsCountersOnly) {
  FaultTimeline faults;
  Fault f;
  f.kind = FaultKind::kByteCorruption;
  f.link = "ttyIMU";
  faults.faults.push_back(f);
  Fault gap;
  gap.kind = FaultKind::kGnssDataGap;  // sends nothing: no excuse for damaged bytes
  faults.faults.push_back(gap);
  const EstimatorHealth h = Health({{"gnss_checksum_errors", 2}, {"imu_crc_errors", 31}});
  const std::vector<LinkIntegrity> r = CheckLinkIntegrity(kSent, h, {}, faults);
  EXPECT_FALSE(r[0].intact) << "nothing damages ttyGPS";
  EXPECT_TRUE(r[1].intact);
  EXPECT_EQ(r[1].excused_by, std::vector<std::string>{"byte_corruption"});
}

TEST(LinkIntegrityTest, TheStartUpBaselineIsSubtracted) {
  // real time: navd opened ttyGPS mid-sentence before its first solution
  const EstimatorHealth h = Health({{"gnss_checksum_errors", 1}, {"gnss_garbage_bytes", 40}});
  const std::vector<LinkIntegrity> r = CheckLinkIntegrity(
      {kSent[0]}, h, {{"gnss_checksum_errors", 1}, {"gnss_garbage_bytes", 40}}, FaultTimeline{});
  EXPECT_TRUE(r[0].intact);
  const std::vector<LinkIntegrity> later = CheckLinkIntegrity(
      {kSent[0]}, Health({{"gnss_checksum_errors", 2}, {"gnss_garbage_bytes", 40}}),
      {{"gnss_checksum_errors", 1}, {"gnss_garbage_bytes", 40}}, FaultTimeline{});
  EXPECT_FALSE(later[0].intact) << "an error after the first solution";
}

TEST(LinkIntegrityTest, BytesTheRunDroppedWithTheHostAttachedAreAProblemWithoutAHealthObject) {
  const std::vector<LinkIntegrity> r =
      CheckLinkIntegrity({{"ttyIMU", "imu", 1000, 24}}, EstimatorHealth{}, {}, FaultTimeline{});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_FALSE(r[0].intact);
  EXPECT_NE(r[0].problem.find("24 bytes dropped"), std::string::npos) << r[0].problem;
}

TEST(LinkIntegrityTest, SeveralGnssLinksShareNavdsCounters) {
  const std::vector<LinkIntegrity> r =
      CheckLinkIntegrity({{"ttyGPS", "gnss", 10, 0}, {"ttyGPS2", "gnss", 20, 0}},
                         Health({{"gnss_checksum_errors", 0}}), {}, FaultTimeline{});
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].links, (std::vector<std::string>{"ttyGPS", "ttyGPS2"}));
  EXPECT_EQ(r[0].bytes_sent, 30u);
  EXPECT_TRUE(r[0].intact);
}

}  // namespace
}  // namespace hil::harness

// `hil campaign` through the real binary: a small campaign (2 scenarios × 2 sweep values × 3
// seeds, short forms) run --local -j 2 and as 3 shards merged afterwards gives the same bytes;
// a missing shard is named with its runs by `status`, the merge refuses it (or merges it with
// --allow-partial), re-running only that shard completes it, a resubmitted shard skips its
// recorded runs, and a bad campaign file exits 2 naming file, line and field.
#include <filesystem>

#include <gtest/gtest.h>

#include "cli_runner.h"

namespace hil::test {
namespace {

namespace fs = std::filesystem;

std::string CampaignFile(const TempDir& dir) {
  const std::string sc = SourceDir() + "/vectors/scenarios/";
  const std::string path = dir / "mc.yaml";
  WriteFile(path,
            "name: e2e\n"
            "scenarios: [" +
                sc + "seed000_gps_only.yaml, " + sc +
                "straight_line_outage.yaml]\n"
                "short: true\n"
                "seeds: {from: 1, to: 3}\n"
                "sweep:\n"
                "  fields:\n"
                "    - {field: gnss.errors.horizontal_sigma_m, values: [0.2, 0.4]}\n"
                "criteria:\n"
                "  - {metric: horizontal_rmse_m, stat: p95, max: 5.0}\n"
                "  - {pass_fraction: 0.3}\n");
  return path;
}

TEST(CampaignE2eTest, ShardsMergedGiveTheBytesOfLocalAndMissingShardsAreNamed) {
  TempDir dir("campaign_e2e");
  const std::string hil = BinDir() + "/hil campaign ";
  const std::string file = CampaignFile(dir);
  const CommandResult local = RunCommand(hil + file + " --local -j 2 --out " + dir / "local");
  ASSERT_TRUE(local.exit_code == 0 || local.exit_code == 1) << local.out;
  EXPECT_NE(local.out.find("[12/12]"), std::string::npos) << local.out;  // the progress line
  EXPECT_NE(local.out.find("ETA"), std::string::npos) << local.out;

  const std::string b = dir / "sharded";
  for (const char* s : {"1/3", "2/3"}) {
    const CommandResult r = RunCommand(hil + file + " --shard " + s + " -j 2 --out " + b);
    ASSERT_EQ(r.exit_code, 0) << r.out;
  }
  // shard 3 never ran: status names it and its runs; the merge refuses, or merges with a flag
  const CommandResult st = RunCommand(hil + "status " + b);
  EXPECT_EQ(st.exit_code, 3) << st.out;
  EXPECT_NE(st.out.find("shard 3/3: 0/4 done, not started; missing runs: "
                        "seed000_gps_only__p0-seed3 seed000_gps_only__p1-seed3"),
            std::string::npos)
      << st.out;
  EXPECT_NE(st.out.find("shard 1/3: 4/4 done, complete"), std::string::npos) << st.out;
  const CommandResult refused = RunCommand(hil + "merge " + b);
  EXPECT_EQ(refused.exit_code, 3) << refused.out;
  EXPECT_NE(refused.out.find("merge refused"), std::string::npos) << refused.out;
  EXPECT_FALSE(fs::exists(b + "/summary.json"));
  const CommandResult partial = RunCommand(hil + "merge " + b + " --allow-partial");
  EXPECT_EQ(partial.exit_code, 3) << partial.out;
  EXPECT_NE(ReadFile(b + "/report.md").find("partial merge"), std::string::npos);

  // only the missing shard again; then a resubmitted shard finds its runs recorded
  const CommandResult s3 = RunCommand(hil + file + " --shard 3/3 --out " + b);
  ASSERT_EQ(s3.exit_code, 0) << s3.out;
  EXPECT_NE(s3.out.find("4 run(s) ran, 0 already recorded"), std::string::npos) << s3.out;
  const CommandResult again = RunCommand(hil + file + " --shard 1/3 --out " + b);
  EXPECT_NE(again.out.find("0 run(s) ran, 4 already recorded"), std::string::npos) << again.out;
  EXPECT_EQ(RunCommand(hil + "status " + b).exit_code, 0);
  const CommandResult merged = RunCommand(hil + "merge " + b);
  EXPECT_EQ(merged.exit_code, local.exit_code) << merged.out;
  for (const char* f : {"summary.json", "report.md", "report.html", "junit.xml",
                        "plots/cdf_horizontal_rmse_m.svg"}) {
    const std::string x = ReadFile(dir / "local/" + f);
    EXPECT_FALSE(x.empty()) << f;
    EXPECT_TRUE(x == ReadFile(b + "/" + f)) << f << " differs between --local and 3 shards";
  }
  // the sweep reached the runs: the larger sigma gives the larger error on average
  const std::string md = ReadFile(b + "/report.md");
  EXPECT_NE(md.find("gnss.errors.horizontal_sigma_m = 0.4"), std::string::npos) << md;
  // a folder keeps its shard count
  const CommandResult other = RunCommand(hil + file + " --shard 1/2 --out " + b);
  EXPECT_EQ(other.exit_code, 2) << other.out;
  EXPECT_NE(other.out.find("planned for 3 shard(s)"), std::string::npos) << other.out;
}

TEST(CampaignE2eTest, BadCampaignFileExitsTwoNamingLineAndField) {
  TempDir dir("campaign_e2e_bad");
  const std::string path = dir / "bad.yaml";
  WriteFile(path, "name: bad\nscenarios: [" + SourceDir() +
                      "/vectors/scenarios/seed000_gps_only.yaml]\nseeds: {from: 1, to: 0}\n");
  const CommandResult r = RunCommand(BinDir() + "/hil campaign " + path + " --local");
  EXPECT_EQ(r.exit_code, 2) << r.out;
  EXPECT_NE(r.out.find(path + ":3: seeds.to:"), std::string::npos) << r.out;
  const CommandResult none = RunCommand(BinDir() + "/hil campaign " + path);
  EXPECT_EQ(none.exit_code, 2) << none.out;
}

}  // namespace
}  // namespace hil::test

// `hil suite` is the simple case of a campaign (campaign_plan.h): the scenario files of a folder,
// optionally with seeds, run here and merged by the campaign engine into the same outputs.
#include "hil/harness/suite/suite.h"

#include <unistd.h>

#include <algorithm>
#include <filesystem>
#include <optional>
#include <stdexcept>

#include "hil/harness/campaign/campaign_merge.h"
#include "hil/harness/campaign/campaign_runner.h"
#include "hil/harness/devices/scenario_file.h"
#include "hil/harness/scenario/scenario.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

// A scenario whose figure is a claim about a distribution (its `statistical:` section) runs over
// its seeds (unless --seed/--seeds name the seeds of every scenario) and its criteria across them
// join the campaign's. An invalid file is left to the runs, which report it.
void AddStatisticalClaims(CampaignSpec& spec, const SuiteOptions& opt) {
  for (const std::string& file : spec.scenario_files) {
    std::optional<Scenario> s;
    try {
      s = LoadScenario(file, opt.short_form);
    } catch (const std::exception&) {
      continue;
    }
    if (s->statistical_seeds == 0) continue;
    if (spec.seeds.empty()) {
      std::vector<std::uint64_t>& seeds = spec.file_seeds[file];
      for (int i = 0; i < s->statistical_seeds; ++i)
        seeds.push_back(s->seed + static_cast<std::uint64_t>(i));
    }
    spec.criteria.insert(spec.criteria.end(), s->statistical_criteria.begin(),
                         s->statistical_criteria.end());
  }
}

CampaignSpec SuiteSpec(const std::vector<std::string>& files, const SuiteOptions& opt) {
  CampaignSpec spec;
  spec.name = "suite-" + fs::path(opt.dir).lexically_normal().filename().string();
  spec.title = "Acceptance suite: our figures beside the papers'";
  spec.source = opt.dir;
  spec.scenario_files = files;
  spec.short_form = opt.short_form;
  if (opt.seed || opt.repeat > 1) {
    for (int i = 0; i < std::max(1, opt.repeat); ++i)
      spec.seeds.push_back(opt.seed.value_or(1) + static_cast<std::uint64_t>(i));
  }
  spec.run_args = opt.run_args;
  AddStatisticalClaims(spec, opt);
  return spec;
}

}  // namespace

std::vector<std::string> SuiteScenarios(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec))
    throw std::runtime_error("cannot read the scenario folder " + dir);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(dir)) {
    const std::string ext = e.path().extension().string();
    if (e.is_regular_file() && (ext == ".yaml" || ext == ".yml"))
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

SuiteResult RunSuite(const SuiteOptions& opt) {
  const CampaignPlan plan = PlanCampaign(SuiteSpec(SuiteScenarios(opt.dir), opt));
  // a suite runs everything again: what an earlier suite left in the folder is removed
  std::error_code ec;
  for (const char* old : {"campaign.json", "records", "runs", "shards"})
    fs::remove_all(fs::path(opt.out_dir) / old, ec);
  const CampaignFolder folder = PrepareCampaignFolder(opt.out_dir, plan, 1);
  std::vector<std::size_t> all(plan.runs.size());
  for (std::size_t k = 0; k < all.size(); ++k) all[k] = k;
  RunnerOptions ro;
  ro.hil_exe = opt.hil_exe;
  ro.jobs = opt.jobs;
  ro.label = "suite";
  ro.live = isatty(STDERR_FILENO) != 0;
  RunCampaignRuns(folder, all, ro);
  const MergeOutcome m = MergeCampaign(folder, false);
  if (!m.written) throw std::runtime_error("runs are missing from " + opt.out_dir + "/records");
  SuiteResult result;
  result.runs = m.summary["runs"].size();
  result.passed = m.summary.value("passed", 0UL);
  result.failed = m.summary.value("failed", 0UL);
  result.invalid = m.summary.value("invalid", 0UL);
  for (const auto& c : m.summary.value("criteria", nlohmann::json::array()))
    result.criteria_failed += c.value("pass", false) ? 0 : 1;
  return result;
}

}  // namespace hil::harness

#include "hil/harness/core/truth_table.h"

#include <chrono>
#include <vector>

#include <gtest/gtest.h>

#include "../run/expect_same_sample.h"
#include "../truth/truth_test_scenarios.h"

namespace hil::harness {
namespace {

using testing::ExpectSameSample;

// The 10 Hz grid over `seconds` and, in each of its first `seconds` seconds, a time 3 ms after the
// whole second (between a 100 Hz run's samples); both asked of `builder`.
struct AskedTimes {
  std::vector<Time> grid, between;
};
AskedTimes AskGridAndBetween(TruthTableBuilder& builder, int seconds) {
  AskedTimes a;
  for (int k = 0; k <= 10 * seconds; ++k) a.grid.push_back(TimeFromNs(k * 100'000'000LL));
  for (int k = 0; k < seconds; ++k)
    a.between.push_back(TimeFromNs(k * 1'000'000'000LL + 3'000'000));
  builder.Ask(a.grid);
  builder.Ask(a.between);
  return a;
}

truth::TruthConfig ClosedLoopConfig() {
  truth::TruthConfig config;
  config.origin = {35.4796096, 50.5979765, 1300};
  config.vehicle = truth::VehicleParams::Tractor();
  config.heading_deg = 90;
  config.external_commands = true;
  config.command_period_s = 0.01;
  return config;
}

TEST(TruthTableBuilderTest, OfferedSamplesServeTheirTimesAndTheThreadIntegratesTheRest) {
  // GIVEN the rough-ground rectangle, a run that samples its truth at 100 Hz and offers every
  // sample, and a table asked for the 10 Hz grid plus times between the run's samples
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  TruthTableBuilder builder(config);
  const auto [grid, between] = AskGridAndBetween(builder, 20);
  // WHEN the run goes on, its samples offered and the watermark a second behind
  truth::TruthIntegrator run(config);
  for (int k = 0; k <= 2000; ++k) {
    const Time t = TimeFromNs(k * 10'000'000LL);
    builder.Offer(run.Sample(t));
    if (k % 50 == 0) builder.Advance(t - std::chrono::seconds(1));
  }
  const TruthTable table = builder.Finish();
  // THEN every time is there, as a fresh integration gives it, and only the times between the
  // run's samples were integrated again
  std::vector<Time> all = grid;
  all.insert(all.end(), between.begin(), between.end());
  const TruthTable fresh(config, all);
  for (const Time t : all) {
    ASSERT_TRUE(table.Has(t));
    ExpectSameSample(table.At(t), fresh.At(t));
  }
  EXPECT_EQ(builder.offered_hits(), grid.size());
  EXPECT_EQ(builder.integrated(), between.size());
}

TEST(TruthTableBuilderTest, WithoutOffersTheThreadIntegratesEveryTime) {
  const truth::TruthConfig config = truth::testing::RoughTurningConfig();
  std::vector<Time> times;
  for (int k = 0; k <= 50; ++k) times.push_back(TimeFromNs(k * 100'000'000LL));
  TruthTableBuilder builder(config);
  builder.Ask(times);
  builder.Advance(TimeFromNs(3'000'000'000LL));
  const TruthTable table = builder.Finish();
  const TruthTable fresh(config, times);
  for (const Time t : times) ExpectSameSample(table.At(t), fresh.At(t));
  EXPECT_EQ(builder.offered_hits(), 0u);
  EXPECT_EQ(builder.integrated(), times.size());
}

TEST(TruthTableBuilderTest, ClosedLoopCopiesTheRunsSamplesAndReplaysTheCommandsForTheRest) {
  // GIVEN a closed-loop truth whose steering command changes every 100 ms as a run sets it (the
  // first command at t = 0, acting from the start) and gives it to the builder, a table asked for
  // the 10 Hz grid and for times between the run's samples, and the run's 100 Hz samples offered
  // except the one taken at t = 0 before the first command (it re-integrates: restart_pending)
  const truth::TruthConfig config = ClosedLoopConfig();
  TruthTableBuilder builder(config);
  const auto [grid, between] = AskGridAndBetween(builder, 10);
  truth::TruthIntegrator run(config);
  std::vector<VehicleCommand> commands;
  std::size_t offered = 0;
  for (int k = 0; k <= 1000; ++k) {
    const Time t = TimeFromNs(k * 10'000'000LL);
    const TruthSample s = run.Sample(t);
    if (k % 10 == 0) {
      const Time t_effect = k == 0 ? t : t + std::chrono::milliseconds(10);
      const double steer_rad = (k / 50) % 2 ? 0.05 : -0.05;
      commands.push_back({t_effect, 1.0, steer_rad});
      run.SetCommand(t_effect, 1.0, steer_rad);
      builder.Command(commands.back());
    }
    if (!run.restart_pending()) {
      builder.Offer(s);
      ++offered;
    }
    if (k % 50 == 0) builder.Advance(t - std::chrono::seconds(1));
  }
  // WHEN the run ends, having given the builder its commands as it went
  const TruthTable table = builder.Finish();
  // THEN every time is the replay's bit for bit; the run's samples served the grid but t = 0,
  // whose sample preceded the first command
  std::vector<Time> all = grid;
  all.insert(all.end(), between.begin(), between.end());
  const TruthTable replay(config, all, commands);
  for (const Time t : all) {
    ASSERT_TRUE(table.Has(t));
    ExpectSameSample(table.At(t), replay.At(t));
  }
  EXPECT_EQ(run.late_command_restarts(), 0);
  EXPECT_EQ(offered, 1000u);
  EXPECT_EQ(builder.offered_hits(), grid.size() - 1);
}

TEST(TruthTableBuilderTest, ALateCommandDropsTheRunsSamplesFromItsTimeOn) {
  // GIVEN samples offered by a run obeying 1 m/s, and then a command for t = 0 (2 m/s) that came
  // late: the run's truth had passed its instant and re-integrates
  const truth::TruthConfig config = ClosedLoopConfig();
  std::vector<Time> times;
  for (int k = 0; k <= 30; ++k) times.push_back(TimeFromNs(k * 100'000'000LL));
  const std::vector<VehicleCommand> commands{{Time{}, 1.0, 0.0}, {Time{}, 2.0, 0.0}};
  TruthTableBuilder builder(config);
  builder.Ask(times);
  builder.Command(commands[0]);
  truth::TruthIntegrator stale(config);
  stale.SetCommand(Time{}, 1.0, 0.0);
  for (const Time t : times) builder.Offer(stale.Sample(t));
  // WHEN the late command comes before the builder took any of them
  builder.Command(commands[1], true);
  builder.Advance(times.back());
  const TruthTable table = builder.Finish();
  // THEN the table is the commands' truth, not the stale samples, and none was scored stale
  const TruthTable replay(config, times, commands);
  for (const Time t : times) ExpectSameSample(table.At(t), replay.At(t));
  EXPECT_NEAR(table.At(times.back()).p_NB_N_m.x(), 6.0, 1e-6);  // 3 s at 2 m/s, east
  EXPECT_EQ(builder.offered_hits(), 0u);
  EXPECT_EQ(builder.stale_samples(), 0u);
}

TEST(TruthTableBuilderTest, ALateCommandBehindWhatWasTakenIsCountedStale) {
  // GIVEN a builder that has taken its first 2 s of times
  const truth::TruthConfig config = ClosedLoopConfig();
  TruthTableBuilder builder(config);
  builder.Command({Time{}, 1.0, 0.0});
  std::vector<Time> times;
  for (int k = 0; k <= 20; ++k) times.push_back(TimeFromNs(k * 100'000'000LL));
  builder.Ask(times);
  builder.Advance(TimeFromSeconds(2));
  builder.WaitTaken(TimeFromSeconds(2));
  // WHEN a command for t = 1 s comes late
  builder.Command({TimeFromSeconds(1), 2.0, 0.0}, true);
  // THEN the times taken cannot be scored again: it is counted
  EXPECT_EQ(builder.stale_samples(), 1u);
  builder.Finish();
}

}  // namespace
}  // namespace hil::harness

// The run's diagnostics (run_diagnostics.h): a value each run owns, the first failure kept.
#include "hil/harness/core/run_diagnostics.h"

#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

TEST(RunDiagnosticsTest, KeepsTheFirstWriteFailure) {
  RunDiagnostics d;
  EXPECT_FALSE(d.FirstWriteFailure());
  d.NoteWriteFailure("run/captures/ttyGPS.cap");
  d.NoteWriteFailure("run/estimate.jsonl");
  ASSERT_TRUE(d.FirstWriteFailure());
  EXPECT_EQ(*d.FirstWriteFailure(), "run/captures/ttyGPS.cap");
}

TEST(RunDiagnosticsTest, TwoRunsDoNotShareTheirFailures) {
  // one value per run: what one run noted is not seen by another, before or after it
  RunDiagnostics first, second;
  first.NoteWriteFailure("a/captures/ttyIMU.cap");
  EXPECT_FALSE(second.FirstWriteFailure());
  second.NoteWriteFailure("b/estimate.jsonl");
  EXPECT_EQ(*first.FirstWriteFailure(), "a/captures/ttyIMU.cap");
  EXPECT_EQ(*second.FirstWriteFailure(), "b/estimate.jsonl");
  EXPECT_FALSE(RunDiagnostics().FirstWriteFailure());
}

TEST(RunDiagnosticsTest, WritersOnSeveralThreadsNoteOneFailure) {
  RunDiagnostics d;
  std::vector<std::thread> writers;
  for (int i = 0; i < 4; ++i) {
    writers.emplace_back([&d, i] {
      for (int k = 0; k < 1000; ++k) d.NoteWriteFailure("link" + std::to_string(i));
    });
  }
  for (auto& w : writers) w.join();
  ASSERT_TRUE(d.FirstWriteFailure());
  const std::string first = d.FirstWriteFailure().value_or("");
  EXPECT_TRUE(first == "link0" || first == "link1" || first == "link2" || first == "link3")
      << first;
}

}  // namespace
}  // namespace hil::harness

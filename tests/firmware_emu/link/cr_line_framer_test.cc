#include "hil/firmware_emu/link/cr_line_framer.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil::link {
namespace {

std::vector<std::string> FeedAll(CrLineFramer& f, const std::string& bytes) {
  std::vector<std::string> lines;
  for (const char c : bytes) {
    if (f.Feed(c)) lines.push_back(f.line());
  }
  return lines;
}

TEST(CrLineFramerTest, SplitsOnCarriageReturnAcrossWritesAndIgnoresLineFeed) {
  CrLineFramer f(32);
  for (const char c : std::string("m 1")) EXPECT_FALSE(f.Feed(c));
  const auto lines = FeedAll(f, "0 2\r\ne\r");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "m 10 2");
  EXPECT_EQ(lines[1], "e");
}

TEST(CrLineFramerTest, ABareCarriageReturnIsAnEmptyLine) {
  CrLineFramer f(8);
  const auto lines = FeedAll(f, "\r\r");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_TRUE(lines[0].empty());
}

TEST(CrLineFramerTest, ALineOfTheLimitIsKeptOneLongerIsDiscardedUpToItsCarriageReturn) {
  CrLineFramer f(4);
  const auto lines = FeedAll(f, "abcd\rabcde");
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0], "abcd");
  EXPECT_TRUE(f.discarding());
  EXPECT_EQ(f.overlong_lines(), 0u) << "counted when its CR comes";
  const auto after = FeedAll(f, "fgh\rok\r");
  EXPECT_FALSE(f.discarding());
  EXPECT_EQ(f.overlong_lines(), 1u);
  ASSERT_EQ(after.size(), 1u);
  EXPECT_EQ(after[0], "ok");
}

}  // namespace
}  // namespace hil::link

// CommandLinkLoss: a window cuts what arrives in [start, end), counted against that window; the
// total is the windows' sum.
#include "hil/firmware_emu/actuator/command_link_loss.h"

#include <gtest/gtest.h>

namespace hil::actuator {
namespace {

Time At(double s) { return Time{} + DurationFromSeconds(s); }

TEST(CommandLinkLossTest, CutsInsideItsWindowsOnlyAndCountsEachWindow) {
  CommandLinkLoss loss({{At(15), At(16)}, {At(30), At(31.5)}});
  EXPECT_FALSE(loss.Cuts(At(14.999), 12));
  EXPECT_TRUE(loss.Cuts(At(15), 12));  // the start belongs to the window
  EXPECT_TRUE(loss.Cuts(At(15.5), 8));
  EXPECT_FALSE(loss.Cuts(At(16), 12));  // the end does not
  EXPECT_TRUE(loss.Cuts(At(31.4), 1));
  EXPECT_FALSE(loss.Cuts(At(40), 1));
  EXPECT_EQ(loss.per_window(), (std::vector<std::uint64_t>{20, 1}));
  EXPECT_EQ(loss.total(), 21u);
}

TEST(CommandLinkLossTest, NoWindowsCutNothing) {
  CommandLinkLoss loss({});
  EXPECT_FALSE(loss.Cuts(At(0), 5));
  EXPECT_TRUE(loss.per_window().empty());
  EXPECT_EQ(loss.total(), 0u);
}

}  // namespace
}  // namespace hil::actuator

// The vcan send counter: read from the interface's tx_packets, relative to its value when made,
// only for a virtual interface; a real interface or an unreadable counter gives none.
#include "hil/harness/links/bus_tx_counter.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

class BusTxCounterTest : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = fs::temp_directory_path() / ("bus_tx_counter_test_" + std::to_string(::getpid()));
    fs::remove_all(root_);
  }
  void TearDown() override { fs::remove_all(root_); }
  void Interface(const std::string& iface, bool is_virtual, const std::string& tx) {
    fs::create_directories(root_ / "class/net" / iface / "statistics");
    if (is_virtual) fs::create_directories(root_ / "devices/virtual/net" / iface);
    SetTx(iface, tx);
  }
  void SetTx(const std::string& iface, const std::string& tx) {
    std::ofstream(root_ / "class/net" / iface / "statistics/tx_packets") << tx;
  }
  fs::path root_;
};

TEST_F(BusTxCounterTest, CountsTheFramesSentSinceItWasMade) {
  Interface("vcan0", true, "1000\n");
  const BusTxCounter c("vcan0", root_.string());
  ASSERT_TRUE(c.available());
  EXPECT_EQ(c.SentSinceStart(), 0u);
  SetTx("vcan0", "1017\n");
  EXPECT_EQ(c.SentSinceStart(), 17u);
}

TEST_F(BusTxCounterTest, ARealInterfaceIsNotCounted) {
  Interface("can0", false, "5\n");
  const BusTxCounter c("can0", root_.string());
  EXPECT_FALSE(c.available());
  EXPECT_EQ(c.SentSinceStart(), std::nullopt);
}

TEST_F(BusTxCounterTest, AnUnreadableOrResetCounterGivesNone) {
  Interface("vcan1", true, "40\n");
  const BusTxCounter c("vcan1", root_.string());
  SetTx("vcan1", "3\n");  // the interface was deleted and made again
  EXPECT_EQ(c.SentSinceStart(), std::nullopt);
  SetTx("vcan1", "garbage");
  EXPECT_EQ(c.SentSinceStart(), std::nullopt);
  EXPECT_FALSE(BusTxCounter("no_such_if", root_.string()).available());
  EXPECT_FALSE(BusTxCounter("../vcan1", root_.string()).available());
}

}  // namespace
}  // namespace hil::harness

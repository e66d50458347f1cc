// hil validate --protocol can on a live interface: what is an interface, and the clear error on a
// kernel without CAN (the listening itself runs in the vcan VM: tests/vcan, vcan_e2e_can_scenario).
#include "hil/harness/validate/validate_can_live.h"

#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/socketcan_port.h"

namespace hil::harness {
namespace {

TEST(ValidateCanLiveTest, InterfaceNamesAreNotFiles) {
  if (std::filesystem::exists("/sys/class/net/lo")) {
    EXPECT_TRUE(IsNetworkInterface("lo"));
  }
  EXPECT_FALSE(IsNetworkInterface("nosuchif9"));
  EXPECT_FALSE(IsNetworkInterface("/sys/class/net/lo"));
  EXPECT_FALSE(IsNetworkInterface(""));
  const std::string here = ::testing::TempDir() + "/validate_can_live_test.candump";
  std::ofstream(here) << "(0.000000) vcan0 123#00\n";
  EXPECT_FALSE(IsNetworkInterface(here));
  std::filesystem::remove(here);
}

TEST(ValidateCanLiveTest, KernelWithoutCanGivesAClearError) {
  if (link::SocketCanPort::Available()) GTEST_SKIP() << "this kernel has CAN";
  try {
    ValidateCanInterface("vcan0", 0.1);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("run_in_vm"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hil::harness

// The emulators' serial links and navd each keep a baud table (the dependency rule keeps the
// estimator and the emulators apart): both must list the same rates with the same termios
// constants, so every rate a scenario can give a link is one navd can open its device at.
#include <termios.h>

#include <gtest/gtest.h>

#include "hil/estimator/navd/serial_bauds.h"
#include "hil/firmware_emu/link/baud_table.h"

namespace {

TEST(BaudTablesTest, EmulatorAndNavdListTheSameRatesAndConstants) {
  ASSERT_EQ(hil::link::kBaudSpeeds.size(), hil::navd::kSerialBauds.size());
  for (std::size_t i = 0; i < hil::link::kBaudSpeeds.size(); ++i) {
    EXPECT_EQ(hil::link::kBaudSpeeds[i].baud, hil::navd::kSerialBauds[i].baud) << "entry " << i;
    EXPECT_EQ(hil::link::kBaudSpeeds[i].speed, hil::navd::kSerialBauds[i].speed) << "entry " << i;
  }
}

TEST(BaudTablesTest, LookupsAgreeAndRejectOtherRates) {
  for (const hil::link::BaudSpeed& b : hil::link::kBaudSpeeds) {
    EXPECT_EQ(hil::link::BaudToSpeed(b.baud), b.speed);
    ASSERT_TRUE(hil::navd::SerialSpeed(b.baud).has_value());
    EXPECT_EQ(*hil::navd::SerialSpeed(b.baud), b.speed);
  }
  EXPECT_EQ(hil::link::BaudToSpeed(9600), static_cast<unsigned>(B9600));
  EXPECT_EQ(hil::link::BaudToSpeed(115200), static_cast<unsigned>(B115200));
  for (const int other : {0, 300, 14400, 28800, 76800, 1000000}) {
    EXPECT_EQ(hil::link::BaudToSpeed(other), 0u) << other;
    EXPECT_FALSE(hil::navd::SerialSpeed(other).has_value()) << other;
  }
}

}  // namespace

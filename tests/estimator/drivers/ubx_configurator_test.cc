#include "hil/estimator/drivers/ubx_configurator.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/neo5m_device.h"

namespace hil::estimator::drivers {
namespace {

constexpr std::int64_t kSecond = 1'000'000'000;

UbxMessage Ack(bool ok, std::uint8_t cls, std::uint8_t id) {
  UbxMessage m;
  m.cls = 0x05;
  m.id = ok ? 0x01 : 0x00;
  m.ack_cls = cls;
  m.ack_id = id;
  return m;
}

TEST(UbxConfiguratorTest, CommandsAreWellFormedCfgFrames) {
  const auto cmds = UbxSetupCommands({.rate_hz = 4, .ubx_navigation = true, .nmea_off = true});
  ASSERT_EQ(cmds.size(), 1u + 6u + 4u);
  EXPECT_EQ(cmds.back().name, "CFG-RATE 250 ms");
  // B5 62 06 08 06 00 | FA 00 01 00 01 00 | checksum
  const std::string rate = cmds.back().frame;
  ASSERT_EQ(rate.size(), 14u);
  EXPECT_EQ(static_cast<unsigned char>(rate[0]), 0xB5);
  EXPECT_EQ(static_cast<unsigned char>(rate[3]), 0x08);
  EXPECT_EQ(static_cast<unsigned char>(rate[6]), 0xFA);
  EXPECT_EQ(cmds[0].name, "CFG-MSG NMEA-GGA 0");
  EXPECT_EQ(cmds[cmds.size() - 2].name, "CFG-MSG NAV-TIMEGPS 1");
  // every frame decodes back with a valid checksum
  int frames = 0;
  UbxDecoder dec([&](const UbxMessage&) { ++frames; });
  for (const auto& c : cmds) dec.Feed(c.frame);
  EXPECT_EQ(dec.stats().bad_checksum, 0u);
  EXPECT_EQ(dec.stats().frames_ok, cmds.size());
  EXPECT_TRUE(UbxSetupCommands({}).empty()) << "nothing asked, nothing sent";
  const auto minimal = UbxSetupCommands({.nmea_minimal = true});
  ASSERT_EQ(minimal.size(), 4u + 2u) << "GLL, GSA, GSV, VTG off; GGA, RMC on";
}

TEST(UbxConfiguratorTest, WaitsForEachAckRetriesAndGivesUp) {
  UbxConfigurator c(UbxSetupCommands({.rate_hz = 5, .ubx_navigation = true}), kSecond, 2);
  ASSERT_EQ(c.commands().size(), 5u);
  auto first = c.Poll(0);
  ASSERT_TRUE(first);
  EXPECT_EQ(*first, c.commands()[0].frame);
  EXPECT_FALSE(c.Poll(kSecond / 2)) << "waits for the ACK";
  c.OnMessage(Ack(true, 0x06, 0x08));  // an ACK of CFG-RATE does not settle the CFG-MSG in flight
  EXPECT_FALSE(c.Poll(kSecond / 2));
  EXPECT_EQ(c.commands()[0].result, UbxCommand::Result::kPending);
  EXPECT_EQ(c.Poll(kSecond + 1).value_or(""), c.commands()[0].frame) << "retried after the timeout";
  c.OnMessage(Ack(true, 0x06, 0x01));
  EXPECT_EQ(c.commands()[0].result, UbxCommand::Result::kAcked);
  EXPECT_EQ(c.commands()[0].attempts, 2);
  // the next one is refused
  EXPECT_EQ(c.Poll(kSecond + 2).value_or(""), c.commands()[1].frame);
  c.OnMessage(Ack(false, 0x06, 0x01));
  EXPECT_EQ(c.commands()[1].result, UbxCommand::Result::kNaked);
  // the receiver goes silent: two sends each, then given up
  std::int64_t t = 2 * kSecond;
  int sends = 0;
  while (!c.done()) {
    if (c.Poll(t)) ++sends;
    t += kSecond / 4;
    ASSERT_LT(t, 100 * kSecond);
  }
  EXPECT_EQ(sends, 3 * 2);
  EXPECT_EQ(c.commands()[4].result, UbxCommand::Result::kTimedOut);
  EXPECT_FALSE(c.all_acked());
  EXPECT_EQ(c.Summary(),
            "5 commands: 1 acked, 1 refused, 3 unanswered (CFG-MSG NAV-VELNED 1 NAK, CFG-MSG "
            "NAV-SOL 1 no answer, "
            "CFG-MSG NAV-TIMEGPS 1 no answer, CFG-RATE 200 ms no answer)");
  c.Restart();
  EXPECT_FALSE(c.done());
  EXPECT_EQ(c.Poll(t).value_or(""), c.commands()[0].frame);
}

// The emulated NEO-5M as the independent peer: the configurator switches it from its default NMEA
// output to UBX navigation at 4 Hz, and the receiver's stream changes accordingly.
TEST(UbxConfiguratorTest, ConfiguresTheEmulatedNeo5m) {
  gnss::Neo5mConfig cfg;
  cfg.start_utc = gnss::ParseIsoUtc("2013-06-10T08:00:00Z");
  gnss::Neo5mDevice rx(cfg, 7);
  UbxConfigurator conf(UbxSetupCommands({.rate_hz = 4, .ubx_navigation = true, .nmea_off = true}));
  UbxDecoder dec([&](const UbxMessage& m) { conf.OnMessage(m); });
  std::vector<std::string> names;
  int nav_posllh = 0, nmea = 0;
  TruthSample truth;
  truth.lat_deg = 35.4796096, truth.lon_deg = 50.5979765, truth.height_m = 1312.0;
  const auto take = [&](const DeviceOutput& out) {
    for (const auto& m : out.serial) {
      dec.Feed(m.bytes);
      if (ToSeconds(m.t_ready) > 10.0) {
        nav_posllh += m.name == "UBX-NAV-POSLLH" ? 1 : 0;
        nmea += m.name.rfind("NMEA-", 0) == 0 ? 1 : 0;
      }
    }
  };
  while (rx.next_event_time() < TimeFromSeconds(20)) {
    const Time t = rx.next_event_time();
    DeviceOutput out;
    truth.t = t;
    rx.OnEvent(truth, out);
    take(out);
    // the host answers between epochs, on its own clock (here the same one)
    const std::int64_t now_ns = ToNs(t);
    if (auto bytes = conf.Poll(now_ns)) {
      DeviceOutput reply;
      rx.OnHostBytes(0, t + std::chrono::milliseconds(1), *bytes, reply);
      take(reply);
    }
  }
  EXPECT_TRUE(conf.done());
  EXPECT_TRUE(conf.all_acked()) << conf.Summary();
  EXPECT_EQ(nmea, 0) << "NMEA switched off";
  EXPECT_NEAR(nav_posllh, 40, 1) << "NAV-POSLLH at 4 Hz over the last 10 s";
}

}  // namespace
}  // namespace hil::estimator::drivers

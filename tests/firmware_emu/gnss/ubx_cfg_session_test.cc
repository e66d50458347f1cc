#include "hil/firmware_emu/gnss/ubx_cfg_session.h"

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/receiver_profile.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/gnss/ubx_messages.h"

namespace hil::gnss::ubx {
namespace {

ReceiverSettings Neo5mDefaults() {
  const ReceiverProfile p = ProfileByName("neo-5m");
  return ReceiverSettings::Defaults(9600, 1000, p.nmea_rates);
}

class CfgSessionTest : public ::testing::Test {
 protected:
  std::vector<Reply> Send(std::uint8_t id, std::vector<std::uint8_t> payload) {
    fx = {};
    return session.Handle(id, payload, kUart1, fx);
  }
  static std::vector<std::uint8_t> PayloadOf(const std::string& frame) {
    return std::vector<std::uint8_t>(frame.begin() + 6, frame.end() - 2);
  }
  UbxCfgSession session{Neo5mDefaults(), ProfileByName("neo-5m").cfg_rate_max_hz};
  CfgEffects fx;
};

TEST_F(CfgSessionTest, PrtSetChangesBaudAndPollReportsIt) {
  Writer w;
  w.U1(1).U1(0).U2(0).U4(0x8D0).U4(115200).U2(0x07).U2(0x01).U2(0).U2(0);
  auto r = Send(0x00, w.bytes());
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].bytes, Ack(true, 0x06, 0x00));
  EXPECT_EQ(session.current().ports[kUart1].baud, 115200u);
  EXPECT_EQ(session.current().ports[kUart1].out_mask, kProtoUbx);
  r = Send(0x00, {1});  // poll UART1
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(r[0].name, "UBX-CFG-PRT");
  const auto p = PayloadOf(r[0].bytes);
  ASSERT_EQ(p.size(), 20u);
  EXPECT_EQ(Reader(p).U4(8), 115200u);
  EXPECT_EQ(Reader(p).U4(4), 0x8D0u);
  EXPECT_EQ(r[1].bytes, Ack(true, 0x06, 0x00));
}

TEST_F(CfgSessionTest, PrtRefusesUnsupportedBaud) {
  Writer w;
  w.U1(1).U1(0).U2(0).U4(0x8D0).U4(12345).U2(0x07).U2(0x03).U2(0).U2(0);
  const auto r = Send(0x00, w.bytes());
  ASSERT_EQ(r.size(), 1u);
  EXPECT_EQ(r[0].bytes, Ack(false, 0x06, 0x00));
  EXPECT_EQ(session.current().ports[kUart1].baud, 9600u);
}

TEST_F(CfgSessionTest, MsgAllThreeFormsAndPoll) {
  EXPECT_EQ(session.current().Rate(0xF0, 0x00), 1);                           // GGA on by default
  EXPECT_EQ(Send(0x01, {0x01, 0x06, 0x01})[0].bytes, Ack(true, 0x06, 0x01));  // port form
  EXPECT_EQ(session.current().Rate(0x01, 0x06), 1);
  EXPECT_EQ(Send(0x01, {0xF0, 0x00, 0, 0, 0, 0, 0, 0})[0].bytes,
            Ack(true, 0x06, 0x01));  // 6-target form
  EXPECT_EQ(session.current().Rate(0xF0, 0x00), 0);
  const auto r = Send(0x01, {0x01, 0x06});  // poll
  ASSERT_EQ(r.size(), 2u);
  EXPECT_EQ(PayloadOf(r[0].bytes), (std::vector<std::uint8_t>{0x01, 0x06, 0, 1, 0, 0, 0, 0}));
  // a message a u-blox 5 does not have (NAV-PVT) is refused
  EXPECT_EQ(Send(0x01, {0x01, 0x07, 0x01})[0].bytes, Ack(false, 0x06, 0x01));
}

// Issue 40 (minor): PX4 asks every receiver for 5 Hz (200 ms) and got a NAK (the profile's 4 Hz
// data-sheet maximum was enforced). The NEO-5M profile acknowledges and runs it
// (receiver_profile.h says why); periods shorter than its 100 ms floor are NAKed, navRate stays 1.
TEST_F(CfgSessionTest, RateAcksAndRunsPx4sFiveHertzKeepsNavRateOne) {
  EXPECT_EQ(Send(0x08, {0xFA, 0x00, 0x01, 0x00, 0x01, 0x00})[0].bytes,
            Ack(true, 0x06, 0x08));  // 250 ms
  EXPECT_EQ(session.current().meas_rate_ms, 250);
  EXPECT_EQ(Send(0x08, {0xC8, 0x00, 0x01, 0x00, 0x01, 0x00})[0].bytes,
            Ack(true, 0x06, 0x08));  // 200 ms, PX4's 5 Hz
  EXPECT_EQ(session.current().meas_rate_ms, 200);
  EXPECT_EQ(Send(0x08, {0x64, 0x00, 0x01, 0x00, 0x01, 0x00})[0].bytes,
            Ack(true, 0x06, 0x08));  // 100 ms
  EXPECT_EQ(Send(0x08, {0x32, 0x00, 0x01, 0x00, 0x01, 0x00})[0].bytes,
            Ack(false, 0x06, 0x08));  // 50 ms: below the floor
  EXPECT_EQ(Send(0x08, {0xE8, 0x03, 0x02, 0x00, 0x01, 0x00})[0].bytes,
            Ack(false, 0x06, 0x08));  // navRate 2
  EXPECT_EQ(session.current().meas_rate_ms, 100);
  const auto r = Send(0x08, {});
  EXPECT_EQ(PayloadOf(r[0].bytes), (std::vector<std::uint8_t>{0x64, 0x00, 0x01, 0x00, 0x01, 0x00}));
}

TEST_F(CfgSessionTest, Nav5PollReturnsTheUblox5DefaultFrame) {
  const auto r = Send(0x24, {});
  ASSERT_EQ(r.size(), 2u);
  // the u-blox 5 CFG-NAV5 frame of the fact sheet (§1), mask reported as all ones
  const std::string expect = Frame(
      0x06, 0x24, std::vector<std::uint8_t>{0xFF, 0xFF, 0x00, 0x03, 0,    0,    0,    0,    0x10,
                                            0x27, 0,    0,    0x05, 0x00, 0xFA, 0x00, 0xFA, 0x00,
                                            0x64, 0x00, 0x2C, 0x01, 0x00, 0,    0,    0,    0,
                                            0,    0,    0,    0,    0,    0,    0,    0,    0});
  EXPECT_EQ(r[0].bytes, expect);
  // set only the minimum elevation (mask bit 1) and a 2D-only fix mode (bit 2)
  std::vector<std::uint8_t> set(36, 0);
  set[0] = 0x06;
  set[3] = 1;
  set[12] = 15;
  EXPECT_EQ(Send(0x24, set)[0].bytes, Ack(true, 0x06, 0x24));
  EXPECT_EQ(session.current().min_elevation_deg(), 15.0);
  EXPECT_EQ(session.current().fix_mode(), FixMode::k2DOnly);
  set[0] = 0x01;
  set[2] = 1;  // dynModel 1 does not exist
  EXPECT_EQ(Send(0x24, set)[0].bytes, Ack(false, 0x06, 0x24));
}

TEST_F(CfgSessionTest, CfgCfgSavesAndHardwareResetRestores) {
  Send(0x01, {0xF0, 0x05, 0x00});                          // VTG off
  Send(0x09, {0, 0, 0, 0, 0xFF, 0xFF, 0, 0, 0, 0, 0, 0});  // save everything
  Send(0x01, {0xF0, 0x00, 0x00});                          // GGA off, not saved
  session.LoadSaved();
  EXPECT_EQ(session.current().Rate(0xF0, 0x05), 0);
  EXPECT_EQ(session.current().Rate(0xF0, 0x00), 1);
  Send(0x09, {0xFF, 0xFF, 0, 0, 0, 0, 0, 0, 0xFF, 0xFF, 0, 0});  // clear, then load the saved
  EXPECT_EQ(session.current().Rate(0xF0, 0x05), 0);
}

TEST_F(CfgSessionTest, RstRestartKinds) {
  EXPECT_EQ(Send(0x04, {0xFF, 0xFF, 0x01, 0x00})[0].bytes, Ack(true, 0x06, 0x04));
  EXPECT_EQ(fx.restart, StartKind::kCold);
  EXPECT_TRUE(fx.hardware_reset);
  Send(0x04, {0x01, 0x00, 0x02, 0x00});
  EXPECT_EQ(fx.restart, StartKind::kWarm);
  EXPECT_FALSE(fx.hardware_reset);
  Send(0x04, {0x00, 0x00, 0x02, 0x00});
  EXPECT_EQ(fx.restart, StartKind::kHot);
}

TEST_F(CfgSessionTest, MessagesOfLaterGenerationsAreRefused) {
  EXPECT_EQ(Send(0x31, std::vector<std::uint8_t>(32, 0))[0].bytes,
            Ack(false, 0x06, 0x31));                           // CFG-TP5
  EXPECT_EQ(Send(0x3E, {})[0].bytes, Ack(false, 0x06, 0x3E));  // CFG-GNSS
}

TEST_F(CfgSessionTest, PollsOfSbasTpNmeaAnswerWithMessageThenAck) {
  for (std::uint8_t id : {std::uint8_t{0x16}, std::uint8_t{0x07}, std::uint8_t{0x17}}) {
    const auto r = Send(id, {});
    ASSERT_EQ(r.size(), 2u);
    EXPECT_EQ(static_cast<std::uint8_t>(r[0].bytes[3]), id);
    EXPECT_EQ(r[1].bytes, Ack(true, 0x06, id));
  }
  EXPECT_EQ(Send(0x17, {0, 0x30, 0, 0})[0].bytes,
            Ack(false, 0x06, 0x17));  // NMEA version 3.0 unknown
}

TEST_F(CfgSessionTest, PubxSetsRatesAndPorts) {
  EXPECT_TRUE(session.HandlePubxSet("PUBX,40,GLL,0,0,0,0,0,0"));
  EXPECT_EQ(session.current().Rate(0xF0, 0x01), 0);
  EXPECT_TRUE(session.HandlePubxSet("PUBX,40,ZDA,0,2,0,0,0,0"));
  EXPECT_EQ(session.current().Rate(0xF0, 0x08), 2);
  EXPECT_TRUE(session.HandlePubxSet("PUBX,41,1,0007,0003,38400,0"));
  EXPECT_EQ(session.current().ports[kUart1].baud, 38400u);
  EXPECT_FALSE(session.HandlePubxSet("PUBX,41,1,0007,0003,1234,0"));
  EXPECT_FALSE(session.HandlePubxSet("PUBX,40,XYZ,0,1,0,0,0,0"));
}

}  // namespace
}  // namespace hil::gnss::ubx

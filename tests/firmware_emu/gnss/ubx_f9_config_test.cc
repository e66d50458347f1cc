// CFG-VALSET / VALGET / VALDEL of the emulated F9 configuration database: the values set and read
// back by their key IDs, the layers, the ACK-ACK and ACK-NAK answers (a NAK for an unknown key,
// and then nothing of the message applied) and transactions.
#include "hil/firmware_emu/gnss/ubx_f9_config.h"

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/ubx_frame.h"

namespace hil::gnss::ubx {
namespace {

namespace key = f9key;

struct Kv {
  std::uint32_t id;
  std::uint64_t value;
};

void PutLe(std::vector<std::uint8_t>& p, std::uint64_t v, std::size_t n) {
  for (std::size_t k = 0; k < n; ++k) p.push_back(static_cast<std::uint8_t>(v >> (8 * k)));
}

std::vector<std::uint8_t> ValSet(std::uint8_t layers, const std::vector<Kv>& kvs,
                                 std::uint8_t version = 0, std::uint8_t transaction = 0) {
  std::vector<std::uint8_t> p{version, layers, transaction, 0};
  for (const Kv& kv : kvs) {
    PutLe(p, kv.id, 4);
    PutLe(p, kv.value, F9ValueBytes(kv.id));
  }
  return p;
}

std::vector<std::uint8_t> KeyList(std::uint8_t head1, const std::vector<std::uint32_t>& ids) {
  std::vector<std::uint8_t> p{0, head1, 0, 0};
  for (const std::uint32_t id : ids) PutLe(p, id, 4);
  return p;
}

// The ACK class id of the last reply (0x01 ACK-ACK, 0x00 ACK-NAK) and the message it answers.
struct Ack {
  std::uint8_t ack_id, cls, id;
};
Ack LastAck(const std::vector<Reply>& r) {
  const std::string& b = r.back().bytes;
  const FrameAt f = ParseFrameAt(b);
  EXPECT_EQ(f.status, FrameAtStatus::kFrame);
  EXPECT_EQ(f.cls, 0x05);
  return {f.id, static_cast<std::uint8_t>(f.payload[0]), static_cast<std::uint8_t>(f.payload[1])};
}

TEST(UbxF9Config, DefaultsAreTheInterfaceDescriptions) {
  const F9ConfigDb db;
  EXPECT_EQ(db.Get(key::kRateMeas), 1000U);
  EXPECT_EQ(db.Get(key::kUart1Baudrate), 38400U);
  EXPECT_EQ(db.Get(key::kNmeaGgaUart1), 1U);
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 0U);
  EXPECT_EQ(db.Get(key::kNavspgConstrDgnssTo), 60U);
  EXPECT_EQ(db.Get(key::kNavhpgDgnssMode), 3U);
  EXPECT_EQ(F9ValueBytes(key::kUart1Baudrate), 4U);
  EXPECT_EQ(F9ValueBytes(key::kRateMeas), 2U);
  EXPECT_EQ(F9ValueBytes(key::kUart1InRtcm3), 1U);
}

TEST(UbxF9Config, ValsetAppliesAndAcks) {
  F9ConfigDb db;
  const auto r = db.Handle(kCfgValset, ValSet(1, {{key::kNavPvtUart1, 1},
                                                  {key::kRateMeas, 200},
                                                  {key::kUart1Baudrate, 115200},
                                                  {key::kUart1InNmea, 0}}));
  ASSERT_EQ(r.size(), 1U);
  const Ack a = LastAck(r);
  EXPECT_EQ(a.ack_id, 0x01);
  EXPECT_EQ(a.cls, 0x06);
  EXPECT_EQ(a.id, 0x8A);
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 1U);
  EXPECT_EQ(db.Get(key::kRateMeas), 200U);
  EXPECT_EQ(db.Get(key::kUart1Baudrate), 115200U);
  EXPECT_EQ(db.Get(key::kUart1InNmea), 0U);
}

TEST(UbxF9Config, UnknownKeyNaksTheWholeMessage) {
  F9ConfigDb db;
  const auto r = db.Handle(kCfgValset, ValSet(1, {{key::kNavPvtUart1, 1}, {0x20919999, 1}}));
  ASSERT_EQ(r.size(), 1U);
  EXPECT_EQ(LastAck(r).ack_id, 0x00);
  EXPECT_EQ(LastAck(r).id, 0x8A);
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 0U) << "nothing of a rejected VALSET applies";
  // a period under 25 ms is refused as well
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(1, {{key::kRateMeas, 10}}))).ack_id, 0x00);
  EXPECT_EQ(db.Get(key::kRateMeas), 1000U);
  // no layer, or a cut value: NAK
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(0, {{key::kNavPvtUart1, 1}}))).ack_id, 0x00);
  auto cut = ValSet(1, {{key::kUart1Baudrate, 9600}});
  cut.pop_back();
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, cut)).ack_id, 0x00);
}

TEST(UbxF9Config, ValgetAnswersThenAcks) {
  F9ConfigDb db;
  db.Handle(kCfgValset, ValSet(1, {{key::kRateMeas, 100}}));
  const auto r = db.Handle(kCfgValget, KeyList(kLayerRam, {key::kRateMeas, key::kUart1Baudrate}));
  ASSERT_EQ(r.size(), 2U);
  const FrameAt f = ParseFrameAt(r[0].bytes);
  ASSERT_EQ(f.status, FrameAtStatus::kFrame);
  EXPECT_EQ(f.cls, 0x06);
  EXPECT_EQ(f.id, 0x8B);
  const std::vector<std::uint8_t> p(f.payload.begin(), f.payload.end());
  std::vector<std::uint8_t> want{1, 0, 0, 0};
  PutLe(want, key::kRateMeas, 4);
  PutLe(want, 100, 2);
  PutLe(want, key::kUart1Baudrate, 4);
  PutLe(want, 38400, 4);
  EXPECT_EQ(p, want);
  EXPECT_EQ(LastAck(r).ack_id, 0x01);
  EXPECT_EQ(LastAck(r).id, 0x8B);
  // the default layer still holds 1000 ms
  const auto d = db.Handle(kCfgValget, KeyList(kLayerDefault, {key::kRateMeas}));
  const FrameAt fd = ParseFrameAt(d[0].bytes);
  EXPECT_EQ(static_cast<std::uint8_t>(fd.payload[8]) | static_cast<std::uint8_t>(fd.payload[9])
                                                           << 8,
            1000);
  // an unknown key: NAK alone
  const auto n = db.Handle(kCfgValget, KeyList(kLayerRam, {key::kRateMeas, 0x10990001}));
  ASSERT_EQ(n.size(), 1U);
  EXPECT_EQ(LastAck(n).ack_id, 0x00);
}

TEST(UbxF9Config, FlashSurvivesAResetAndValdelRemovesIt) {
  F9ConfigDb db;
  db.Handle(kCfgValset, ValSet(1 | 4, {{key::kNavPvtUart1, 1}}));  // RAM + Flash
  db.Handle(kCfgValset, ValSet(1, {{key::kNavSatUart1, 5}}));      // RAM only
  db.LoadStored();
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 1U);
  EXPECT_EQ(db.Get(key::kNavSatUart1), 0U);
  // Flash holds the key, BBR does not: VALGET on BBR NAKs, on Flash answers
  EXPECT_EQ(LastAck(db.Handle(kCfgValget, KeyList(kLayerBbr, {key::kNavPvtUart1}))).ack_id, 0x00);
  EXPECT_EQ(LastAck(db.Handle(kCfgValget, KeyList(kLayerFlash, {key::kNavPvtUart1}))).ack_id, 0x01);
  EXPECT_EQ(LastAck(db.Handle(kCfgValdel, KeyList(4, {key::kNavPvtUart1}))).ack_id, 0x01);
  db.LoadStored();
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 0U);
  EXPECT_EQ(LastAck(db.Handle(kCfgValdel, KeyList(4, {0x10990001}))).ack_id, 0x00);
  EXPECT_EQ(LastAck(db.Handle(kCfgValdel, KeyList(1, {key::kNavPvtUart1}))).ack_id, 0x00)
      << "RAM is no VALDEL layer";
}

TEST(UbxF9Config, TransactionAppliesAtItsEndOrNotAtAll) {
  F9ConfigDb db;
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(1, {{key::kNavPvtUart1, 1}}, 1, 1))).ack_id, 1);
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 0U) << "staged until the end";
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(1, {{key::kRateMeas, 500}}, 1, 3))).ack_id, 1);
  EXPECT_EQ(db.Get(key::kNavPvtUart1), 1U);
  EXPECT_EQ(db.Get(key::kRateMeas), 500U);
  // a rejected message inside a transaction drops it whole
  db.Handle(kCfgValset, ValSet(1, {{key::kNavSatUart1, 1}}, 1, 1));
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(1, {{0x20919999, 1}}, 1, 2))).ack_id, 0);
  EXPECT_EQ(LastAck(db.Handle(kCfgValset, ValSet(1, {{key::kRateMeas, 250}}, 1, 3))).ack_id, 0);
  EXPECT_EQ(db.Get(key::kNavSatUart1), 0U);
  EXPECT_EQ(db.Get(key::kRateMeas), 500U);
}

}  // namespace
}  // namespace hil::gnss::ubx

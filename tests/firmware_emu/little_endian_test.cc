#include "hil/firmware_emu/little_endian.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace hil {
namespace {

TEST(LittleEndianTest, ReadsTheLeastSignificantByteFirst) {
  const std::string b("\x34\x12\x78\x56\x34\x12\xff", 7);
  EXPECT_EQ(LeRead<std::uint16_t>(b, 0), 0x1234u);
  EXPECT_EQ(LeRead<std::uint32_t>(b, 2), 0x12345678u);
  EXPECT_EQ(LeRead(b, 0, 3), 0x781234u);
  EXPECT_EQ(LeRead(b, 6, 1), 0xFFu);
}

TEST(LittleEndianTest, SignedValuesAreTwosComplement) {
  const std::string b("\xfe\xff\x00\x80\xff\xff\xff\xff\xff\xff\xff\xff", 12);
  EXPECT_EQ(LeRead<std::int16_t>(b, 0), -2);
  EXPECT_EQ(LeRead<std::int16_t>(b, 2), -32768);
  EXPECT_EQ(LeRead<std::int64_t>(b, 4), -1);
  const auto* p = reinterpret_cast<const unsigned char*>(b.data());
  EXPECT_EQ(LeRead<std::int32_t>(p), static_cast<std::int32_t>(0x8000FFFEu));
}

TEST(LittleEndianTest, ReadsEightBytes) {
  const std::array<unsigned char, 8> b{1, 2, 3, 4, 5, 6, 7, 0x88};
  EXPECT_EQ(LeRead<std::uint64_t>(b.data()), 0x8807060504030201ull);
}

TEST(LittleEndianTest, PutWritesOnlyItsBytesInPlace) {
  std::array<std::uint8_t, 6> a{};
  a.fill(0xEE);
  LePut(a, 1, 0xABCDEF, 3);
  EXPECT_EQ(a, (std::array<std::uint8_t, 6>{0xEE, 0xEF, 0xCD, 0xAB, 0xEE, 0xEE}));
  std::string s(4, '\0');
  LePut(s, 0, static_cast<std::uint32_t>(-2), 4);  // a negative value keeps its low bytes
  EXPECT_EQ(s, std::string("\xfe\xff\xff\xff", 4));
}

TEST(LittleEndianTest, AppendGrowsTheContainer) {
  std::vector<std::uint8_t> v{0x01};
  LeAppend(v, 0x0302, 2);
  LeAppend(v, 0x07060504, 4);
  EXPECT_EQ(v, (std::vector<std::uint8_t>{1, 2, 3, 4, 5, 6, 7}));
  std::string s;
  LeAppend(s, 0x1234, 2);
  EXPECT_EQ(s, std::string("\x34\x12", 2));
}

TEST(LittleEndianTest, WhatIsWrittenReadsBack) {
  for (int n = 1; n <= 8; ++n) {
    const std::uint64_t v = 0x0123456789ABCDEFull >> (8 * (8 - n));
    std::string s;
    LeAppend(s, v, n);
    ASSERT_EQ(s.size(), static_cast<std::size_t>(n));
    EXPECT_EQ(LeRead(s, 0, n), v) << n << " bytes";
  }
}

}  // namespace
}  // namespace hil

// The controller's side of the ROSArduinoBridge base protocol against
// vectors/base_serial/session_golden.tsv: it formats the golden's motor commands byte for byte and
// reads every encoder reply.
#include "hil/estimator/guidance/base_serial_client.h"

#include <cstdlib>
#include <numbers>
#include <string>

#include <gtest/gtest.h>

#include "../../firmware_emu/actuator/base_session_golden.h"

namespace hil::estimator::guidance {
namespace {

TEST(BaseSerialClientGolden, FormatsTheGoldenCommandsAndReadsTheReplies) {
  const auto golden = hil::test::ReadBaseSessionGolden();
  ASSERT_GE(golden.size(), 15u);
  int formatted = 0, encoder_replies = 0;
  for (const auto& e : golden) {
    if (e.host.rfind("m ", 0) == 0 && e.host.find('+') == std::string::npos) {
      const long l = std::strtol(e.host.c_str() + 2, nullptr, 10);
      const long r = std::strtol(e.host.c_str() + e.host.rfind(' '), nullptr, 10);
      EXPECT_EQ(FormatMotorSpeeds(l, r).view(), e.host) << "line " << e.line_number;
      ++formatted;
    }
    if (e.host == "e\r") {
      EXPECT_EQ(FormatReadEncoders().view(), e.host);
    }
    BaseReplyReader reader;
    int lines = 0;
    for (char c : e.reply) {
      if (!reader.Feed(c)) continue;
      ++lines;
      std::int32_t left = 0, right = 0;
      const bool is_counts = ParseEncoderReply(reader.line(), left, right);
      EXPECT_EQ(is_counts, e.host.rfind("e", 0) == 0) << "line " << e.line_number;
      if (!is_counts) continue;
      ++encoder_replies;
      const std::string back = std::to_string(left) + " " + std::to_string(right) + "\r\n";
      EXPECT_EQ(back, e.reply) << "line " << e.line_number;
    }
    EXPECT_EQ(lines, e.reply.empty() ? 0 : 1) << "line " << e.line_number;
  }
  EXPECT_GE(formatted, 3);
  EXPECT_GE(encoder_replies, 7);
}

TEST(BaseSerialClient, TicksPerFrameFromWheelSpeed) {
  EXPECT_EQ(TicksPerFrame(2 * std::numbers::pi, 1200, 30.0), 40);  // 1 rev/s
  EXPECT_EQ(TicksPerFrame(-2 * std::numbers::pi, 1200, 30.0), -40);
  std::int32_t l = 0, r = 0;
  EXPECT_FALSE(ParseEncoderReply("OK", l, r));
  EXPECT_FALSE(ParseEncoderReply("12 x", l, r));
  EXPECT_TRUE(ParseEncoderReply("-2147483648 7", l, r));
  EXPECT_EQ(l, -2147483647 - 1);
}

}  // namespace
}  // namespace hil::estimator::guidance

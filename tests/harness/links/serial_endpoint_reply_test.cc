// Issue 40.7: on a device's serial link, an answer to the host (SerialMessage::reply) goes on the
// line after the message being sent and ahead of the queued messages not yet begun; the capture
// shows the bytes in that order, with their moved times.
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/links/capture_format.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

SerialMessage Msg(double t_s, std::string bytes, std::string name, bool reply = false) {
  SerialMessage m{TimeFromSeconds(t_s), 0, std::move(bytes), std::move(name)};
  m.reply = reply;
  return m;
}

TEST(SerialEndpointReplyTest, AnAnswerGoesBetweenTheQueuedMessages) {
  const fs::path dir = fs::temp_directory_path() / ("hil_reply_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string cap = (dir / "ttyR.cap").string();
  {
    SerialEndpoint ep("ttyR", (dir / "ttyR").string(), 9600, 1024, cap);
    ASSERT_TRUE(ep.Queue(Msg(1.0, std::string(96, 'a'), "A")));  // 1.0 to 1.1 s at 9600 Bd
    ASSERT_TRUE(ep.Queue(Msg(1.0, std::string(96, 'b'), "B")));
    ASSERT_TRUE(ep.Queue(Msg(1.0, std::string(96, 'c'), "C")));
    ASSERT_TRUE(ep.Queue(Msg(1.05, "ack", "ACK", true)));  // while A is on the wire
    EXPECT_EQ(ep.last_queued_end(), TimeFromSeconds(1.0) + ep.uart().byte_period() * 291);
    ep.WriteAll();  // nobody has the pty open: captured as drops, in line order
  }
  const Capture c = ReadCapture(cap);
  std::vector<std::string> names;
  std::vector<std::int64_t> t_ns;
  for (const CaptureRecord& r : c.records) {
    names.push_back(r.name);
    t_ns.push_back(r.t_emu_ns);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"A", "ACK", "B", "C"}));
  const std::int64_t byte_ns = 1041667;
  ASSERT_EQ(t_ns.size(), 4u);
  EXPECT_EQ(t_ns[1], 1000000000 + 96 * byte_ns);
  EXPECT_EQ(t_ns[2], 1000000000 + 99 * byte_ns);
  EXPECT_EQ(t_ns[3], 1000000000 + 195 * byte_ns);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

// SocketCanPort on a real vcan0: frames of every kind cross from one socket to another unchanged,
// with kernel timestamps; error frames and receive-queue overflows are counted.
#include <time.h>

#include <thread>

#include <sys/socket.h>

#include "hil/firmware_emu/link/candump_log.h"
#include "hil/firmware_emu/link/socketcan_port.h"

#include "vcan_test_util.h"

namespace hil::link {
namespace {

using test::Iface;
using test::ReceiveFrames;

CanWireFrame Frame(const char* text) {
  auto f = ParseCanFrameText(text);
  EXPECT_TRUE(f.has_value()) << text;
  return f.value_or(CanWireFrame{});
}

std::int64_t RealtimeNs() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

TEST(SocketCanPortVcanTest, TheKernelHasCan) {
  ASSERT_TRUE(SocketCanPort::Available()) << "no AF_CAN: this test must run in the vcan VM";
}

TEST(SocketCanPortVcanTest, ClassicFramesCrossUnchangedWithKernelTimestamps) {
  SocketCanPort tx(Iface());
  SocketCanPort rx(Iface());
  const std::vector<CanWireFrame> sent{Frame("123#DEADBEEF"), Frame("09F80180#8868111FBFA49103"),
                                       Frame("7FF#"),         Frame("0CF02DE2#007D007DD580000A"),
                                       Frame("321#R"),        Frame("12345678#R8")};
  const std::int64_t before = RealtimeNs();
  for (const auto& f : sent) ASSERT_TRUE(tx.Send(f).has_value()) << FormatCanFrameText(f);
  const auto got = ReceiveFrames(rx, sent.size(), std::chrono::seconds(2));
  const std::int64_t after = RealtimeNs();
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) {
    EXPECT_EQ(FormatCanFrameText(got[i].frame), FormatCanFrameText(sent[i]));
    EXPECT_EQ(got[i].frame, sent[i]);
    EXPECT_GE(ToNs(got[i].t_kernel), before);
    EXPECT_LE(ToNs(got[i].t_kernel), after);
    EXPECT_FALSE(got[i].own);
  }
  EXPECT_EQ(tx.stats().frames_sent, sent.size());
  EXPECT_EQ(rx.stats().frames_received, sent.size());
}

TEST(SocketCanPortVcanTest, OwnFramesComeBackOnlyWhenAskedFor) {
  SocketCanPort::Options o;
  o.receive_own_frames = true;
  SocketCanPort me(Iface(), o);
  ASSERT_TRUE(me.Send(Frame("100#01")).has_value());
  const auto echo = ReceiveFrames(me, 1, std::chrono::seconds(1));
  ASSERT_EQ(echo.size(), 1u);
  EXPECT_TRUE(echo[0].own);
  EXPECT_GT(ToNs(echo[0].t_kernel), 0);  // stamped like any frame (candump's time of it)
  EXPECT_EQ(me.stats().own_frames_received, 1u);
  EXPECT_EQ(me.stats().frames_received, 0u);  // echoes are not frames from others
  SocketCanPort quiet(Iface());
  ASSERT_TRUE(quiet.Send(Frame("101#02")).has_value());
  EXPECT_TRUE(ReceiveFrames(quiet, 1, std::chrono::milliseconds(200)).empty());
}

TEST(SocketCanPortVcanTest, FdFramesWhenTheInterfaceAllowsThem) {
  SocketCanPort::Options o;
  o.fd = true;
  SocketCanPort tx(Iface(), o);
  SocketCanPort rx(Iface(), o);
  if (tx.mtu() != 72) {
    // a classic-only interface refuses FD frames (counted) and still carries classic ones
    EXPECT_FALSE(tx.fd_enabled());
    EXPECT_FALSE(tx.Send(Frame("123##1AABB")).has_value());
    EXPECT_EQ(tx.stats().send_failures, 1u);
    ASSERT_TRUE(tx.Send(Frame("123#AABB")).has_value());
    EXPECT_EQ(ReceiveFrames(rx, 1, std::chrono::seconds(1)).size(), 1u);
    return;
  }
  ASSERT_TRUE(tx.fd_enabled());
  std::string text = "1ABCDEF0##1";
  for (int i = 0; i < 64; ++i) text += "A5";
  const std::vector<CanWireFrame> sent{Frame("123##1112233"), Frame(text.c_str()),
                                       Frame("456#0102")};
  for (const auto& f : sent) ASSERT_TRUE(tx.Send(f).has_value());
  const auto got = ReceiveFrames(rx, sent.size(), std::chrono::seconds(2));
  ASSERT_EQ(got.size(), sent.size());
  for (std::size_t i = 0; i < sent.size(); ++i) EXPECT_EQ(got[i].frame, sent[i]) << i;
}

TEST(SocketCanPortVcanTest, ErrorFramesAreCountedByClass) {
  // vcan has no controller; a raw socket may still put error frames on it, which is how a test
  // can see the counting
  SocketCanPort tx(Iface());
  SocketCanPort rx(Iface());
  ASSERT_TRUE(tx.Send(Frame("20000004#0001000000000000")).has_value());  // controller: RX overflow
  ASSERT_TRUE(tx.Send(Frame("20000040#0000000000000000")).has_value());  // bus-off
  ASSERT_TRUE(
      tx.Send(Frame("20000088#0000000000000000")).has_value());  // protocol violation + bus error
  ASSERT_TRUE(tx.Send(Frame("123#00")).has_value());
  int errors = 0;
  for (int i = 0; i < 40 && rx.stats().frames_received < 1; ++i) {
    if (auto r = rx.Receive(std::chrono::milliseconds(50)); r && r->frame.error) ++errors;
  }
  EXPECT_EQ(errors, 3);
  EXPECT_EQ(rx.stats().error_frames, 3u);
  EXPECT_EQ(rx.stats().controller_overflows, 1u);
  EXPECT_EQ(rx.stats().bus_off, 1u);
  EXPECT_EQ(rx.stats().bus_errors, 1u);
  EXPECT_EQ(rx.stats().frames_received, 1u);
}

TEST(SocketCanPortVcanTest, ReceiveQueueOverflowIsCounted) {
  SocketCanPort tx(Iface());
  SocketCanPort rx(Iface());
  const int small = 4096;  // the kernel doubles it and keeps a minimum; still far below 5000 frames
  ASSERT_EQ(setsockopt(rx.fd(), SOL_SOCKET, SO_RCVBUF, &small, sizeof small), 0);
  constexpr int kSent = 5000;
  int accepted = 0;
  for (int i = 0; i < kSent; ++i) {
    CanWireFrame f = Frame("200#0000");
    f.data[0] = static_cast<std::uint8_t>(i >> 8);
    f.data[1] = static_cast<std::uint8_t>(i);
    if (tx.Send(f)) ++accepted;
  }
  ASSERT_GT(accepted, 0);
  std::size_t received = 0;
  while (rx.Receive(std::chrono::milliseconds(100))) ++received;
  // the kernel stamps its drop total on each queued frame: one more frame reports the last drops
  ASSERT_TRUE(tx.Send(Frame("201#")).has_value());
  ++accepted;
  while (rx.Receive(std::chrono::milliseconds(100))) ++received;
  EXPECT_GT(received, 0u);
  EXPECT_LT(received, static_cast<std::size_t>(accepted));
  // every accepted frame was either received or counted as dropped by the receive queue
  EXPECT_EQ(received + rx.stats().rx_queue_drops, static_cast<std::size_t>(accepted));
  std::printf("receive-queue overflow: %d sent, %zu received, %llu counted as dropped\n", accepted,
              received, static_cast<unsigned long long>(rx.stats().rx_queue_drops));
}

TEST(SocketCanPortVcanTest, UnknownInterfaceIsAClearError) {
  try {
    SocketCanPort p("vcan9");
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("vcan9"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace hil::link

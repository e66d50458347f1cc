#include "hil/firmware_emu/link/uart_tx_queue.h"

#include <vector>

#include <gtest/gtest.h>

namespace hil::link {
namespace {

TEST(UartTxQueueTest, BytesLeaveAtTenBitTimesEach) {
  UartTxQueue q(9600, 1024);
  EXPECT_EQ(q.byte_period().count(), 1041667);  // 10 / 9600 s
  const auto a = q.Submit(TimeFromSeconds(1.0), std::string(10, 'a'));
  ASSERT_TRUE(a);
  EXPECT_EQ(a->t_first, TimeFromSeconds(1.0));
  // a second message queued while the first is on the wire follows it back to back
  const auto b = q.Submit(TimeFromSeconds(1.001), "bb");
  ASSERT_TRUE(b);
  EXPECT_EQ(b->t_first, a->t_end());
  EXPECT_EQ(q.bytes_sent(), 12u);
}

TEST(UartTxQueueTest, DropsWholeMessagesWhenTheBufferIsFull) {
  UartTxQueue q(9600, 100);
  ASSERT_TRUE(q.Submit(Time{}, std::string(80, 'x')));
  // 80 bytes still queued at t = 0: 30 more do not fit and are dropped whole
  EXPECT_FALSE(q.Submit(Time{}, std::string(30, 'y')));
  EXPECT_EQ(q.messages_dropped(), 1u);
  EXPECT_EQ(q.bytes_dropped(), 30u);
  // after 60 bytes have drained, the same message fits
  const auto later = q.Submit(Time{} + q.byte_period() * 60, std::string(30, 'y'));
  ASSERT_TRUE(later);
  EXPECT_EQ(later->bytes.size(), 30u);
}

// Issue 40.7: an answer goes after the message on the wire and ahead of those not begun, which
// move behind it; a second answer goes behind the first.
TEST(UartTxQueueTest, RepliesGoAheadOfMessagesNotBegun) {
  UartTxQueue q(9600, 1024);
  const Duration byte = q.byte_period();
  auto a = *q.Submit(TimeFromSeconds(1.0), std::string(10, 'a'));
  auto b = *q.Submit(TimeFromSeconds(1.0), std::string(10, 'b'));
  auto c = *q.Submit(TimeFromSeconds(1.0), std::string(10, 'c'));
  std::vector<TimedChunk*> waiting{&a, &b, &c};
  const Time t_reply = TimeFromSeconds(1.0) + byte * 3;  // a is on the wire
  const auto r1 = q.SubmitAhead(t_reply, "rr", Time{}, waiting);
  ASSERT_TRUE(r1);
  EXPECT_EQ(r1->index, 1u);
  EXPECT_EQ(r1->chunk.t_first, a.t_end());
  EXPECT_EQ(b.t_first, r1->chunk.t_end());
  EXPECT_EQ(c.t_first, b.t_end());
  EXPECT_EQ(q.QueuedBytesAt(TimeFromSeconds(1.0)), 32u);
  auto r1_chunk = r1->chunk;
  std::vector<TimedChunk*> now{&a, &r1_chunk, &b, &c};
  const auto r2 = q.SubmitAhead(t_reply, "ss", Time{}, now);
  ASSERT_TRUE(r2);
  EXPECT_EQ(r2->index, 2u) << "behind the first answer";
  EXPECT_EQ(r2->chunk.t_first, r1_chunk.t_end());
  EXPECT_EQ(c.t_end(), TimeFromSeconds(1.0) + byte * 34);
  // nothing waiting that has not begun: the answer goes last, as Submit puts it
  const auto r3 = q.SubmitAhead(TimeFromSeconds(2.0), "tt", c.t_end(), {});
  ASSERT_TRUE(r3);
  EXPECT_EQ(r3->chunk.t_first, TimeFromSeconds(2.0));
}

TEST(UartTxQueueTest, RejectsNonPositiveBaud) {
  EXPECT_THROW(UartTxQueue(0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace hil::link

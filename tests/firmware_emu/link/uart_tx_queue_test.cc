#include "hil/firmware_emu/link/uart_tx_queue.h"

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

TEST(UartTxQueueTest, RejectsNonPositiveBaud) {
  EXPECT_THROW(UartTxQueue(0, 10), std::invalid_argument);
}

}  // namespace
}  // namespace hil::link

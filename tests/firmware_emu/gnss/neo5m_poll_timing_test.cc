// Issue 40.7: how long the NEO-5M takes to answer a host command sent at various times within its
// epoch, as PX4's u-blox driver sends them (it waits 250 ms for an ACK). The device's output goes
// through its port's transmit queue as SerialEndpoint::Queue puts it there: periodic output with
// UartTxQueue::Submit, answers (SerialMessage::reply) with UartTxQueue::SubmitAhead.

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/firmware_emu/gnss/neo5m_device.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/link/uart_tx_queue.h"

namespace hil::gnss {
namespace {

TruthSample Truth(Time t) {
  TruthSample s;
  s.t = t;
  s.lat_deg = 35.4796096;
  s.lon_deg = 50.5979765;
  s.height_m = 1312.0;
  return s;
}

// One receiver and its UART1 line: every message in line order, with its times.
struct Line {
  Line() : dev(Config(), 3), uart(9600, 1024) {}
  static Neo5mConfig Config() {
    Neo5mConfig c;
    c.start_utc = ParseIsoUtc("2013-06-10T08:00:00Z");
    return c;
  }
  // `replies_ahead` false: every message in the order it is made (the queue before issue 40.7)
  void Queue(const DeviceOutput& out, bool replies_ahead) {
    for (const SerialMessage& m : out.serial) {
      if (m.reply && replies_ahead) {
        std::vector<link::TimedChunk*> waiting;
        for (auto& [name, c] : sent) waiting.push_back(&c);
        auto placed = uart.SubmitAhead(m.t_ready, m.bytes, Time{}, waiting);
        ASSERT_TRUE(placed) << m.name;
        sent.emplace(sent.begin() + static_cast<std::ptrdiff_t>(placed->index), m.name,
                     placed->chunk);
      } else {
        auto c = uart.Submit(m.t_ready, m.bytes);
        ASSERT_TRUE(c) << m.name;
        sent.emplace_back(m.name, *c);
      }
    }
  }
  void RunTo(Time t, bool replies_ahead) {
    while (dev.next_event_time() <= t) {
      DeviceOutput out;
      dev.OnEvent(Truth(dev.next_event_time()), out);
      Queue(out, replies_ahead);
    }
  }
  // Sends `bytes` at `asked`; returns the time the last byte of the answer named `answer` ends.
  Time Ask(Time asked, const std::string& bytes, const std::string& answer, bool replies_ahead) {
    RunTo(asked, replies_ahead);
    DeviceOutput out;
    dev.OnHostBytes(0, asked, bytes, out);
    Queue(out, replies_ahead);
    Time end{};
    for (const auto& [name, c] : sent) {
      if (name == answer && c.t_first >= asked) end = std::max(end, c.t_end());
    }
    return end;
  }
  Neo5mDevice dev;
  link::UartTxQueue uart;
  std::vector<std::pair<std::string, link::TimedChunk>> sent;
};

std::string CfgPrtPoll() {
  ubx::Writer w;
  w.U1(1);
  return ubx::Frame(0x06, 0x00, w);
}

// The answer's last byte, ms after the question, for a question at each offset within the epoch.
std::vector<double> AnswerLatencies_ms(const std::vector<int>& offsets_ms, bool replies_ahead) {
  Line line;
  std::vector<double> ms;
  int second = 2;
  for (const int off : offsets_ms) {
    const Time asked = TimeFromSeconds(second++) + std::chrono::milliseconds(off);
    const Time end = line.Ask(asked, CfgPrtPoll(), "UBX-ACK-ACK", replies_ahead);
    ms.push_back(ToSeconds(end - asked) * 1e3);
  }
  return ms;
}

const std::vector<int> kOffsets_ms = {26, 68, 100, 150, 250, 400, 550, 700, 770, 970};

TEST(Neo5mPollTimingTest, AnswersWithinTensOfMsAtAnyTimeOfTheEpoch) {
  const std::vector<double> fifo = AnswerLatencies_ms(kOffsets_ms, false);
  const std::vector<double> ahead = AnswerLatencies_ms(kOffsets_ms, true);
  for (std::size_t i = 0; i < kOffsets_ms.size(); ++i) {
    std::printf("poll CFG-PRT at x.%03d s: ACK ends %.1f ms later (in made order: %.1f ms)\n",
                kOffsets_ms[i], ahead[i], fifo[i]);
    // the CFG-PRT answer (28 bytes) and its ACK (10): 40 ms at 9600 Bd, after the 10 ms response
    // delay and at most the one message on the wire (a GSV sentence, ≤ 75 ms)
    EXPECT_LT(ahead[i], 130.0) << "asked at x." << kOffsets_ms[i];
  }
  // the defect: in made order a question between an epoch and its output waited for all of it
  EXPECT_GT(fifo[0], 500.0);
}

// An answer never splits a message: the epoch's messages keep their bytes and order, the answer
// sits between two of them, and the epoch moves later by the answer's length only.
TEST(Neo5mPollTimingTest, AnswerGoesBetweenTheEpochsMessages) {
  Line line;
  line.Ask(TimeFromSeconds(3.3), CfgPrtPoll(), "UBX-ACK-ACK", true);
  line.RunTo(TimeFromSeconds(3.99), true);
  for (std::size_t i = 1; i < line.sent.size(); ++i) {
    EXPECT_GE(line.sent[i].second.t_first, line.sent[i - 1].second.t_end())
        << line.sent[i].first << " overlaps " << line.sent[i - 1].first;
  }
  const auto cfg = std::find_if(line.sent.begin(), line.sent.end(),
                                [](const auto& s) { return s.first == "UBX-CFG-PRT"; });
  ASSERT_NE(cfg, line.sent.end());
  ASSERT_NE(cfg, line.sent.begin());
  EXPECT_EQ(std::prev(cfg)->first.rfind("NMEA-", 0), 0u) << "epoch 3's output before it";
  EXPECT_EQ(std::next(cfg)->first, "UBX-ACK-ACK") << "the answer, then its ACK";
  EXPECT_EQ(std::next(cfg, 2)->first.rfind("NMEA-", 0), 0u) << "then the rest of epoch 3";
  EXPECT_LT(cfg->second.t_first, TimeFromSeconds(3.3) + std::chrono::milliseconds(90));
}

}  // namespace
}  // namespace hil::gnss

// Virtual mode's write queue (virtual_gate.h): with hold_tail, a paced host reads each link in
// runs of messages (one write per run), and across links in exactly the order the messages were
// made, as message by message.
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/links/serial_endpoint.h"
#include "hil/harness/run/virtual_gate.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

struct Reader {
  int fd = -1;
  std::vector<std::string> reads;  // each read() the host did, in order
  std::string Drain() {
    std::string all;
    char buf[8192];
    for (pollfd p{fd, POLLIN, 0}; poll(&p, 1, 0) > 0; p.revents = 0) {
      const ssize_t n = read(fd, buf, sizeof buf);
      if (n <= 0) break;
      reads.emplace_back(buf, static_cast<std::size_t>(n));
      all += reads.back();
    }
    return all;
  }
};

void Queue(SerialEndpoint& ep, VirtualWriteQueue& q, double t_s, const std::string& bytes) {
  SerialMessage m;
  m.t_ready = TimeFromSeconds(t_s);
  m.bytes = bytes;
  m.name = "M";
  ASSERT_TRUE(ep.Queue(m));
  q.Add(ep, bytes.size());
}

TEST(VirtualWriteQueueTest, HoldTailHandsARunOfOneLinkOverInOneWriteAndKeepsTheOrderAcrossLinks) {
  const fs::path dir = fs::temp_directory_path() / ("hil_vwq_" + std::to_string(getpid()));
  fs::create_directories(dir);
  SerialEndpoint imu("ttyI", (dir / "ttyI").string(), 115200, 1 << 20, (dir / "ttyI.cap").string());
  SerialEndpoint gps("ttyG", (dir / "ttyG").string(), 115200, 1 << 20, (dir / "ttyG.cap").string());
  Reader ri{open((dir / "ttyI").c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY), {}};
  Reader rg{open((dir / "ttyG").c_str(), O_RDONLY | O_NONBLOCK | O_NOCTTY), {}};
  ASSERT_GE(ri.fd, 0);
  ASSERT_GE(rg.fd, 0);
  VirtualGate gate({&imu, &gps}, 4096, [](std::size_t, bool) { return true; });
  VirtualWriteQueue q(&gate, 8192);

  // ten IMU frames: the run of one link stays queued while it may still grow
  for (int k = 0; k < 10; ++k) {
    Queue(imu, q, 0.01 * k, "I" + std::to_string(k) + ";");
    ASSERT_TRUE(q.Pump(false, true));
  }
  EXPECT_EQ(q.deferred_bytes(), 30u);
  EXPECT_EQ(imu.PendingToHost(), 0u);
  // a GNSS epoch follows: the IMU run is complete and goes in one write, the epoch waits
  Queue(gps, q, 0.095, "$G1*00\r\n");
  ASSERT_TRUE(q.Pump(false, true));
  EXPECT_EQ(imu.PendingToHost(), 30u);
  EXPECT_EQ(q.deferred_bytes(), 8u);
  // the next IMU frame: the epoch may go only once the host has read the IMU run
  Queue(imu, q, 0.1, "I10;");
  ASSERT_TRUE(q.Pump(false, true));
  EXPECT_EQ(gps.PendingToHost(), 0u) << "the host has not read the IMU run yet";
  EXPECT_EQ(ri.Drain(), "I0;I1;I2;I3;I4;I5;I6;I7;I8;I9;");
  ASSERT_TRUE(q.Pump(false, true));
  EXPECT_EQ(gps.PendingToHost(), 8u);
  EXPECT_EQ(imu.PendingToHost(), 0u) << "the IMU frame after the epoch waits for the epoch's read";
  EXPECT_EQ(rg.Drain(), "$G1*00\r\n");
  ASSERT_TRUE(q.Pump(true));  // a host turn: everything goes
  EXPECT_EQ(q.deferred_bytes(), 0u);
  EXPECT_EQ(ri.Drain(), "I10;");
  EXPECT_EQ(ri.reads.size(), 2u) << "one read per run of the link";

  // without hold_tail (beside a CAN bus) every message goes at once
  Queue(imu, q, 0.11, "I11;");
  ASSERT_TRUE(q.Pump(false, false));
  EXPECT_EQ(q.deferred_bytes(), 0u);
  EXPECT_EQ(ri.Drain(), "I11;");
  // a run that reaches kBatchBytes goes without waiting for another link
  const std::string big(VirtualWriteQueue::kBatchBytes, 'x');
  Queue(imu, q, 0.12, big);
  ASSERT_TRUE(q.Pump(false, true));
  EXPECT_EQ(q.deferred_bytes(), 0u);
  EXPECT_EQ(ri.Drain().size(), big.size());
  close(ri.fd);
  close(rg.fd);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

// Virtual mode, a link nobody paces (no estimator reads it, or no estimator at all): a pty holds
// 12-20 kB, and what does not fit is dropped after the 1 s stall (PtyPort::Write). The capture
// says so (issue 40.6): before, every byte was captured as `tx` whether it reached the pty or not,
// so a clean capture hid a loss.
#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hil/harness/links/capture_format.h"
#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

TEST(SerialEndpointFullPtyTest, TheCaptureRecordsWhatAFullPtyDroppedAsDrops) {
  const fs::path dir = fs::temp_directory_path() / ("hil_fullpty_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string link = (dir / "ttyF").string(), cap = (dir / "ttyF.cap").string();
  std::string sent, read_back;
  {
    SerialEndpoint ep("ttyF", link, 115200, 1 << 20, cap);
    for (int k = 0; k < 40; ++k) {  // 40 messages of 1000 bytes: twice what a pty holds
      SerialMessage m;
      m.t_ready = TimeFromSeconds(0.1 * k);
      m.bytes = std::string(1000, static_cast<char>('A' + k % 26));
      m.name = "M";
      ASSERT_TRUE(ep.Queue(m));
      sent += m.bytes;
    }
    // a host has it open and does not read (a port nobody has open would drop every byte)
    const int idle = open(link.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(idle, 0);
    EXPECT_TRUE(ep.WriteChunks(40));  // nobody reads: the rest is dropped after the stall
    EXPECT_GT(ep.bytes_dropped_unread(), 0u);
    EXPECT_LT(ep.bytes_dropped_unread(), sent.size());
    EXPECT_EQ(ep.bytes_sent() + ep.bytes_dropped_unread(), sent.size());
    EXPECT_EQ(ep.queued_bytes(), 0u);
    // what the pty holds, read by a host that opens it now
    const int fd = open(link.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    char buf[4096];
    for (pollfd p{fd, POLLIN, 0}; poll(&p, 1, 200) > 0; p.revents = 0) {
      const ssize_t n = read(fd, buf, sizeof buf);
      if (n <= 0) break;
      read_back.append(buf, static_cast<std::size_t>(n));
    }
    close(fd);
    close(idle);
  }
  std::string tx, drop, both;
  for (const CaptureRecord& r : ReadCapture(cap).records) {
    (r.dir == CaptureDir::kTx ? tx : drop) += r.bytes;
    both += r.bytes;
    EXPECT_TRUE(r.dir == CaptureDir::kTx || r.dir == CaptureDir::kDrop);
  }
  EXPECT_EQ(tx.size(), read_back.size());
  EXPECT_TRUE(tx == read_back) << "tx is exactly what reached the host";
  EXPECT_FALSE(drop.empty());
  EXPECT_TRUE(both == sent) << "tx then drop: every byte, in order";
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

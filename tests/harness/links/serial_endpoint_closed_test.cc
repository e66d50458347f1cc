// Issue 40 (minor): when the reader of a link goes away mid-run (it closed the pty, the run
// stopped early), the bytes never written to it (the rest of the epoch, a pending ACK) are in
// the capture as `drop` records, as the capture format promises (capture_format.h), not as `tx`.
#include <fcntl.h>
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

TEST(SerialEndpointClosedTest, BytesNeverWrittenAreCapturedAsDrops) {
  const fs::path dir = fs::temp_directory_path() / ("hil_closed_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string link = (dir / "ttyC").string(), cap = (dir / "ttyC.cap").string();
  {
    SerialEndpoint ep("ttyC", link, 9600, 1024, cap);
    const int fd = open(link.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    ASSERT_GE(fd, 0);
    ASSERT_TRUE(ep.Queue({TimeFromSeconds(1.1), 0, "$GPRMC,1*00\r\n", "NMEA-RMC"}));
    ASSERT_TRUE(ep.Queue({TimeFromSeconds(1.1), 0, "$GPGGA,1*00\r\n", "NMEA-GGA"}));
    SerialMessage ack{TimeFromSeconds(1.105), 0, std::string(10, '\xb5'), "UBX-ACK-ACK"};
    ack.reply = true;
    ASSERT_TRUE(ep.Queue(ack));
    // the host reads the first message and closes; the run gives up waiting for it
    ASSERT_TRUE(
        ep.WriteChunks(1, [](const std::function<std::size_t()>& more) { return more() == 0; }));
    char buf[64];
    EXPECT_EQ(read(fd, buf, sizeof buf), 13);
    close(fd);
    EXPECT_FALSE(ep.WriteChunks(2, [](const std::function<std::size_t()>&) { return false; }));
  }  // the run ends with two messages never written
  const Capture c = ReadCapture(cap);
  std::vector<std::string> got;
  for (const CaptureRecord& r : c.records) {
    const char* kind =
        r.dir == CaptureDir::kTx ? "tx " : (r.dir == CaptureDir::kDrop ? "drop " : "? ");
    got.push_back(std::string(kind) + r.name);
  }
  EXPECT_EQ(got, (std::vector<std::string>{"tx NMEA-RMC", "drop UBX-ACK-ACK", "drop NMEA-GGA"}));
  for (const CaptureRecord& r : c.records) {
    if (r.dir == CaptureDir::kDrop) {
      EXPECT_EQ(r.t_wall, WallTime{}) << r.name;
    }
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

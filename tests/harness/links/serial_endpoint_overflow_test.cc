// A message the UART's transmit buffer has no room for is captured as a `drop` record after the
// chunks queued before it, whenever the host reads those: its place in the capture no longer
// follows the host's pace. Before, the drop was written when the message was refused, ahead of
// the `tx` records of the chunks still waiting for the host, so two runs of faults/gnss_overload
// gave the same records in different orders.
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

SerialMessage Message(double t_s, char fill, const char* name) {
  SerialMessage m;
  m.t_ready = TimeFromSeconds(t_s);
  m.bytes = std::string(400, fill);
  m.name = name;
  return m;
}

// The capture's records as "dir:name", in file order.
std::vector<std::string> RecordOrder(const std::string& cap) {
  std::vector<std::string> out;
  for (const CaptureRecord& r : ReadCapture(cap).records)
    out.push_back(std::string(r.dir == CaptureDir::kTx ? "tx" : "drop") + ":" + r.name);
  return out;
}

// Queues A, B (refused: the 600-byte buffer still holds A), C after A has left the UART; the
// host reads `read_first` chunks before the endpoint closes (the rest are captured as drops).
std::vector<std::string> RunWithHostReading(std::size_t read_first, const fs::path& dir) {
  fs::create_directories(dir);
  const std::string link = (dir / "ttyO").string(), cap = (dir / "ttyO.cap").string();
  {
    SerialEndpoint ep("ttyO", link, 9600, 600, cap);
    const int host = open(link.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    EXPECT_GE(host, 0);
    EXPECT_TRUE(ep.Queue(Message(0.0, 'a', "A")));
    EXPECT_FALSE(ep.Queue(Message(0.0, 'b', "B")));  // no room: A is still in the buffer
    EXPECT_TRUE(ep.Queue(Message(1.0, 'c', "C")));   // A has left the UART by 0.42 s
    if (read_first > 0) {
      EXPECT_TRUE(ep.WriteChunks(read_first));
    }
    close(host);
  }
  return RecordOrder(cap);
}

TEST(SerialEndpointOverflowTest, ARefusedMessageIsCapturedAfterTheChunksQueuedBeforeIt) {
  const fs::path dir = fs::temp_directory_path() / ("hil_overflow_" + std::to_string(getpid()));
  const std::vector<std::string> read_one = RunWithHostReading(1, dir / "one");
  const std::vector<std::string> read_none = RunWithHostReading(0, dir / "none");
  const std::vector<std::string> read_all = RunWithHostReading(2, dir / "all");
  EXPECT_EQ(read_one, (std::vector<std::string>{"tx:A", "drop:B", "drop:C"}));
  EXPECT_EQ(read_none, (std::vector<std::string>{"drop:A", "drop:B", "drop:C"}));
  EXPECT_EQ(read_all, (std::vector<std::string>{"tx:A", "drop:B", "tx:C"}));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

// A real-time serial link's memory does not grow with the bytes it writes (issue 40, minor: hil's
// memory per emulated hour): each byte's schedule error goes into a QuantileSketch, not a vector
// of every byte's error (8 bytes a byte: 330 MB in an hour of a 115 200 Bd link). A run writing
// four times the bytes must not hold more heap at its end than the shorter one.
#include <fcntl.h>
#include <malloc.h>
#include <poll.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "hil/harness/links/serial_endpoint.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

constexpr int kBaud = 115200;
// emulated time runs this much faster than the wall (the test takes about 4 s, on no clock of its
// own: only bytes and heap are compared)
constexpr double kSpeed = 50.0;
// 900 bytes every 80 ms: 11 250 B/s on the line's 11 520 B/s
constexpr std::size_t kMessageBytes = 900;
constexpr double kMessagePeriodS = 0.08;

std::size_t HeapBytes() {
  const struct mallinfo2 m = mallinfo2();
  return m.uordblks + m.hblkhd;  // small blocks in use and mmapped blocks
}

struct RunFigures {
  std::uint64_t bytes_sent = 0;
  std::size_t heap_growth = 0;  // at the run's end, before the endpoint goes
};

// Writes `messages` messages through a real-time endpoint whose pty a thread drains.
RunFigures WriteMessages(const fs::path& dir, int messages) {
  const std::string link = (dir / "ttyM").string(), cap = (dir / "ttyM.cap").string();
  RunFigures out;
  const std::size_t heap_before = HeapBytes();
  SerialEndpoint ep("ttyM", link, kBaud, 1 << 20, cap);
  std::atomic<bool> stop{false};
  std::thread reader([&] {
    const int fd = open(link.c_str(), O_RDONLY | O_NOCTTY | O_NONBLOCK);
    char buf[4096];
    for (pollfd p{fd, POLLIN, 0}; !stop; p.revents = 0) {
      if (poll(&p, 1, 10) > 0 && read(fd, buf, sizeof buf) <= 0) continue;
    }
    close(fd);
  });
  while (!ep.HostAttached()) std::this_thread::yield();  // the reader has the pty open
  const link::RealtimePacer pacer(kSpeed);
  int queued = 0;
  for (;;) {
    if (queued < messages && ep.queued_bytes() < 4 * kMessageBytes) {
      SerialMessage m;
      m.t_ready = TimeFromSeconds(kMessagePeriodS * queued);
      m.bytes = std::string(kMessageBytes, static_cast<char>('a' + queued % 26));
      m.name = "MSG";
      EXPECT_TRUE(ep.Queue(m));
      ++queued;
      continue;
    }
    if (!ep.next_byte_time()) break;
    ep.WriteNextByte(pacer);
  }
  out.bytes_sent = ep.bytes_sent();
  const std::size_t heap_after = HeapBytes();
  out.heap_growth = heap_after > heap_before ? heap_after - heap_before : 0;
  stop = true;
  reader.join();
  return out;
}

TEST(SerialEndpointMemoryTest, FourTimesTheBytesHoldNoMoreMemory) {
  const fs::path dir = fs::temp_directory_path() / ("hil_ep_memory_" + std::to_string(getpid()));
  fs::create_directories(dir);
  constexpr int kMessages = 450;  // 405 000 bytes: past the sketch's 2^18 exact values
  const RunFigures one = WriteMessages(dir, kMessages);
  const RunFigures four = WriteMessages(dir, 4 * kMessages);
  std::printf(
      "HIL-FIGURE serial_endpoint_memory bytes=%llu heap_growth=%zu B, bytes=%llu "
      "heap_growth=%zu B\n",
      static_cast<unsigned long long>(one.bytes_sent), one.heap_growth,
      static_cast<unsigned long long>(four.bytes_sent), four.heap_growth);
  // the reader kept up: most bytes left (a loaded machine may drop a few at a full pty)
  ASSERT_GT(one.bytes_sent, std::uint64_t{1} << 18);
  ASSERT_GT(four.bytes_sent, 3 * one.bytes_sent);
  // a per-byte record would hold 8 B for each of the ≥ 800 000 more bytes (6.4 MB); our bound:
  // 1 MiB more at most (capture and pty buffers vary a little from run to run)
  EXPECT_LT(four.heap_growth, one.heap_growth + (std::size_t{1} << 20));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

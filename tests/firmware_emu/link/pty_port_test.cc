#include "hil/firmware_emu/link/pty_port.h"

#include <fcntl.h>
#include <poll.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "joined_text.h"

namespace hil::link {
namespace {

using hil::test::Joined;

std::string ReadSome(int fd, std::size_t want) {
  std::string out;
  char buf[256];
  while (out.size() < want) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, 1000) <= 0) break;
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) break;
    out.append(buf, static_cast<std::size_t>(n));
  }
  return out;
}

TEST(PtyPortTest, BytesCrossBothWaysThroughTheSymlink) {
  const std::string link =
      std::filesystem::temp_directory_path() / ("hil_pty_test_" + std::to_string(getpid()));
  PtyPort port(link, 9600);
  ASSERT_TRUE(std::filesystem::is_symlink(link));
  const int host = open(link.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(host, 0);
  // raw mode: CR/LF and binary bytes arrive untouched, nothing is echoed back
  const std::string msg = Joined("$GPGGA,1*00\r\n", std::string_view("\xB5\x62\x00\xFF", 4));
  ASSERT_EQ(port.Write(msg), static_cast<long>(msg.size()));
  EXPECT_EQ(ReadSome(host, msg.size()), msg);
  EXPECT_EQ(port.ReadAvailable(), "");
  ASSERT_EQ(write(host, "\xB5\x62\x0A\x04", 4), 4);
  usleep(20000);
  EXPECT_EQ(port.ReadAvailable(), std::string("\xB5\x62\x0A\x04", 4));
  close(host);
  // the host closing and reopening the port is survived
  const int again = open(link.c_str(), O_RDWR | O_NOCTTY);
  ASSERT_GE(again, 0);
  ASSERT_EQ(port.Write("abc"), 3);
  EXPECT_EQ(ReadSome(again, 3), "abc");
  close(again);
}

TEST(PtyPortTest, BadLinkPathIsAClearError) {
  try {
    PtyPort port("/nonexistent-dir/ttyGPS", 9600);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent-dir/ttyGPS"), std::string::npos);
  }
}

}  // namespace
}  // namespace hil::link

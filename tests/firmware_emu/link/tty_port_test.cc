#include "hil/firmware_emu/link/tty_port.h"

#include <fcntl.h>
#include <poll.h>
#include <stdlib.h>
#include <termios.h>
#include <unistd.h>

#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/pty_port.h"

namespace hil::link {
namespace {

// A pty's slave /dev/pts/N is a real tty device: it stands in for /dev/ttyUSB0 here, with the
// master playing the far end of the cable.
struct Cable {
  int far = -1;
  std::string device;
  Cable() {
    far = posix_openpt(O_RDWR | O_NOCTTY);
    grantpt(far);
    unlockpt(far);
    device = ptsname(far);
  }
  ~Cable() { close(far); }
};

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

TEST(TtyPortTest, DrivesAnExistingDeviceRaw8N1BothWays) {
  Cable cable;
  ASSERT_TRUE(IsDevicePath(cable.device));
  TtyPort port(cable.device, 115200);
  termios tio{};
  ASSERT_EQ(tcgetattr(port.fd(), &tio), 0);
  EXPECT_EQ(cfgetospeed(&tio), static_cast<speed_t>(B115200));
  EXPECT_EQ(tio.c_cflag & CSIZE, static_cast<tcflag_t>(CS8));
  EXPECT_EQ(tio.c_cflag & (PARENB | CSTOPB), 0u);
  EXPECT_EQ(tio.c_lflag & (ICANON | ECHO), 0u);
  const std::string msg("$GPRMC,x*00\r\n\xB5\x62\x00\xFF", 17);
  ASSERT_EQ(port.Write(msg), static_cast<long>(msg.size()));
  EXPECT_EQ(ReadSome(cable.far, msg.size()), msg);
  ASSERT_EQ(write(cable.far, "\xB5\x62\x06\x00", 4), 4);
  std::string got;
  for (int i = 0; i < 100 && got.size() < 4; ++i) {
    got += port.ReadAvailable();
    usleep(2000);
  }
  EXPECT_EQ(got, std::string("\xB5\x62\x06\x00", 4));
  EXPECT_EQ(port.path(), cable.device);
}

TEST(TtyPortTest, OpenSerialLinkPicksPtyOrDevice) {
  Cable cable;
  const std::string dir = std::filesystem::temp_directory_path();
  auto dev = OpenSerialLink(dir, cable.device, 9600);
  EXPECT_EQ(dev->path(), cable.device);
  const std::string name = "hil_tty_test_" + std::to_string(getpid());
  auto pty = OpenSerialLink(dir, name, 9600);
  EXPECT_EQ(pty->path(), dir + "/" + name);
  EXPECT_TRUE(std::filesystem::is_symlink(dir + "/" + name));
}

TEST(TtyPortTest, MissingDeviceIsAClearError) {
  try {
    TtyPort port("/dev/ttyHIL-does-not-exist", 9600);
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/dev/ttyHIL-does-not-exist"), std::string::npos);
  }
}

}  // namespace
}  // namespace hil::link

#include "isobus_link.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

namespace hil::guidanced {
namespace g = estimator::guidance;

namespace {

constexpr int kIsobusBitrate = 250000;  // ISO 11783-2

int OpenCan(const std::string& iface) {
  const int fd = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd < 0) return -1;
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, iface.c_str(), IFNAMSIZ - 1);
  sockaddr_can addr{};
  if (ioctl(fd, SIOCGIFINDEX, &ifr) < 0) {
    const int e = errno;
    close(fd);
    errno = e;
    return -1;
  }
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  if (bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0) {
    const int e = errno;
    close(fd);
    errno = e;
    return -1;
  }
  return fd;
}

int OpenTty(const std::string& tty) {
  const int fd = open(tty.c_str(), O_RDWR | O_NOCTTY | O_CLOEXEC);
  if (fd < 0) return -1;
  termios t{};
  if (tcgetattr(fd, &t) == 0) {
    cfmakeraw(&t);
    cfsetispeed(&t, B115200);
    cfsetospeed(&t, B115200);
    tcsetattr(fd, TCSANOW, &t);
  }
  return fd;
}

}  // namespace

bool IsobusLink::WriteAll(const char* p, std::size_t n) {
  while (n > 0) {
    const ssize_t w = write(fd_, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

bool IsobusLink::Open(const std::string& where, bool slcan, std::uint8_t ecu_address) {
  slcan_ = slcan;
  ecu_ = ecu_address;
  fd_ = slcan ? OpenTty(where) : OpenCan(where);
  if (fd_ < 0 || !slcan) return fd_ >= 0;
  // the adapter's start-up, as slcand does it: close, bit rate, open
  g::SlcanRecord rate;
  g::FormatSlcanBitrate(kIsobusBitrate, rate);
  const g::SlcanRecord close_rec = g::FormatSlcanClose(), open_rec = g::FormatSlcanOpen();
  return WriteAll(close_rec.bytes.data(), close_rec.size) &&
         WriteAll(rate.bytes.data(), rate.size) && WriteAll(open_rec.bytes.data(), open_rec.size);
}

bool IsobusLink::Send(const g::IsobusFrame& frame) {
  if (slcan_) {
    const g::SlcanRecord r = g::FormatSlcanExtendedFrame(frame);
    return WriteAll(r.bytes.data(), r.size);
  }
  can_frame f{};
  f.can_id = (frame.id & CAN_EFF_MASK) | CAN_EFF_FLAG;
  f.can_dlc = frame.len;
  std::memcpy(f.data, frame.data.data(), frame.len);
  return write(fd_, &f, sizeof f) == static_cast<ssize_t>(sizeof f);
}

void IsobusLink::OnFrame(const g::IsobusFrame& frame) {
  if ((frame.id & 0xFF) != ecu_) return;
  g::MachineInfo m;
  if (g::DecodeMachineInfo(frame, m) != g::IsobusDecodeResult::kOk) return;
  ++machine_infos_;
  reset_requested_ = m.request_reset == 1;
}

bool IsobusLink::OnReadable() {
  if (!slcan_) {
    can_frame f{};
    const ssize_t n = read(fd_, &f, sizeof f);
    if (n < 0) return errno == EINTR || errno == EAGAIN;
    if (n != static_cast<ssize_t>(sizeof f)) return n != 0;
    if (!(f.can_id & CAN_EFF_FLAG) || (f.can_id & (CAN_RTR_FLAG | CAN_ERR_FLAG))) return true;
    g::IsobusFrame i;
    i.id = f.can_id & CAN_EFF_MASK;
    i.len = f.can_dlc > 8 ? 8 : f.can_dlc;
    std::memcpy(i.data.data(), f.data, i.len);
    OnFrame(i);
    return true;
  }
  std::array<char, 512> buf{};
  const ssize_t n = read(fd_, buf.data(), buf.size());
  if (n < 0) return errno == EINTR || errno == EAGAIN;
  if (n == 0) return false;
  for (ssize_t i = 0; i < n; ++i) {
    const g::SlcanReply r = reader_.Feed(buf[static_cast<std::size_t>(i)]);
    if (r == g::SlcanReply::kFrame) OnFrame(reader_.frame());
    if (r == g::SlcanReply::kRefused) ++refusals_;
  }
  return true;
}

}  // namespace hil::guidanced

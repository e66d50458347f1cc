#include "hil/firmware_emu/link/socketcan_port.h"

#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#include "hil/firmware_emu/link/sys_error.h"
#include "hil/firmware_emu/wall_time.h"

#ifndef SO_RXQ_OVFL
#define SO_RXQ_OVFL 40
#endif

namespace hil::link {
namespace {

// The kernel's frame layout is the API here; the payload is copied byte by byte.
canfd_frame ToKernel(const CanWireFrame& f) {
  canfd_frame k{};
  k.can_id = f.id & (f.extended || f.error ? CAN_EFF_MASK : CAN_SFF_MASK);
  if (f.extended) k.can_id |= CAN_EFF_FLAG;
  if (f.rtr) k.can_id |= CAN_RTR_FLAG;
  if (f.error) k.can_id = (f.id & CAN_ERR_MASK) | CAN_ERR_FLAG;
  k.len = std::min<std::uint8_t>(f.len, f.fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN);
  if (f.fd) k.flags = f.fd_flags & (CANFD_BRS | CANFD_ESI);
  if (!f.rtr) std::copy_n(f.data.begin(), k.len, k.data);
  return k;
}

CanWireFrame FromKernel(const canfd_frame& k, bool fd) {
  CanWireFrame f;
  f.error = (k.can_id & CAN_ERR_FLAG) != 0;
  f.extended = (k.can_id & CAN_EFF_FLAG) != 0 || f.error;
  f.rtr = (k.can_id & CAN_RTR_FLAG) != 0;
  f.id = f.error      ? (k.can_id & CAN_ERR_MASK)
         : f.extended ? (k.can_id & CAN_EFF_MASK)
                      : (k.can_id & CAN_SFF_MASK);
  f.fd = fd;
  if (fd) f.fd_flags = k.flags & (CANFD_BRS | CANFD_ESI);
  f.len = std::min<std::uint8_t>(k.len, fd ? CANFD_MAX_DLEN : CAN_MAX_DLEN);
  if (!f.rtr) std::copy_n(k.data, f.len, f.data.begin());
  return f;
}

}  // namespace

bool SocketCanPort::Available() {
  const int s = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (s < 0) return false;
  close(s);
  return true;
}

SocketCanPort::SocketCanPort(const std::string& ifname, const Options& options) : ifname_(ifname) {
  if (ifname.empty() || ifname.size() >= IFNAMSIZ)
    throw std::runtime_error("bad CAN interface name '" + ifname + "'");
  fd_ = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC, CAN_RAW);
  if (fd_ < 0) throw SysError("cannot open a CAN socket for " + ifname);
  const auto fail = [&](const std::string& what) {
    const auto e = SysError(what + " on " + ifname);
    close(fd_);
    fd_ = -1;
    return e;
  };
  ifreq ifr{};
  std::memcpy(ifr.ifr_name, ifname.c_str(), ifname.size() + 1);
  if (ioctl(fd_, SIOCGIFINDEX, &ifr) < 0) throw fail("no CAN interface");
  const int ifindex = ifr.ifr_ifindex;
  if (ioctl(fd_, SIOCGIFMTU, &ifr) < 0) throw fail("cannot read the MTU");
  mtu_ = ifr.ifr_mtu;

  const int on = 1, off = 0;
  if (options.fd && mtu_ == static_cast<int>(CANFD_MTU)) {
    fd_enabled_ = setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_FD_FRAMES, &on, sizeof on) == 0;
  }
  if (options.receive_own_frames)
    setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_RECV_OWN_MSGS, &on, sizeof on);
  if (!options.loopback) setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_LOOPBACK, &off, sizeof off);
  if (options.error_frames) {
    const can_err_mask_t mask = CAN_ERR_MASK;
    setsockopt(fd_, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &mask, sizeof mask);
  }
  if (options.receive_buffer_bytes > 0 &&
      setsockopt(fd_, SOL_SOCKET, SO_RCVBUFFORCE, &options.receive_buffer_bytes,
                 sizeof options.receive_buffer_bytes) < 0) {
    setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &options.receive_buffer_bytes,
               sizeof options.receive_buffer_bytes);
  }
  setsockopt(fd_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
  setsockopt(fd_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on);

  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifindex;
  if (bind(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0)
    throw fail("cannot bind a CAN socket");
}

SocketCanPort::~SocketCanPort() {
  if (fd_ >= 0) close(fd_);
}

std::optional<WallTime> SocketCanPort::Send(const CanWireFrame& frame) {
  if (frame.fd && !fd_enabled_) {
    ++stats_.send_failures;
    return std::nullopt;
  }
  const canfd_frame k = ToKernel(frame);
  const std::size_t size = frame.fd ? CANFD_MTU : CAN_MTU;
  const WallTime give_up = WallNow() + std::chrono::milliseconds(10);
  for (;;) {
    const ssize_t n = write(fd_, &k, size);
    if (n == static_cast<ssize_t>(size)) {
      ++stats_.frames_sent;
      return WallNow();
    }
    if (n < 0 && (errno == ENOBUFS || errno == EAGAIN) && WallNow() < give_up) {
      pollfd p{fd_, POLLOUT, 0};
      poll(&p, 1, 1);
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == ENOBUFS || errno == EAGAIN))
      ++stats_.send_queue_full;
    else
      ++stats_.send_failures;
    return std::nullopt;
  }
}

std::optional<ReceivedCanFrame> SocketCanPort::Receive(Duration timeout) {
  pollfd p{fd_, POLLIN, 0};
  const int wait_ms = static_cast<int>((timeout.count() + 999999) / 1000000);
  if (poll(&p, 1, wait_ms) <= 0 || !(p.revents & POLLIN)) return std::nullopt;

  canfd_frame k{};
  iovec iov{&k, sizeof k};
  alignas(
      cmsghdr) char control[CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t)) + 64];
  msghdr msg{};
  msg.msg_iov = &iov;
  msg.msg_iovlen = 1;
  msg.msg_control = control;
  msg.msg_controllen = sizeof control;
  const ssize_t n = recvmsg(fd_, &msg, MSG_DONTWAIT);
  if (n != static_cast<ssize_t>(CAN_MTU) && n != static_cast<ssize_t>(CANFD_MTU))
    return std::nullopt;

  ReceivedCanFrame r;
  r.t_read_mono = WallNow();
  r.frame = FromKernel(k, n == static_cast<ssize_t>(CANFD_MTU));
  r.own = (msg.msg_flags & MSG_CONFIRM) != 0;
  for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
    if (c->cmsg_level != SOL_SOCKET) continue;
    if (c->cmsg_type == SO_TIMESTAMPNS) {
      timespec ts{};
      std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
      r.t_kernel = UnixTimeFromNs(static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec);
    } else if (c->cmsg_type == SO_RXQ_OVFL) {
      std::uint32_t drops = 0;
      std::memcpy(&drops, CMSG_DATA(c), sizeof drops);
      // the kernel reports its running total for this socket
      if (drops > last_drop_count_) stats_.rx_queue_drops += drops - last_drop_count_;
      last_drop_count_ = drops;
    }
  }
  if (r.frame.error)
    CountErrorFrame(r.frame);
  else if (r.own)
    ++stats_.own_frames_received;
  else
    ++stats_.frames_received;
  return r;
}

void SocketCanPort::CountErrorFrame(const CanWireFrame& f) {
  ++stats_.error_frames;
  if (f.id & CAN_ERR_BUSOFF) ++stats_.bus_off;
  if (f.id & (CAN_ERR_PROT | CAN_ERR_BUSERROR | CAN_ERR_ACK | CAN_ERR_TRX)) ++stats_.bus_errors;
  if ((f.id & CAN_ERR_CRTL) && f.len > 1 &&
      (f.data[1] & (CAN_ERR_CRTL_RX_OVERFLOW | CAN_ERR_CRTL_TX_OVERFLOW))) {
    ++stats_.controller_overflows;
  }
}

}  // namespace hil::link

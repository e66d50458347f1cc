#include "can_imu_input.h"

#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include <linux/can.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

#ifndef SO_RXQ_OVFL
#define SO_RXQ_OVFL 40
#endif

namespace hil::navd {
namespace {

namespace drv = estimator::drivers;

constexpr int kReceiveBufferBytes = 4 << 20;  // room for seconds of frames if navd is held up

std::int64_t RealtimeNs() {
  timespec ts{};
  clock_gettime(CLOCK_REALTIME, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
}

}  // namespace

CanImuInput::CanImuInput(const std::string& interface, const drv::J1939ImuDecoderConfig& config)
    : iface_(interface), decoder_(config) {
  sock_ = socket(PF_CAN, SOCK_RAW | SOCK_CLOEXEC | SOCK_NONBLOCK, CAN_RAW);
  if (sock_ < 0) {
    throw std::runtime_error("[imu] cannot open a CAN socket for " + interface + ": " +
                             std::strerror(errno) +
                             (errno == EAFNOSUPPORT ? " (this kernel has no SocketCAN)" : ""));
  }
  const auto fail = [&](const std::string& what) {
    const std::string err = std::strerror(errno);
    close(sock_);
    sock_ = -1;
    return std::runtime_error("[imu] " + what + " " + interface + ": " + err);
  };
  ifreq ifr{};
  std::strncpy(ifr.ifr_name, interface.c_str(), IFNAMSIZ - 1);
  if (ioctl(sock_, SIOCGIFINDEX, &ifr) < 0) throw fail("no CAN interface");
  // only the IMU's PGNs (identifier bits 8–25), extended frames
  const std::uint32_t pgns[] = {drv::kPgnAri, drv::kPgnAccs, drv::kPgnSsi2, drv::kPgnHilTimePulse};
  can_filter filters[4];
  for (int i = 0; i < 4; ++i) {
    filters[i].can_id = (pgns[i] << 8) | CAN_EFF_FLAG;
    filters[i].can_mask = (0x3FFFFu << 8) | CAN_EFF_FLAG | CAN_RTR_FLAG;
  }
  if (setsockopt(sock_, SOL_CAN_RAW, CAN_RAW_FILTER, filters, sizeof filters) < 0)
    throw fail("cannot filter CAN on");
  const int on = 1;
  setsockopt(sock_, SOL_SOCKET, SO_TIMESTAMPNS, &on, sizeof on);
  setsockopt(sock_, SOL_SOCKET, SO_RXQ_OVFL, &on, sizeof on);
  // a larger receive queue: the privileged call may exceed rmem_max, the plain one is capped by it
  if (setsockopt(sock_, SOL_SOCKET, SO_RCVBUFFORCE, &kReceiveBufferBytes,
                 sizeof kReceiveBufferBytes) < 0)
    setsockopt(sock_, SOL_SOCKET, SO_RCVBUF, &kReceiveBufferBytes, sizeof kReceiveBufferBytes);
  sockaddr_can addr{};
  addr.can_family = AF_CAN;
  addr.can_ifindex = ifr.ifr_ifindex;
  if (bind(sock_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0)
    throw fail("cannot bind CAN interface");
}

CanImuInput::~CanImuInput() {
  if (sock_ >= 0) close(sock_);
}

void CanImuInput::ReadAll(const std::function<void(const estimator::ImuSample&)>& on_sample) {
  for (;;) {
    can_frame k{};
    iovec iov{&k, sizeof k};
    alignas(cmsghdr) char
        control[CMSG_SPACE(sizeof(timespec)) + CMSG_SPACE(sizeof(std::uint32_t)) + 64];
    msghdr msg{};
    msg.msg_iov = &iov;
    msg.msg_iovlen = 1;
    msg.msg_control = control;
    msg.msg_controllen = sizeof control;
    const ssize_t n = recvmsg(sock_, &msg, MSG_DONTWAIT);
    if (n < 0) {
      if (errno == EINTR) continue;
      if (errno != EAGAIN && errno != EWOULDBLOCK) {
        ++read_errors_;
        usleep(10000);  // e.g. the interface went down: poll() keeps reporting it, do not spin
      }
      return;
    }
    if (n != static_cast<ssize_t>(sizeof k)) {
      ++read_errors_;
      continue;
    }
    drv::CanRxFrame f;
    f.rx_ns = 0;
    for (cmsghdr* c = CMSG_FIRSTHDR(&msg); c != nullptr; c = CMSG_NXTHDR(&msg, c)) {
      if (c->cmsg_level != SOL_SOCKET) continue;
      if (c->cmsg_type == SO_TIMESTAMPNS) {
        timespec ts{};
        std::memcpy(&ts, CMSG_DATA(c), sizeof ts);
        f.rx_ns = static_cast<std::int64_t>(ts.tv_sec) * 1000000000LL + ts.tv_nsec;
      } else if (c->cmsg_type == SO_RXQ_OVFL) {
        std::uint32_t total = 0;
        std::memcpy(&total, CMSG_DATA(c), sizeof total);
        if (total > last_drop_total_)
          drops_ += total - last_drop_total_;  // the kernel's running total
        last_drop_total_ = total;
      }
    }
    if (f.rx_ns == 0) f.rx_ns = RealtimeNs();
    ++frames_;
    f.extended = (k.can_id & CAN_EFF_FLAG) != 0;
    f.id = k.can_id & (f.extended ? CAN_EFF_MASK : CAN_SFF_MASK);
    f.len = k.len > 8 ? 8 : k.len;
    std::memcpy(f.data.data(), k.data, f.len);
    if (const auto s = decoder_.Add(f)) on_sample(*s);
  }
}

void PrintCanImuStats(const CanImuInput& in, std::FILE* to) {
  const auto& st = in.decoder().stats();
  const auto u = [](std::uint64_t v) { return static_cast<unsigned long long>(v); };
  std::fprintf(to,
               "navd: can_imu %s frames=%llu drops=%llu read_errors=%llu ari=%llu accs=%llu "
               "ssi2=%llu pulses=%llu "
               "imu=%llu no_time=%llu gaps=%llu unpaired=%llu other_source=%llu unknown_pgn=%llu "
               "bad_length=%llu "
               "not_available=%llu mcu_resets=%llu clock_jumps=%llu host_rate=%.6f mcu_ppm=%.1f\n",
               in.interface().c_str(), u(in.frames_read()), u(in.drops()), u(in.read_errors()),
               u(st.ari), u(st.accs), u(st.ssi2), u(st.pulses), u(st.imu_out), u(st.imu_no_time),
               u(st.imu_gap), u(st.unpaired), u(st.other_source), u(st.unknown_pgn),
               u(st.bad_length), u(st.not_available), u(st.mcu_resets),
               u(in.decoder().arrival_clock().jumps()), in.decoder().arrival_clock().rate(),
               in.decoder().mcu_clock().offset_ppm());
}

}  // namespace hil::navd

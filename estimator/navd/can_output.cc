#include "can_output.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include <linux/can.h>
#include <net/if.h>
#include <sys/ioctl.h>
#include <sys/socket.h>

namespace hil::navd {

CanOutput::CanOutput(const std::string& interface, const std::string& log_path,
                     std::uint8_t source_address, double rapid_rate_hz)
    : iface_name_(interface.empty() ? "can0" : interface),
      sa_(source_address),
      rapid_period_ns_(static_cast<std::int64_t>(std::llround(1e9 / rapid_rate_hz))) {
  if (!interface.empty()) {
    sock_ = socket(PF_CAN, SOCK_RAW, CAN_RAW);
    if (sock_ < 0)
      throw std::runtime_error("cannot open CAN socket for " + interface + ": " +
                               std::strerror(errno));
    ifreq ifr{};
    std::strncpy(ifr.ifr_name, interface.c_str(), IFNAMSIZ - 1);
    sockaddr_can addr{};
    if (ioctl(sock_, SIOCGIFINDEX, &ifr) < 0) {
      const std::string err = std::strerror(errno);
      close(sock_);
      throw std::runtime_error("no CAN interface " + interface + ": " + err);
    }
    addr.can_family = AF_CAN;
    addr.can_ifindex = ifr.ifr_ifindex;
    if (bind(sock_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) < 0) {
      const std::string err = std::strerror(errno);
      close(sock_);
      throw std::runtime_error("cannot bind CAN interface " + interface + ": " + err);
    }
  }
  if (!log_path.empty()) {
    log_ = std::fopen(log_path.c_str(), "w");
    if (!log_)
      throw std::runtime_error("cannot write CAN log " + log_path + ": " + std::strerror(errno));
  }
}

CanOutput::~CanOutput() {
  if (sock_ >= 0) close(sock_);
  if (log_) std::fclose(log_);
}

void CanOutput::Send(const estimator::outputs::CanFrame& f, std::int64_t utc_ns) {
  ++frames_;
  if (log_)
    std::fputs(estimator::outputs::CandumpLine(f, utc_ns / 1000, iface_name_).c_str(), log_);
  if (sock_ >= 0) {
    can_frame cf{};
    cf.can_id = f.id | CAN_EFF_FLAG;
    cf.len = f.len;
    std::memcpy(cf.data, f.data.data(), f.len);
    if (write(sock_, &cf, sizeof cf) != static_cast<ssize_t>(sizeof cf)) ++send_errors_;
  }
}

void CanOutput::Publish(const estimator::NavOutput& o, std::int64_t utc_ns) {
  namespace out = estimator::outputs;
  if (!enabled() || !o.valid) return;
  if (last_rapid_ < 0 || utc_ns / rapid_period_ns_ != last_rapid_ / rapid_period_ns_) {
    last_rapid_ = utc_ns;
    sid_ = static_cast<std::uint8_t>((sid_ + 1) % 253);
    Send(out::EncodePositionRapid(o.position.lat_deg, o.position.lon_deg, sa_), utc_ns);
    Send(out::EncodeCogSogRapid(sid_, std::atan2(o.v_N_mps.x(), o.v_N_mps.y()),
                                o.v_N_mps.head<2>().norm(), sa_),
         utc_ns);
    if (o.has_attitude) {
      const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX(),
                            y = o.q_NB * Eigen::Vector3d::UnitY();
      const double heading = M_PI / 2 - std::atan2(x.y(), x.x());
      Send(out::EncodeVesselHeading(sid_, heading, sa_), utc_ns);
      Send(out::EncodeAttitude(sid_, heading, std::asin(std::clamp(x.z(), -1.0, 1.0)),
                               -std::asin(std::clamp(y.z(), -1.0, 1.0)), sa_),
           utc_ns);
    }
  }
  const std::int64_t s = 1'000'000'000LL;
  if (last_slow_ < 0 || utc_ns / s != last_slow_ / s) {
    last_slow_ = utc_ns;
    const std::int64_t day_ns = 86400LL * s;
    const int method = (o.status & estimator::kStatusDeadReckoning) ? 6 : 1;
    const out::FastPacket fp = out::EncodeGnssPosition(
        sid_, static_cast<std::uint16_t>(utc_ns / day_ns),
        static_cast<double>(utc_ns % day_ns) * 1e-9, o.position.lat_deg, o.position.lon_deg,
        o.position.height_m, method, 8, 1.0, fp_seq_, sa_);
    fp_seq_ = static_cast<std::uint8_t>((fp_seq_ + 1) & 7);
    for (int i = 0; i < fp.count; ++i) Send(fp.frames[static_cast<std::size_t>(i)], utc_ns);
  }
  if (log_) std::fflush(log_);
}

}  // namespace hil::navd

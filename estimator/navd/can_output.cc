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
namespace {

// NMEA 2000's transmission interval of 129026 COG & SOG Rapid Update (canboat: 250 ms)
constexpr std::int64_t kCogSogPeriodNs = 250'000'000;
constexpr std::int64_t kSecondNs = 1'000'000'000;

// Whether `t` starts a new period since `last` (-1: nothing sent yet).
bool NewPeriod(std::int64_t t, std::int64_t last, std::int64_t period) {
  return last < 0 || t / period != last / period;
}

}  // namespace

CanOutput::CanOutput(const std::string& interface, const std::string& log_path,
                     std::uint8_t source_address, double rapid_rate_hz)
    : iface_name_(interface.empty() ? "can0" : interface),
      sa_(source_address),
      rapid_period_ns_(static_cast<std::int64_t>(std::llround(1e9 / rapid_rate_hz))),
      cog_sog_period_ns_(std::max<std::int64_t>(rapid_period_ns_, kCogSogPeriodNs)) {
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

void CanOutput::OnGnss(const estimator::GnssSample& g) {
  num_sv_ = g.num_sv;
  hdop_ = g.hdop;
  geoid_separation_m_ = g.geoid_separation_m;
}

void CanOutput::Publish(const estimator::NavOutput& o, std::int64_t utc_ns) {
  namespace out = estimator::outputs;
  if (!enabled() || !o.valid) return;
  const bool rapid = NewPeriod(utc_ns, last_rapid_, rapid_period_ns_);
  const bool cog_sog = NewPeriod(utc_ns, last_cog_sog_, cog_sog_period_ns_);
  // one SID per instant: what goes out now (and the 129029 of a whole second) shares it
  if (rapid || cog_sog) sid_ = static_cast<std::uint8_t>((sid_ + 1) % 253);
  if (rapid) {
    last_rapid_ = utc_ns;
    Send(out::EncodePositionRapid(o.position.lat_deg, o.position.lon_deg, sa_), utc_ns);
  }
  if (cog_sog) {
    last_cog_sog_ = utc_ns;
    Send(out::EncodeCogSogRapid(sid_, std::atan2(o.v_N_mps.x(), o.v_N_mps.y()),
                                o.v_N_mps.head<2>().norm(), sa_),
         utc_ns);
  }
  if (rapid && o.has_attitude) {
    const Eigen::Vector3d x = o.q_NB * Eigen::Vector3d::UnitX(),
                          y = o.q_NB * Eigen::Vector3d::UnitY();
    const double heading = M_PI / 2 - std::atan2(x.y(), x.x());
    Send(out::EncodeVesselHeading(sid_, heading, sa_), utc_ns);
    Send(out::EncodeAttitude(sid_, heading, std::asin(std::clamp(x.z(), -1.0, 1.0)),
                             -std::asin(std::clamp(y.z(), -1.0, 1.0)), sa_),
         utc_ns);
  }
  if (NewPeriod(utc_ns, last_slow_, kSecondNs)) {
    last_slow_ = utc_ns;
    SendGnssPosition(o, utc_ns);
  }
  if (log_) std::fflush(log_);
}

void CanOutput::SendGnssPosition(const estimator::NavOutput& o, std::int64_t utc_ns) {
  const std::int64_t day_ns = 86400LL * kSecondNs;
  const int method = (o.status & estimator::kStatusDeadReckoning) ? 6 : 1;
  const estimator::outputs::FastPacket fp = estimator::outputs::EncodeGnssPosition(
      sid_, static_cast<std::uint16_t>(utc_ns / day_ns),
      static_cast<double>(utc_ns % day_ns) * 1e-9, o.position.lat_deg, o.position.lon_deg,
      o.position.height_m, method, num_sv_, hdop_, fp_seq_, sa_, geoid_separation_m_);
  fp_seq_ = static_cast<std::uint8_t>((fp_seq_ + 1) & 7);
  for (int i = 0; i < fp.count; ++i) Send(fp.frames[static_cast<std::size_t>(i)], utc_ns);
}

}  // namespace hil::navd

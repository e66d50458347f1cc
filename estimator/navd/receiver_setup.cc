#include "receiver_setup.h"

#include <unistd.h>

#include <cstdio>

namespace hil::navd {

ReceiverSetup::ReceiverSetup(const estimator::NavdConfig& cfg) {
  if (!cfg.gnss_configure) return;
  estimator::drivers::ReceiverSetup want;
  want.rate_hz = cfg.gnss_rate_hz;
  const bool ubx = cfg.gnss_protocol == "ubx";
  want.ubx_navigation = ubx;
  want.nmea_off = ubx;       // a UBX host needs no NMEA: the baud goes to the NAV messages
  want.nmea_minimal = !ubx;  // an NMEA host needs GGA and RMC only
  conf_.emplace(estimator::drivers::UbxSetupCommands(want));
}

void ReceiverSetup::Service(SerialDevice& dev, std::int64_t now_ns) {
  if (!conf_ || dev.fd() < 0) return;
  if (dev.reopen_count() != seen_reopens_) {
    seen_reopens_ = dev.reopen_count();
    conf_->Restart();
    reported_ = false;
  }
  if (auto bytes = conf_->Poll(now_ns)) {
    if (write(dev.fd(), bytes->data(), bytes->size()) != static_cast<ssize_t>(bytes->size()))
      ++write_errors_;
  }
  if (conf_->done() && !reported_) {
    std::fprintf(stderr, "navd: receiver configuration on %s: %s\n", dev.path().c_str(),
                 conf_->Summary().c_str());
    reported_ = true;
  }
}

void ReceiverSetup::OnMessage(const estimator::drivers::UbxMessage& m) {
  if (conf_) conf_->OnMessage(m);
}

}  // namespace hil::navd

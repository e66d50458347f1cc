#pragma once
/// @file
/// navd's start-up configuration of its GNSS receiver over the receiver's own serial port:
/// the UBX CFG session of drivers/ubx_configurator.h, driven by the poll loop. Sent again from the
/// start whenever the port is reopened (the receiver may have been power-cycled).

#include <cstdint>
#include <optional>
#include <string_view>

#include "hil/estimator/drivers/ubx_configurator.h"
#include "hil/estimator/navd/navd_config.h"

#include "serial_device.h"

namespace hil::navd {

class ReceiverSetup {
 public:
  /// Empty (does nothing) unless `[input] gnss_configure = true`.
  explicit ReceiverSetup(const estimator::NavdConfig& cfg);

  bool enabled() const { return conf_.has_value(); }
  /// True while commands are outstanding: the loop must feed the port's bytes to the UBX decoder
  /// (for the ACKs) even when it reads NMEA.
  bool active() const { return conf_ && !conf_->done(); }
  /// Writes what is due to the open device; reports the outcome on stderr once per session.
  void Service(SerialDevice& dev, std::int64_t now_ns);
  /// Every UBX message decoded from the receiver's port.
  void OnMessage(const estimator::drivers::UbxMessage& m);
  std::uint64_t write_errors() const { return write_errors_; }

 private:
  std::optional<estimator::drivers::UbxConfigurator> conf_;
  std::uint64_t seen_reopens_ = 0, write_errors_ = 0;
  bool reported_ = false;
};

}  // namespace hil::navd

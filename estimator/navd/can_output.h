#pragma once
/// @file
/// navd's NMEA 2000 output: encodes the solution (129025, 129026, 127250, 127257 at the rapid rate;
/// 129029 once per second) and sends the frames to a SocketCAN interface and/or appends them to a
/// `candump -l` log file. The only file of navd that touches CAN sockets.

#include <cstdint>
#include <cstdio>
#include <string>

#include "hil/estimator/navigator.h"
#include "hil/estimator/outputs/n2k_encoder.h"

namespace hil::navd {

class CanOutput {
 public:
  /// Opens the outputs; `interface` or `log_path` may be empty. @throws std::runtime_error naming
  /// the interface or file when it cannot be opened.
  CanOutput(const std::string& interface, const std::string& log_path, std::uint8_t source_address,
            double rapid_rate_hz);
  ~CanOutput();
  CanOutput(const CanOutput&) = delete;
  CanOutput& operator=(const CanOutput&) = delete;

  bool enabled() const { return sock_ >= 0 || log_ != nullptr; }
  /// Sends what is due at this solution's time of validity (UTC Unix ns).
  void Publish(const estimator::NavOutput& o, std::int64_t utc_ns);
  std::uint64_t send_errors() const { return send_errors_; }
  std::uint64_t frames_sent() const { return frames_; }

 private:
  void Send(const estimator::outputs::CanFrame& f, std::int64_t utc_ns);
  int sock_ = -1;
  std::FILE* log_ = nullptr;
  std::string iface_name_;
  std::uint8_t sa_;
  std::int64_t rapid_period_ns_;
  std::int64_t last_rapid_ = -1, last_slow_ = -1;
  std::uint8_t sid_ = 0, fp_seq_ = 0;
  std::uint64_t send_errors_ = 0, frames_ = 0;
};

}  // namespace hil::navd

#pragma once
/// @file
/// navd's NMEA 2000 output: encodes the solution and sends the frames to a SocketCAN interface
/// and/or appends them to a `candump -l` log file. The only file of navd that touches CAN sockets.
/// Rates (vectors/can/hil_imu.dbc's GenMsgCycleTime, after NMEA 2000's default transmission
/// intervals in canboat's database): 129025, 127250, 127257 at the rapid rate (`can_rate_hz`,
/// default 10 Hz); 129026 COG & SOG Rapid Update every 250 ms (at most; slower when the rapid rate
/// is); 129029 GNSS Position Data once per second, with the satellites, HDOP and geoid separation
/// the receiver last reported (OnGnss), "not available" before it reported any. Each goes out with
/// the first solution of its period (so at a 10 Hz solution rate 129026's 250 ms alternate 200 and
/// 300 ms); the frames of one instant share a SID.

#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>

#include "hil/estimator/navigator.h"
#include "hil/estimator/outputs/n2k_encoder.h"
#include "hil/estimator/samples.h"

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
  /// A receiver's fix: its satellites, HDOP and geoid separation go into the next 129029.
  void OnGnss(const estimator::GnssSample& g);
  std::uint64_t send_errors() const { return send_errors_; }
  std::uint64_t frames_sent() const { return frames_; }

 private:
  void Send(const estimator::outputs::CanFrame& f, std::int64_t utc_ns);
  void SendGnssPosition(const estimator::NavOutput& o, std::int64_t utc_ns);
  int sock_ = -1;
  std::FILE* log_ = nullptr;
  std::string iface_name_;
  std::uint8_t sa_;
  std::int64_t rapid_period_ns_, cog_sog_period_ns_;
  std::int64_t last_rapid_ = -1, last_cog_sog_ = -1, last_slow_ = -1;
  int num_sv_ = -1;                           // the receiver's last report; -1: none yet
  double hdop_ = 0;                           // 0: not reported
  std::optional<double> geoid_separation_m_;  // none: not reported
  std::uint8_t sid_ = 0, fp_seq_ = 0;
  std::uint64_t send_errors_ = 0, frames_ = 0;
};

}  // namespace hil::navd

#pragma once
/// @file
/// navd's IMU input from CAN: a raw SocketCAN socket on the configured interface, filtered in the
/// kernel to the IMU's four PGNs (ARI, ACCS, SSI2, HIL_TIME_PULSE), with kernel receive timestamps
/// (SO_TIMESTAMPNS) and the socket's drop counter (SO_RXQ_OVFL). Frames go to the J1939 decoder
/// (estimator/drivers/j1939_imu_decoder.h), which turns them into IMU samples on GPS time. The only
/// file of navd that reads CAN sockets.

#include <cstdint>
#include <cstdio>
#include <functional>
#include <string>

#include "hil/estimator/drivers/j1939_imu_decoder.h"

namespace hil::navd {

class CanImuInput {
 public:
  /// Opens and binds the socket. @throws std::runtime_error naming the interface.
  CanImuInput(const std::string& interface,
              const estimator::drivers::J1939ImuDecoderConfig& config);
  ~CanImuInput();
  CanImuInput(const CanImuInput&) = delete;
  CanImuInput& operator=(const CanImuInput&) = delete;

  int fd() const { return sock_; }
  /// Reads every frame waiting (non-blocking) and hands each completed IMU sample to `on_sample`.
  void ReadAll(const std::function<void(const estimator::ImuSample&)>& on_sample);
  const estimator::drivers::J1939ImuDecoder& decoder() const { return decoder_; }
  std::uint64_t frames_read() const { return frames_; }
  /// Frames the kernel dropped because this socket's receive queue was full.
  std::uint64_t drops() const { return drops_; }
  std::uint64_t read_errors() const { return read_errors_; }
  const std::string& interface() const { return iface_; }

 private:
  std::string iface_;
  int sock_ = -1;
  estimator::drivers::J1939ImuDecoder decoder_;
  std::uint64_t frames_ = 0, drops_ = 0, read_errors_ = 0;
  std::uint32_t last_drop_total_ = 0;
};

/// One line of counters ("navd: can_imu …") for navd's stop report.
void PrintCanImuStats(const CanImuInput& in, std::FILE* to);

}  // namespace hil::navd

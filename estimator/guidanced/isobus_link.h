#pragma once
// guidanced's ISOBUS command channel (estimator/guidanced/README.md): Guidance System Command
// frames to the steering ECU and its Guidance Machine Info back, over a SocketCAN interface
// (`--isobus-can vcan0`) or a serial SLCAN adapter (`--isobus-slcan /dev/ttyACM0`: the
// controller sets 250 kbit/s and opens the channel itself, as slcand would). Fixed buffers.
#include <cstdint>
#include <string>

#include "hil/estimator/guidance/isobus_guidance_codec.h"
#include "hil/estimator/guidance/slcan_codec.h"

namespace hil::guidanced {

class IsobusLink {
 public:
  /// Opens the interface (`slcan` false) or the adapter's tty (`slcan` true); false with errno.
  bool Open(const std::string& where, bool slcan, std::uint8_t ecu_address);
  int fd() const { return fd_; }
  /// Sends one frame; false when the write failed.
  bool Send(const estimator::guidance::IsobusFrame& frame);
  /// Reads what the ECU sent; false when the link ended.
  bool OnReadable();
  /// The ECU's latest Guidance Machine Info asks for "not intended to steer" (after an exit).
  bool reset_requested() const { return reset_requested_; }
  void clear_reset_request() { reset_requested_ = false; }
  std::uint64_t machine_infos() const { return machine_infos_; }
  std::uint64_t refusals() const { return refusals_; }

 private:
  void OnFrame(const estimator::guidance::IsobusFrame& frame);
  bool WriteAll(const char* p, std::size_t n);

  int fd_ = -1;
  bool slcan_ = false;
  std::uint8_t ecu_ = 0x1C;
  estimator::guidance::SlcanReader reader_;
  bool reset_requested_ = false;
  std::uint64_t machine_infos_ = 0, refusals_ = 0;
};

}  // namespace hil::guidanced

#pragma once
/// @file
/// Start-up configuration of a u-blox 5 receiver, as a real host driver does it: a list of UBX CFG
/// commands sent one at a time, each waiting for its ACK-ACK (or ACK-NAK) with a timeout and a few
/// retries. Transport-free: the caller writes the bytes `Poll` returns to the receiver's port and
/// hands every decoded UBX message to `OnMessage`. Times are host monotonic nanoseconds (the
/// configuration protocol runs on the host's clock; nothing here reaches the filter).
///
/// Commands (u-blox 5 protocol, class 0x06):
///  - CFG-RATE (06 08): measRate ms, navRate 1, timeRef 1 (GPS time);
///  - CFG-MSG (06 01), 3-byte form: class, id, rate on the port the command arrives on.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hil/estimator/drivers/ubx_decoder.h"

namespace hil::estimator::drivers {

/// One CFG command and what became of it.
struct UbxCommand {
  enum class Result { kPending, kAcked, kNaked, kTimedOut };
  std::string name;  ///< e.g. "CFG-MSG NAV-POSLLH 1"
  std::uint8_t cls = 0, id = 0;
  std::string frame;  ///< the complete UBX frame to send
  Result result = Result::kPending;
  int attempts = 0;
};

/// What the receiver should send after start-up.
struct ReceiverSetup {
  double rate_hz = 0;           ///< navigation rate; 0 leaves the receiver's rate alone
  bool ubx_navigation = false;  ///< enable NAV-POSLLH, NAV-VELNED, NAV-SOL, NAV-TIMEGPS every epoch
  bool nmea_minimal = false;    ///< GGA and RMC every epoch, GLL/GSA/GSV/VTG off (saves the baud)
  bool nmea_off = false;        ///< all six default NMEA sentences off (UBX-only hosts)
};

/// The CFG commands that put a receiver into `setup`, in the order a driver sends them: the
/// messages to switch off, those to switch on, then the rate (so the output never exceeds the baud
/// on the way).
std::vector<UbxCommand> UbxSetupCommands(const ReceiverSetup& setup);

/// Sends commands one by one, waiting for the acknowledgement of each.
class UbxConfigurator {
 public:
  /// @param timeout_ns how long to wait for an ACK before sending the command again
  /// @param max_attempts sends per command before it is given up as timed out
  /// The default timeout covers an ACK queued behind a whole epoch of NMEA at 9600 baud; a shorter
  /// one resends too early, and u-blox ACKs name only the class and id (every CFG-MSG looks alike).
  explicit UbxConfigurator(std::vector<UbxCommand> commands,
                           std::int64_t timeout_ns = 1'500'000'000, int max_attempts = 3);

  /// Bytes to write now (the current command, first send or retry), if any.
  std::optional<std::string> Poll(std::int64_t now_ns);
  /// Every decoded UBX message of the receiver's port; ACK-ACK / ACK-NAK of the current command
  /// settle it. Other messages are ignored.
  void OnMessage(const UbxMessage& m);
  /// Starts over from the first command (the port was reopened, the receiver restarted).
  void Restart();

  bool done() const { return next_ >= commands_.size(); }
  /// True when every command was acknowledged.
  bool all_acked() const;
  const std::vector<UbxCommand>& commands() const { return commands_; }
  /// One line such as "7 commands: 6 acked, 1 refused, 0 unanswered (CFG-MSG NAV-TIMEGPS 1 NAK)".
  std::string Summary() const;

 private:
  std::vector<UbxCommand> commands_;
  std::int64_t timeout_ns_;
  int max_attempts_;
  std::size_t next_ = 0;
  std::optional<std::int64_t> sent_at_ns_;
};

}  // namespace hil::estimator::drivers

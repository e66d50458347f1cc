#pragma once
/// @file
/// The emulated serial CAN adapter (a Lawicel CAN232 / CANUSB class device, as Linux `slcand` and
/// the common USB-CAN adapters in SLCAN mode speak it; vectors/slcan/README.md): the session layer
/// above slcan_framing.h. It executes the host's records and answers as the adapter does:
///  - `Sn` (n = 0…8: 10, 20, 50, 100, 125, 250, 500, 800, 1000 kbit/s) and `sxxyy` (BTR0/BTR1) set
///    the bit rate while the channel is closed; `O` opens, `L` opens listen-only, `C` closes (a
///    closed channel too: hosts such as slcand close first);
///    `V` (version), `N` (serial number), `F` (status flags), `Zn` (receive time stamps off/on),
///    `Mxxxxxxxx` / `mxxxxxxxx` (acceptance code / mask: accepted, not filtered);
///  - `t`/`T`/`r`/`R` transmit a frame while the channel is open (not listen-only): answered
///    `z` CR (11-bit) / `Z` CR (29-bit);
///  - success is CR (13), refusal BEL (7): a bad record, an unknown command, a frame while closed
///    or listen-only, a bit rate while open. Refusals are counted.
/// Frames from the bus reach the host only while the channel is open (otherwise counted dropped),
/// with a 4-digit millisecond time stamp (mod 60000) appended when `Z1` is set.
/// Pure and deterministic: the times are the emulated arrival times the caller gives.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/link/cr_line_framer.h"
#include "hil/firmware_emu/link/slcan_framing.h"

namespace hil::link {

struct SlcanAdapterCounters {
  std::uint64_t records = 0;            ///< records received from the host
  std::uint64_t frames_from_host = 0;   ///< frames the host transmitted (onto the bus)
  std::uint64_t frames_to_host = 0;     ///< bus frames the host was sent
  std::uint64_t dropped_closed = 0;     ///< bus frames dropped: the channel was closed
  std::uint64_t refused = 0;            ///< records answered with BEL
  std::uint64_t opens = 0, closes = 0;  ///< `O`/`L` and `C` executed
};

class SlcanAdapter {
 public:
  /// `serial_number`: the 4 characters `N` answers.
  explicit SlcanAdapter(std::string serial_number = "HIL1");

  /// Bytes the host wrote, arriving at `t`: the adapter's answers are appended to `reply`, the
  /// frames the host transmitted (stamped `t`) to `frames`.
  void OnHostBytes(Time t, std::string_view bytes, std::string& reply,
                   std::vector<CanFrame>& frames);
  /// The record of a bus frame for the host, or empty when the channel is closed.
  std::string ToHost(const CanFrame& frame);

  bool open() const { return open_; }
  bool listen_only() const { return listen_only_; }
  /// The bit rate set (bit/s; 0 after `s` with BTR values).
  int bitrate_bps() const { return bitrate_bps_; }
  const SlcanAdapterCounters& counters() const { return counters_; }
  /// Records over kMaxSlcanRecord, counted from their first byte past the limit.
  std::uint64_t overlong_records() const {
    return splitter_.overlong_lines() + (splitter_.discarding() ? 1 : 0);
  }

 private:
  /// Executes one record; returns the answer.
  std::string Execute(Time t, const std::string& record, std::vector<CanFrame>& frames);
  std::string Transmit(Time t, const std::string& record, std::vector<CanFrame>& frames);
  std::string Refuse();

  std::string serial_number_;
  CrLineFramer splitter_{kMaxSlcanRecord};
  bool open_ = false;
  bool listen_only_ = false;
  bool timestamps_ = false;
  int bitrate_bps_ = 0;
  SlcanAdapterCounters counters_;
};

}  // namespace hil::link

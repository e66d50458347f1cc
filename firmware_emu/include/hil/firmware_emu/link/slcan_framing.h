#pragma once
/// @file
/// Framing layer of the SLCAN (Lawicel CAN232/CANUSB ASCII) protocol, the adapter's side
/// (vectors/slcan/README.md): one CAN frame as one ASCII record ended by CR (13).
///   data frame    `tiiiLdd…` (11-bit id, 3 hex digits)  `Tiiiiiiii Ldd…` (29-bit id, 8 hex digits)
///   remote frame  `riiiL`                                `RiiiiiiiiL`
/// L is the data length 0–8 (one digit), dd two upper-case hex digits per data byte. Decoding takes
/// either case. Never throws on input.

#include <cstddef>
#include <string>
#include <string_view>

#include "hil/firmware_emu/device.h"

namespace hil::link {

/// The longest record: `T` + 8 + 1 + 16 hex digits (+ CR). A longer one is discarded up to its CR
/// (link::CrLineFramer) and counted.
inline constexpr std::size_t kMaxSlcanRecord = 26;

/// The record of a classic frame (with its CR). FD frames and data beyond 8 bytes are not
/// representable: such a frame is encoded with its first 8 bytes.
std::string EncodeSlcanFrame(const CanFrame& frame);

enum class SlcanFrameError : std::uint8_t {
  kNone = 0,
  kNotAFrame,  ///< the record does not start with t, T, r or R
  kBadId,      ///< too few or non-hex identifier digits, or an 11-bit id above 0x7FF / 29-bit above
               ///< 0x1FFFFFFF
  kBadLength,  ///< the length digit is not 0–8
  kBadData,    ///< the data digits are not 2·L hex digits
};

/// Decodes one record (without its CR). On success `out` holds the frame (its time untouched).
SlcanFrameError DecodeSlcanFrame(std::string_view record, CanFrame& out);

}  // namespace hil::link

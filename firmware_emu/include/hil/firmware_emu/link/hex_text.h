#pragma once
/// @file
/// Hexadecimal digits of the text links (candump logs, SLCAN records): upper-case out, either case
/// in.

#include <cstdint>
#include <string>

namespace hil::link {

/// The value of one hex digit (either case), or -1 for any other character.
inline int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

/// Appends the low `digits` hex digits of v, upper case, most significant first.
inline void PutHex(std::string& out, std::uint32_t v, int digits) {
  constexpr char kDigits[] = "0123456789ABCDEF";
  for (int i = digits - 1; i >= 0; --i) out.push_back(kDigits[(v >> (4 * i)) & 0xF]);
}

}  // namespace hil::link

#pragma once
/// @file
/// Test support: bytes written as hexadecimal text, the form the golden files and the protocol
/// sheets' examples give them in ("b562", "B5 62", "B5 62 " …).

#include <string>
#include <string_view>

namespace hil::test {

struct HexStyle {
  bool upper = false;     ///< "B5" rather than "b5"
  const char* sep = "";   ///< between two bytes
  bool trailing = false;  ///< `sep` after the last byte too
};

/// `bytes` as two hexadecimal digits a byte.
inline std::string HexBytes(std::string_view bytes, HexStyle style = {}) {
  const char* digits = style.upper ? "0123456789ABCDEF" : "0123456789abcdef";
  const std::string_view sep(style.sep);
  std::string out;
  out.reserve(bytes.size() * (2 + sep.size()));
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const auto b = static_cast<unsigned char>(bytes[i]);
    if (i > 0) out += sep;
    out += digits[b >> 4];
    out += digits[b & 15];
  }
  if (style.trailing && !bytes.empty()) out += sep;
  return out;
}

}  // namespace hil::test

#pragma once
/// @file
/// Fixed-point decimal text for the run folder's CSV files and plots: the characters printf's
/// "%.Nf" writes (the correctly rounded digits of the exact binary value), from std::to_chars,
/// without a format string to parse or a locale to consult per number. A run writes millions of
/// these (seed004: about 800 000 in its three CSV files).

#include <charconv>
#include <stdexcept>
#include <string>

namespace hil::harness {

/// Appends `v` with `decimals` (0 to kMaxDecimals) digits after the point.
inline constexpr int kMaxDecimals = 60;
inline void AppendFixed(std::string& out, double v, int decimals) {
  if (decimals < 0 || decimals > kMaxDecimals)
    throw std::out_of_range("AppendFixed: " + std::to_string(decimals) + " decimals");
  // the longest: a sign, 309 integer digits (DBL_MAX), the point and kMaxDecimals decimals
  char buf[1 + 309 + 1 + kMaxDecimals];
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  out.append(buf, r.ptr);
}

/// Appends the values with `decimals` digits each, a comma before every one but the first.
template <typename... Values>
void AppendFixedRow(std::string& out, int decimals, double first, Values... rest) {
  AppendFixed(out, first, decimals);
  ((out.push_back(','), AppendFixed(out, rest, decimals)), ...);
}

}  // namespace hil::harness

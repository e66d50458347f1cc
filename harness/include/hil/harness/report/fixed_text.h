#pragma once
/// @file
/// Fixed-point decimal text for the run folder's CSV files and plots: the characters printf's
/// "%.Nf" writes (the correctly rounded digits of the exact binary value), from std::to_chars,
/// without a format string to parse or a locale to consult per number. A run writes millions of
/// these (seed004: about 800 000 in its three CSV files).

#include <charconv>
#include <cstdio>
#include <string>

namespace hil::harness {

/// Appends `v` with `decimals` digits after the point.
inline void AppendFixed(std::string& out, double v, int decimals) {
  char buf[128];
  const std::to_chars_result r =
      std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals);
  if (r.ec == std::errc{}) {
    out.append(buf, r.ptr);
    return;
  }
  // beyond 10^100 (never a metre or a second here): printf's own digits, however many
  const int n = std::snprintf(nullptr, 0, "%.*f", decimals, v);
  std::string wide(static_cast<std::size_t>(n) + 1, '\0');
  std::snprintf(wide.data(), wide.size(), "%.*f", decimals, v);
  out.append(wide.data(), static_cast<std::size_t>(n));
}

/// Appends the values with `decimals` digits each, a comma before every one but the first.
template <typename... Values>
void AppendFixedRow(std::string& out, int decimals, double first, Values... rest) {
  AppendFixed(out, first, decimals);
  ((out.push_back(','), AppendFixed(out, rest, decimals)), ...);
}

}  // namespace hil::harness

#include "hil/estimator/datasets/fixed_decimal.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>

namespace hil::estimator::datasets {
namespace {

constexpr int kMaxFastDecimals = 12;
constexpr double kPow10[kMaxFastDecimals + 1] = {1e0, 1e1, 1e2, 1e3,  1e4,  1e5, 1e6,
                                                 1e7, 1e8, 1e9, 1e10, 1e11, 1e12};

// |v|·10^decimals rounded to the nearest integer, as std::to_chars rounds the exact binary value;
// nullopt when that is not certain (a tie, or beyond a double's exact integers). The residual
// |v|·10^d − n comes from one fused multiply-add (10^d ≤ 10^12 is exact), so it is the exact
// residual rounded once: its comparison with ½ is exact unless it rounds onto ½ itself.
std::optional<std::int64_t> ScaledRound(double abs_v, int decimals) {
  const double p = kPow10[decimals];
  const double s = abs_v * p;
  if (!(s < 4e15)) return std::nullopt;  // also NaN and infinities
  auto n = static_cast<std::int64_t>(s + 0.5);
  double r = std::fma(abs_v, p, -static_cast<double>(n));
  if (r > 0.5) {
    ++n;
    r -= 1.0;
  } else if (r < -0.5) {
    --n;
    r += 1.0;
  }
  if (!(r < 0.5 && r > -0.5)) return std::nullopt;  // a tie: to_chars decides
  return n;
}

}  // namespace

char* FormatFixed(char* first, char* last, double v, int decimals) {
  constexpr int kLongest = 1 + 16 + 2 + kMaxFastDecimals;  // sign, digits, "0.", zeros
  const std::optional<std::int64_t> n =
      decimals >= 0 && decimals <= kMaxFastDecimals && last - first >= kLongest
          ? ScaledRound(std::fabs(v), decimals)
          : std::nullopt;
  if (!n) {
    const std::to_chars_result r =
        std::to_chars(first, last, v, std::chars_format::fixed, decimals);
    return r.ec == std::errc() ? r.ptr : first;
  }
  char* p = first;
  if (std::signbit(v)) *p++ = '-';  // as to_chars: "-0.000" for −0 and for what rounds to it
  char digits[24];
  const char* const end = std::to_chars(digits, digits + sizeof digits, *n).ptr;
  const int count = static_cast<int>(end - digits);
  const char* q = digits;
  if (count > decimals) {
    for (int k = count - decimals; k > 0; --k) *p++ = *q++;
  } else {
    *p++ = '0';
  }
  if (decimals == 0) return p;
  *p++ = '.';
  for (int k = count; k < decimals; ++k) *p++ = '0';
  while (q != end) *p++ = *q++;
  return p;
}

}  // namespace hil::estimator::datasets

#include "hil/estimator/datasets/fixed_decimal.h"

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <utility>

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

// Writes the `Count` low decimal digits of `value` (zero-padded) ending just before `end`, two
// at a time from a table of the pairs 00..99.
template <int Count>
void WriteFractionDigits(char* end, std::uint64_t value) {
  static constexpr char kPairs[] =
      "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
      "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
      "8081828384858687888990919293949596979899";
  for (int count = Count; count >= 2; count -= 2) {  // a constant count: the loop unrolls
    const auto pair = static_cast<unsigned>(value % 100) * 2;
    value /= 100;
    *--end = kPairs[pair + 1];
    *--end = kPairs[pair];
  }
  if constexpr (Count % 2 == 1) *--end = static_cast<char>('0' + value % 10);
}

// `scaled` / 10^Decimals written as "integer.fraction"; the compile-time divisor lets the
// compiler divide by multiplication (a profile found the run-time 64-bit division dominant).
template <int Decimals>
char* WriteSplitDigits(char* p, char* last, std::uint64_t scaled) {
  constexpr auto kScale = static_cast<std::uint64_t>(kPow10[Decimals]);
  p = std::to_chars(p, last, scaled / kScale).ptr;  // the integer part, "0" when below one
  if constexpr (Decimals == 0) {
    return p;
  } else {
    *p++ = '.';
    WriteFractionDigits<Decimals>(p + Decimals, scaled % kScale);
    return p + Decimals;
  }
}

template <int... D>
char* WriteScaledDigitsOf(std::integer_sequence<int, D...> /*unused*/, char* p, char* last,
                          std::uint64_t scaled, int decimals) {
  char* out = p;
  (void)((decimals == D && ((out = WriteSplitDigits<D>(p, last, scaled)), true)) || ...);
  return out;
}

char* WriteScaledDigits(char* p, char* last, std::uint64_t scaled, int decimals) {
  return WriteScaledDigitsOf(std::make_integer_sequence<int, kMaxFastDecimals + 1>{}, p, last,
                             scaled, decimals);
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
  return WriteScaledDigits(p, last, static_cast<std::uint64_t>(*n), decimals);
}

}  // namespace hil::estimator::datasets

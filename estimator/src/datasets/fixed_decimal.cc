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

constexpr char kDigitPairs[] =
    "00010203040506070809101112131415161718192021222324252627282930313233343536373839"
    "40414243444546474849505152535455565758596061626364656667686970717273747576777879"
    "8081828384858687888990919293949596979899";

// Writes x < 10^(2·Pairs) as 2·Pairs digits (zero-padded), leading pair first, by fixed-point
// multiplication: y = x·⌈2^57 / 10^(2·Pairs − 2)⌉ has the leading pair in its top bits, and each
// ×100 of the 57-bit fraction brings up the next one (no division). Checked against printf for
// every x below 10^8 (all Pairs ≤ 4); the tests compare the whole formatter with std::to_chars.
template <int Pairs>
void WriteDigitPairs(char* out, std::uint32_t x) {
  static_assert(Pairs >= 1 && Pairs <= 4);
  constexpr int kShift = 57;
  constexpr auto kDivisor = static_cast<std::uint64_t>(kPow10[2 * Pairs - 2]);
  constexpr std::uint64_t kMagic = ((std::uint64_t{1} << kShift) + kDivisor - 1) / kDivisor;
  constexpr std::uint64_t kMask = (std::uint64_t{1} << kShift) - 1;
  std::uint64_t y = x * kMagic;
  for (int i = 0; i < Pairs; ++i) {  // a constant count: the loop unrolls
    const auto pair = static_cast<unsigned>(y >> kShift) * 2;
    out[2 * i] = kDigitPairs[pair];
    out[2 * i + 1] = kDigitPairs[pair + 1];
    y = (y & kMask) * 100;
  }
}

// Writes value < 10^Count as exactly `Count` digits (zero-padded) from `out` on: eight at a time
// from the right, an odd leading digit on its own.
template <int Count>
void WriteFractionDigits(char* out, std::uint64_t value) {
  static_assert(Count >= 1 && Count <= kMaxFastDecimals);
  if constexpr (Count > 8) {
    constexpr std::uint64_t kLow = 100000000;
    WriteFractionDigits<Count - 8>(out, value / kLow);
    WriteDigitPairs<4>(out + Count - 8, static_cast<std::uint32_t>(value % kLow));
  } else if constexpr (Count % 2 == 1) {
    constexpr auto kRest = static_cast<std::uint32_t>(kPow10[Count - 1]);
    const auto v = static_cast<std::uint32_t>(value);
    out[0] = static_cast<char>('0' + v / kRest);
    if constexpr (Count > 1) WriteDigitPairs<Count / 2>(out + 1, v % kRest);
  } else {
    WriteDigitPairs<Count / 2>(out, static_cast<std::uint32_t>(value));
  }
}

// The integer part: one or two digits from the table (most of navd's columns), else to_chars.
char* WriteIntegerPart(char* p, char* last, std::uint64_t v) {
  if (v < 10) {
    *p = static_cast<char>('0' + v);
    return p + 1;
  }
  if (v < 100) {
    p[0] = kDigitPairs[2 * v];
    p[1] = kDigitPairs[2 * v + 1];
    return p + 2;
  }
  return std::to_chars(p, last, v).ptr;
}

// `scaled` / 10^Decimals written as "integer.fraction"; the compile-time divisor lets the
// compiler divide by multiplication (a profile found the run-time 64-bit division dominant).
template <int Decimals>
char* WriteSplitDigits(char* p, char* last, std::uint64_t scaled) {
  constexpr auto kScale = static_cast<std::uint64_t>(kPow10[Decimals]);
  p = WriteIntegerPart(p, last, scaled / kScale);  // "0" when below one
  if constexpr (Decimals == 0) {
    return p;
  } else {
    *p++ = '.';
    WriteFractionDigits<Decimals>(p, scaled % kScale);
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

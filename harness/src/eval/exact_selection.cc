#include "hil/harness/eval/exact_selection.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace hil::harness {
namespace {

// A key whose unsigned order is the values' order (negative values' bits inverted).
std::uint64_t Key(double v) {
  const auto b = std::bit_cast<std::uint64_t>(v);
  return (b >> 63) != 0 ? ~b : b | (std::uint64_t{1} << 63);
}

constexpr int kDigitBits = 12;

}  // namespace

double KthSmallest(std::size_t n, std::size_t k, const ValuePass& pass) {
  if (k >= n) throw std::invalid_argument("KthSmallest: rank beyond the set");
  std::uint64_t prefix = 0;  // the high `known` bits of the wanted key
  int known = 0;
  std::size_t candidates = n;  // values whose key starts with prefix
  std::vector<std::size_t> counts(std::size_t{1} << kDigitBits);
  while (candidates > kSelectionInMemory && known < 64) {
    const int bits = std::min(kDigitBits, 64 - known);
    const int shift = 64 - known - bits;
    std::fill(counts.begin(), counts.end(), 0);
    pass([&](double v) {
      const std::uint64_t key = Key(v);
      if (known > 0 && (key >> (64 - known)) != prefix) return;
      ++counts[static_cast<std::size_t>((key >> shift) & ((std::uint64_t{1} << bits) - 1))];
    });
    std::size_t digit = 0;
    while (k >= counts[digit]) k -= counts[digit++];
    prefix = (prefix << bits) | digit;
    known += bits;
    candidates = counts[digit];
  }
  if (known == 64) {  // every bit known: the key is the value
    const std::uint64_t b = (prefix >> 63) != 0 ? prefix & ~(std::uint64_t{1} << 63) : ~prefix;
    return std::bit_cast<double>(b);
  }
  std::vector<double> kept;
  kept.reserve(candidates);
  pass([&](double v) {
    if (known == 0 || (Key(v) >> (64 - known)) == prefix) kept.push_back(v);
  });
  std::nth_element(kept.begin(), kept.begin() + static_cast<std::ptrdiff_t>(k), kept.end());
  return kept[k];
}

double NearestRankP95(std::size_t n, const ValuePass& pass) {
  if (n == 0) return 0;
  const auto rank = static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(n)));
  return KthSmallest(n, std::clamp<std::size_t>(rank, 1, n) - 1, pass);
}

}  // namespace hil::harness

#pragma once
/// @file
/// The k-th smallest of a set of values read as often as needed (a spill file, spill_file.h), in
/// bounded memory: exact, as std::sort would give it, not a sketch's approximation (issue 40: the
/// tracking figures' nearest-rank percentiles of a run of any length). A set of at most
/// `kInMemory` values (our choice, 64 KiB) is read once and selected in memory; a larger one is
/// narrowed down by the digits of its values' order-preserving 64-bit keys, 12 bits a pass (4096
/// counters), until the candidates fit in memory: at most 6 passes.

#include <cstddef>
#include <functional>

namespace hil::harness {

/// One pass over the values: calls its argument on each.
using ValueVisit = std::function<void(double)>;
using ValuePass = std::function<void(const ValueVisit&)>;

/// The value of rank `k` (0 = the smallest) of the `n` values `pass` visits (k < n, no NaN).
double KthSmallest(std::size_t n, std::size_t k, const ValuePass& pass);

/// Our choice: candidates selected in memory (8192 doubles, 64 KiB).
inline constexpr std::size_t kSelectionInMemory = 8192;

/// The nearest-rank 95th percentile of the values (the rank min(n, ceil(0.95 n))), 0 when none.
double NearestRankP95(std::size_t n, const ValuePass& pass);

}  // namespace hil::harness

#pragma once
/// @file
/// Overlapping Allan deviation of a uniformly sampled rate y (IEEE Std 952-1997, annex C; Riley,
/// NIST SP 1065 §5.2.4): with θ the cumulative sum of y·τ0 and τ = m·τ0,
///   σ²(τ) = Σ_{k=0}^{N−2m} (θ_{k+2m} − 2θ_{k+m} + θ_k)² / (2 τ² (N − 2m + 1)),
/// where θ has N + 1 points (θ_0 = 0) for N samples. Computed from the cumulative sum in O(N) per
/// τ (the mean rate is removed first: it cancels and would cost precision in θ).

#include <cstddef>
#include <vector>

namespace hil::harness {

/// Octave-spaced cluster sizes m = 1, 2, 4, ... with m <= samples / 4 (at least N/2 + 1
/// overlapping second differences at the longest τ). Empty below 4 samples.
std::vector<std::size_t> OctaveClusterSizes(std::size_t samples);

/// σ(m·tau0_s) for each m (same unit as y). @throws std::invalid_argument for an m with
/// 2m > N or m = 0.
std::vector<double> OverlappingAllanDeviation(const std::vector<double>& y, double tau0_s,
                                              const std::vector<std::size_t>& m);

}  // namespace hil::harness

#pragma once
/// @file
/// The empirical percentile of a set of values, the one interpolation every figure of the harness
/// uses (the evaluation's percentiles, QuantileSketch's exact mode, the links' schedule errors).

#include <vector>

namespace hil::harness {

/// Empirical percentile (0–100) by linear interpolation of sorted values.
double Percentile(std::vector<double> values, double pct);
/// The same of values already sorted.
double PercentileOfSorted(const std::vector<double>& v, double pct);

}  // namespace hil::harness

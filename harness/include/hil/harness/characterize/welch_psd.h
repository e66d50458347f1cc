#pragma once
/// @file
/// One-sided power spectral density by Welch's method (Welch 1967): Hann-windowed segments of
/// `segment` samples overlapping by half, each with its mean removed, |FFT|² averaged and scaled
/// to unit²/Hz so that the PSD integrates to the variance (bins other than DC and Nyquist
/// doubled). FFTs by FFTW3 (real-to-complex, FFTW_ESTIMATE plans: the same bytes every run).

#include <cstddef>
#include <vector>

namespace hil::harness {

struct Psd {
  std::vector<double> freq_hz;  ///< segment/2 + 1 bins from 0 to the Nyquist frequency
  std::vector<double> density;  ///< unit²/Hz, one-sided
  std::size_t segments = 0;
};

/// The default segment length: the largest power of two <= samples / 8, within [16, 4096].
std::size_t DefaultWelchSegment(std::size_t samples);

/// @throws std::invalid_argument for segment < 4, an odd segment, or fewer samples than one
/// segment.
Psd WelchPsd(const std::vector<double>& y, double sample_rate_hz, std::size_t segment);

}  // namespace hil::harness

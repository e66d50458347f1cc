#include "hil/harness/characterize/welch_psd.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fftw3.h>

namespace hil::harness {
namespace {

// one FFTW real-to-complex plan and its buffers, freed on every path out
class R2cPlan {
 public:
  explicit R2cPlan(std::size_t n)
      : n_(n),
        in_(fftw_alloc_real(n)),
        out_(fftw_alloc_complex(n / 2 + 1)),
        plan_(fftw_plan_dft_r2c_1d(static_cast<int>(n), in_, out_, FFTW_ESTIMATE)) {
    if (!in_ || !out_ || !plan_) throw std::runtime_error("FFTW: cannot make a plan");
  }
  ~R2cPlan() {
    if (plan_) fftw_destroy_plan(plan_);
    fftw_free(in_);
    fftw_free(out_);
  }
  R2cPlan(const R2cPlan&) = delete;
  R2cPlan& operator=(const R2cPlan&) = delete;

  double* in() { return in_; }
  double Power(std::size_t k) const { return out_[k][0] * out_[k][0] + out_[k][1] * out_[k][1]; }
  void Execute() { fftw_execute(plan_); }
  std::size_t size() const { return n_; }

 private:
  std::size_t n_;
  double* in_;
  fftw_complex* out_;
  fftw_plan plan_;
};

}  // namespace

std::size_t DefaultWelchSegment(std::size_t samples) {
  std::size_t s = 16;
  while (2 * s <= samples / 8 && 2 * s <= 4096) s *= 2;
  return s;
}

Psd WelchPsd(const std::vector<double>& y, double sample_rate_hz, std::size_t segment) {
  if (segment < 4 || segment % 2 != 0 || y.size() < segment)
    throw std::invalid_argument("Welch: segment must be even, >= 4 and no longer than the data");
  std::vector<double> w(segment);
  double w2 = 0;
  for (std::size_t i = 0; i < segment; ++i) {  // periodic Hann
    w[i] = 0.5 - 0.5 * std::cos(2 * std::numbers::pi * static_cast<double>(i) /
                                static_cast<double>(segment));
    w2 += w[i] * w[i];
  }
  R2cPlan fft(segment);
  Psd p;
  const std::size_t bins = segment / 2 + 1, hop = segment / 2;
  p.density.assign(bins, 0.0);
  for (std::size_t start = 0; start + segment <= y.size(); start += hop) {
    double mean = 0;
    for (std::size_t i = 0; i < segment; ++i) mean += y[start + i];
    mean /= static_cast<double>(segment);
    for (std::size_t i = 0; i < segment; ++i) fft.in()[i] = (y[start + i] - mean) * w[i];
    fft.Execute();
    for (std::size_t k = 0; k < bins; ++k) p.density[k] += fft.Power(k);
    ++p.segments;
  }
  const double scale = 1.0 / (sample_rate_hz * w2 * static_cast<double>(p.segments));
  for (std::size_t k = 0; k < bins; ++k) {
    const bool edge = k == 0 || k == bins - 1;
    p.density[k] *= scale * (edge ? 1.0 : 2.0);
    p.freq_hz.push_back(static_cast<double>(k) * sample_rate_hz / static_cast<double>(segment));
  }
  return p;
}

}  // namespace hil::harness

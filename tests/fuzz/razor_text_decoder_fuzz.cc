// Fuzz target: navd's decoder of the Razor v13 stock text lines survives any byte stream in any
// split. Oracles: each emitted sample is in its fields' ranges, printing it back in its format and
// parsing again gives the same sample, and the counters agree with what was emitted.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "hil/estimator/drivers/razor_text_decoder.h"

namespace {

using hil::estimator::drivers::RazorTextDecoder;
using hil::estimator::drivers::RazorTextSample;

std::string Print(const RazorTextSample& s) {
  std::string out = s.format == RazorTextSample::Format::kRaw ? "$," : "!Data:";
  const std::array<int, 3>* groups[3] = {&s.accel_counts, &s.gyro_adc, &s.mag_counts};
  for (int g = 0; g < 3; ++g) {
    for (int k = 0; k < 3; ++k) {
      out += std::to_string((*groups[g])[static_cast<std::size_t>(k)]);
      if (g < 2 || k < 2) out += ',';
    }
  }
  out += s.format == RazorTextSample::Format::kRaw ? ",#" : "#";
  return out;
}

bool InRange(const std::array<int, 3>& v, int lo, int hi) {
  for (int x : v) {
    if (x < lo || x > hi) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::uint64_t emitted = 0;
  RazorTextDecoder dec([&](const RazorTextSample& s) {
    ++emitted;
    if (!InRange(s.accel_counts, -512, 511) || !InRange(s.gyro_adc, 0, 1023) ||
        !InRange(s.mag_counts, -4096, 2047))
      std::abort();
    RazorTextSample again;
    if (!RazorTextDecoder::ParseLine(Print(s), again)) std::abort();
    if (again.format != s.format || again.accel_counts != s.accel_counts ||
        again.gyro_adc != s.gyro_adc || again.mag_counts != s.mag_counts)
      std::abort();
  });
  const std::size_t chunk = size > 0 ? 1 + data[0] % 64 : 1;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  for (std::size_t i = 0; i < all.size(); i += chunk) dec.Feed(all.substr(i, chunk));
  if (dec.stats().lines_ok != emitted) std::abort();
  if (dec.stats().lines_ok + dec.stats().bad_lines + dec.stats().garbage_bytes > size + 1)
    std::abort();
  return 0;
}

// The line rate of a capture: which baud a stream is judged at, and bytes closer together than
// that rate carries them.
#include <cstdio>
#include <stdexcept>
#include <string>

#include "hil/harness/validate/validate.h"

namespace hil::harness {

int ValidationBaud(const ByteStream& stream, int baud, bool baud_given) {
  if (stream.line_baud <= 0) return baud;
  if (baud_given && baud != stream.line_baud) {
    throw std::invalid_argument("the capture records " + std::to_string(stream.line_baud) +
                                " baud (its '# link' header), --baud says " + std::to_string(baud));
  }
  return stream.line_baud;
}

void CheckLineRate(const ByteStream& stream, ValidationReport& report) {
  if (stream.line_baud <= 0 || stream.t_ns.size() != stream.bytes.size()) return;
  const double char_ns = LineCharacterNs(stream.line_baud);
  const double min_ns = char_ns * (1.0 - kLineRateTolerance);
  std::size_t too_close = 0, first = 0;
  std::int64_t shortest_ns = 0;
  for (std::size_t i = 1; i < stream.t_ns.size(); ++i) {
    const std::int64_t gap_ns = stream.t_ns[i] - stream.t_ns[i - 1];
    if (static_cast<double>(gap_ns) >= min_ns) continue;
    if (too_close == 0 || gap_ns < shortest_ns) shortest_ns = gap_ns;
    if (too_close++ == 0) first = i;
  }
  if (too_close == 0) return;
  char msg[256];
  std::snprintf(msg, sizeof msg,
                "%zu byte(s) start less than a character time after the byte before "
                "(%.1f us: 10 bits at %d baud, 8N1); they could not have crossed the line "
                "(first at byte %zu, shortest spacing %.1f us)",
                too_close, char_ns * 1e-3, stream.line_baud, first,
                static_cast<double>(shortest_ns) * 1e-3);
  report.findings.push_back({true, "line_rate", msg, static_cast<std::int64_t>(first)});
}

}  // namespace hil::harness

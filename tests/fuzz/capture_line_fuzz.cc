// Fuzz target: the capture-file line parser (hil replay, hil validate) accepts a line or returns
// nothing; an accepted record formats back to a line that parses to the same record.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hil/harness/links/capture_format.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  if (const auto r = hil::harness::ParseCaptureLine(line)) {
    const auto again = hil::harness::ParseCaptureLine(hil::harness::FormatCaptureLine(*r));
    if (!again || !(*again == *r)) std::abort();
  }
  return 0;
}

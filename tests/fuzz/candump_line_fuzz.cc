// Fuzz target: the candump -l line reader (hil replay, validate --protocol can) accepts a line or
// returns nothing; a line it accepts is written back and parses to the same frame.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hil/firmware_emu/link/candump_log.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view line(reinterpret_cast<const char*>(data), size);
  if (const auto f = hil::link::ParseCanFrameText(line)) {
    const auto again = hil::link::ParseCanFrameText(hil::link::FormatCanFrameText(*f));
    if (!again || !(*again == *f)) std::abort();
  }
  (void)hil::link::ParseCandumpLine(line);
  return 0;
}

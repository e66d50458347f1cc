#include "hil/firmware_emu/mcu/razor_text.h"

namespace hil::mcu {

std::string EncodeRazorLine(RazorTextFormat format, const std::array<int, 3>& accel,
                            const std::array<int, 3>& gyro_adc, const std::array<int, 3>& mag) {
  std::string fields;
  bool first = true;
  for (const auto* triad : {&accel, &gyro_adc, &mag}) {
    for (int v : *triad) {
      if (!first) fields += ',';
      fields += std::to_string(v);
      first = false;
    }
  }
  if (format == RazorTextFormat::kRaw) return "$," + fields + ",#\r\n";
  return "!Data:" + fields + "#\n\r";
}

}  // namespace hil::mcu

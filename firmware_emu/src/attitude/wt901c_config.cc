#include "hil/firmware_emu/attitude/wt901c_config.h"

namespace hil::wit {

double RateHzOfCode(std::uint16_t rrate_code) {
  switch (rrate_code) {
    case 0x01:
      return 0.2;
    case 0x02:
      return 0.5;
    case 0x03:
      return 1.0;
    case 0x04:
      return 2.0;
    case 0x05:
      return 5.0;
    case 0x06:
      return 10.0;
    case 0x07:
      return 20.0;
    case 0x08:
      return 50.0;
    case 0x09:
      return 100.0;
    case 0x0B:
      return 200.0;  // 0x0A (125 Hz) exists on the WT931 only
    default:
      return 0.0;
  }
}

int BaudOfCode(std::uint16_t baud_code) {
  static constexpr int kBauds[] = {4800, 9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600};
  if (baud_code < 1 || baud_code > 9) return 0;
  return kBauds[baud_code - 1];
}

}  // namespace hil::wit

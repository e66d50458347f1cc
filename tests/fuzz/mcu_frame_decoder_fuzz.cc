// Fuzz target: navd's decoder of the microcontroller's binary frames (and the adapter that turns
// them into IMU samples on GPS time) survive any byte stream in any split.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hil::estimator::drivers;
  McuImuAdapter adapter;
  McuFrameDecoder decoder([&](const McuFrame& f) { (void)adapter.Add(f); });
  const std::size_t chunk = size > 0 ? 1 + data[0] % 64 : 1;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  for (std::size_t i = 0; i < all.size(); i += chunk) decoder.Feed(all.substr(i, chunk));
  return 0;
}

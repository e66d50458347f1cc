// Fuzz target: navd's UBX decoder and epoch joiner survive any byte stream in any split.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "hil/estimator/drivers/ubx_decoder.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hil::estimator::drivers;
  UbxEpochAssembler epochs;
  UbxDecoder decoder([&](const UbxMessage& m) { (void)epochs.Add(m); });
  const std::size_t chunk = size > 0 ? 1 + data[0] % 64 : 1;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  for (std::size_t i = 0; i < all.size(); i += chunk) decoder.Feed(all.substr(i, chunk));
  return 0;
}

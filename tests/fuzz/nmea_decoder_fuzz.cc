// Fuzz target: navd's tolerant NMEA decoder and epoch joiner must survive any byte stream,
// in any split, and never produce a solution with impossible values.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/nmea_epoch.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace hil::estimator::drivers;
  NmeaEpochAssembler epochs;
  NmeaDecoder decoder([&](const NmeaFix& fix) {
    if (fix.lat_deg &&
        (std::fabs(*fix.lat_deg) > 90.0 + 1.0 / 60.0 || !std::isfinite(*fix.lat_deg)))
      std::abort();
    if (fix.lon_deg && (std::fabs(*fix.lon_deg) > 181.0 || !std::isfinite(*fix.lon_deg)))
      std::abort();
    (void)epochs.Add(fix);
  });
  // the first byte chooses the read size, so split reads are explored too
  const std::size_t chunk = size > 0 ? 1 + data[0] % 64 : 1;
  const std::string_view all(reinterpret_cast<const char*>(data), size);
  for (std::size_t i = 0; i < all.size(); i += chunk) decoder.Feed(all.substr(i, chunk));
  return 0;
}

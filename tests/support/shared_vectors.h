#pragma once
// The project's shared reference data beside the checkout: gpsd's real u-blox 5 logs in
// $HIL_SOURCE_DIR/../shared/vectors/gpsd-ublox5, read in place. A clone has no ../shared beside
// it, so every test that reads them starts with HIL_SKIP_WITHOUT_GPSD_VECTORS(): skipped, with
// the folder it looked for, instead of failing.
#include <cstdlib>
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

namespace hil::test {

/// The folder of gpsd's u-blox 5 logs (it may not exist).
inline std::string GpsdVectorsDir() {
  const char* src = std::getenv("HIL_SOURCE_DIR");
  return std::string(src ? src : ".") + "/../shared/vectors/gpsd-ublox5";
}

/// One of gpsd's u-blox 5 logs by name.
inline std::string GpsdVector(const std::string& name) { return GpsdVectorsDir() + "/" + name; }

/// Whether the logs are there (the folder holds the log every user of it reads).
inline bool GpsdVectorsPresent() {
  std::error_code ec;
  return std::filesystem::is_regular_file(GpsdVector("nl551e.log"), ec);
}

}  // namespace hil::test

/// Skips the calling test when the shared gpsd vectors are absent (a clone without ../shared).
#define HIL_SKIP_WITHOUT_GPSD_VECTORS()                                                    \
  do {                                                                                     \
    if (!::hil::test::GpsdVectorsPresent())                                                \
      GTEST_SKIP() << "gpsd's u-blox 5 logs are absent (" << ::hil::test::GpsdVectorsDir() \
                   << "): this test reads them";                                           \
  } while (false)

// Fuzz target: navd's configuration loader either accepts a file or rejects it with a ConfigError;
// nothing else may escape.
#include <cstddef>
#include <cstdint>
#include <string>

#include "hil/estimator/navd/config_file.h"
#include "hil/estimator/navd/navd_config.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    (void)hil::estimator::NavdConfig::FromFile(
        hil::estimator::ConfigFile::Parse(text, "fuzz.conf"));
  } catch (const hil::estimator::ConfigError&) {
  }
  return 0;
}

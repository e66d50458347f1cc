#pragma once
// navd.conf text for the configuration tests: the loaded configuration, or the error it gives.
#include <string>

#include "hil/estimator/navd/navd_config.h"

namespace hil::estimator::test {

inline NavdConfig Load(const std::string& text) {
  return NavdConfig::FromFile(ConfigFile::Parse(text, "n.conf"));
}

/// The ConfigError's message, or "no error" when the text loads.
inline std::string Error(const std::string& text) {
  try {
    Load(text);
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace hil::estimator::test

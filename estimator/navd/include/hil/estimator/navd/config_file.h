#pragma once
/// @file
/// navd's configuration file: an INI-style text file, `[section]` headers and `key = value`
/// lines, `#` comments. Parsing is separate from validation: ConfigFile holds every entry with its
/// line; NavdConfig (navd_config.h) checks keys and types against its schema. Errors name the file,
/// the line and the key. (The estimator depends on Eigen only, hence no YAML library here.)

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace hil::estimator {

/// A configuration error: "FILE:LINE: [section] key: message".
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& file, int line, const std::string& field,
              const std::string& message);
};

/// One `key = value` line.
struct ConfigEntry {
  std::string section, key, value;
  int line = 0;
};

/// How errors name an entry's field: `[section] key`.
std::string FieldName(const ConfigEntry& e);

/// The parsed text of a configuration file, in file order.
class ConfigFile {
 public:
  /// Reads and parses a file. @throws ConfigError on an unreadable file or a malformed line.
  static ConfigFile Load(const std::string& path);
  /// Parses text; `name` is used in error messages.
  static ConfigFile Parse(const std::string& text, const std::string& name);

  const std::vector<ConfigEntry>& entries() const { return entries_; }
  const std::string& name() const { return name_; }

 private:
  std::string name_;
  std::vector<ConfigEntry> entries_;
};

/// Throws the ConfigError of entry `e` of file `f` with message `m`.
[[noreturn]] void FailAt(const ConfigFile& f, const ConfigEntry& e, const std::string& m);

}  // namespace hil::estimator

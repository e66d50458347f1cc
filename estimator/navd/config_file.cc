#include "hil/estimator/navd/config_file.h"

#include <fstream>
#include <sstream>

namespace hil::estimator {
namespace {

std::string Trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

}  // namespace

ConfigError::ConfigError(const std::string& file, int line, const std::string& field,
                         const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": " +
                         (field.empty() ? "" : field + ": ") + message) {}

ConfigFile ConfigFile::Load(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError(path, 0, "", "cannot read the configuration file");
  std::stringstream ss;
  ss << in.rdbuf();
  return Parse(ss.str(), path);
}

ConfigFile ConfigFile::Parse(const std::string& text, const std::string& name) {
  ConfigFile cf;
  cf.name_ = name;
  std::istringstream in(text);
  std::string raw, section;
  int line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    const auto hash = raw.find('#');
    const std::string line = Trim(hash == std::string::npos ? raw : raw.substr(0, hash));
    if (line.empty()) continue;
    if (line.front() == '[') {
      if (line.back() != ']' || line.size() < 3)
        throw ConfigError(name, line_no, "", "malformed section header '" + line + "'");
      section = Trim(line.substr(1, line.size() - 2));
      continue;
    }
    const auto eq = line.find('=');
    if (eq == std::string::npos)
      throw ConfigError(name, line_no, "", "expected 'key = value', got '" + line + "'");
    ConfigEntry e{section, Trim(line.substr(0, eq)), Trim(line.substr(eq + 1)), line_no};
    if (e.key.empty()) throw ConfigError(name, line_no, "", "empty key");
    cf.entries_.push_back(std::move(e));
  }
  return cf;
}

std::string FieldName(const ConfigEntry& e) { return "[" + e.section + "] " + e.key; }

void FailAt(const ConfigFile& f, const ConfigEntry& e, const std::string& m) {
  throw ConfigError(f.name(), e.line, FieldName(e), m);
}

}  // namespace hil::estimator

#include "hil/harness/scenario/yaml_text_checks.h"

#include <cstdio>
#include <map>

#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

std::optional<TextProblem> FirstNonText(const std::string& text) {
  int line = 1, column = 1;
  for (std::size_t i = 0; i < text.size(); ++column) {
    const auto c = static_cast<unsigned char>(text[i]);
    std::size_t len = c < 0x80             ? 1
                      : (c & 0xE0) == 0xC0 ? 2
                      : (c & 0xF0) == 0xE0 ? 3
                      : (c & 0xF8) == 0xF0 ? 4
                                           : 0;
    bool ok = len > 0 && (c >= 0x20 || c == '\t' || c == '\n' || c == '\r') && c != 0x7F &&
              i + len <= text.size() && !(len == 2 && c < 0xC2);
    for (std::size_t k = 1; ok && k < len; ++k)
      ok = (static_cast<unsigned char>(text[i + k]) & 0xC0) == 0x80;
    if (!ok) {
      char hex[8];
      std::snprintf(hex, sizeof hex, "0x%02X", c);
      return TextProblem{line, "column " + std::to_string(column) + ": byte " + hex +
                                   " is not text (a scenario is a UTF-8 YAML text file; is this a "
                                   "binary file?)"};
    }
    if (c == '\n') ++line, column = 0;
    i += len;
  }
  return std::nullopt;
}

std::optional<TextProblem> FirstTabIndent(const std::string& text) {
  int line = 1;
  bool at_indent = true;
  for (const char c : text) {
    if (c == '\n') {
      ++line;
      at_indent = true;
    } else if (at_indent && c == '\t') {
      return TextProblem{line,
                         "a tab in the indentation (YAML indents with spaces only; replace the "
                         "tab with spaces)"};
    } else if (c != ' ') {
      at_indent = false;
    }
  }
  return std::nullopt;
}

void CheckNoDuplicateKeys(const YAML::Node& node, const std::string& file,
                          const std::string& path) {
  if (node.IsSequence()) {
    std::size_t i = 0;
    for (const auto& el : node)
      CheckNoDuplicateKeys(el, file, path + "[" + std::to_string(i++) + "]");
    return;
  }
  if (!node.IsMap()) return;
  std::map<std::string, int> seen;  // key -> its line
  for (const auto& kv : node) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
    const std::string field = path.empty() ? key : path + "." + key;
    const int line = kv.first.Mark().line + 1;
    if (kv.first.IsScalar()) {
      const auto [it, fresh] = seen.emplace(key, line);
      if (!fresh) {
        throw ScenarioError(file, line, IsPlainKey(key) ? field : path,
                            "duplicate key: already given on line " + std::to_string(it->second) +
                                " (a key may appear once in a mapping; remove one of them)");
      }
    }
    CheckNoDuplicateKeys(kv.second, file, IsPlainKey(key) ? field : path);
  }
}

bool IsPlainKey(const std::string& key) {
  if (key.empty() || key.size() > 64) return false;
  for (const char c : key) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                    c == '_' || c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace hil::harness

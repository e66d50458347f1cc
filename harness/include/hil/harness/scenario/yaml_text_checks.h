#pragma once
/// @file
/// Checks of a YAML document's text and tree that yaml-cpp does not make: bytes that are not
/// text, a tab in the indentation, duplicate keys, and keys that are not plain names.

#include <optional>
#include <string>

#include <yaml-cpp/yaml.h>

namespace hil::harness {

struct TextProblem {
  int line = 0;  ///< 1-based
  std::string message;
};

/// The first byte that cannot be in a YAML text file (a control character other than tab and
/// line ends, or invalid UTF-8), named by its line, column and value.
std::optional<TextProblem> FirstNonText(const std::string& text);

/// The first line whose indentation holds a tab (YAML indents with spaces only). Only asked
/// after yaml-cpp refused the text: a tab after the indentation (in a block scalar) is legal.
std::optional<TextProblem> FirstTabIndent(const std::string& text);

/// @throws ScenarioError at the second of two equal keys of one mapping, at any depth, naming
/// the line of the first (yaml-cpp keeps both, and the first would silently win).
void CheckNoDuplicateKeys(const YAML::Node& node, const std::string& file, const std::string& path);

/// True for a key hil can name in a message: letters, digits, '_', '-' and '.', at most 64.
/// Anything else (a line of some other file read as a key) is never echoed.
bool IsPlainKey(const std::string& key);

}  // namespace hil::harness

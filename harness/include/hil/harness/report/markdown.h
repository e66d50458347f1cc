#pragma once
/// @file
/// Text helpers for the Markdown reports (suite and campaign).

#include <string>

namespace hil::harness {

/// A Markdown table cell: pipes become '/', newlines spaces.
inline std::string MarkdownCell(std::string s) {
  for (char& c : s) {
    if (c == '|') c = '/';
    if (c == '\n') c = ' ';
  }
  return s;
}

}  // namespace hil::harness

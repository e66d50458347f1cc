#include "hil/harness/dut/shell_substitute.h"

#include <cstring>

namespace hil::harness {
namespace {

enum class ShellQuoting { kNone, kSingle, kDouble };

bool PlainShellWord(const std::string& v) {
  if (v.empty()) return false;
  for (const char c : v) {
    const bool alnum = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9');
    if (!alnum && std::strchr("_@%+=:,./-", c) == nullptr) return false;
  }
  return true;
}

// Text of a single-quoted string: each ' closes the string, adds an escaped quote, reopens it.
std::string InsideSingleQuotes(const std::string& v) {
  std::string out;
  for (const char c : v) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out;
}

std::string InsideDoubleQuotes(const std::string& v) {
  std::string out;
  for (const char c : v) {
    if (c == '\\' || c == '$' || c == '`' || c == '"') out += '\\';
    out += c;
  }
  return out;
}

std::string QuotedForPlace(ShellQuoting q, const std::string& value) {
  switch (q) {
    case ShellQuoting::kNone:
      return ShellWord(value);
    case ShellQuoting::kSingle:
      return InsideSingleQuotes(ShellWord(value));
    case ShellQuoting::kDouble:
      return InsideDoubleQuotes(value);
  }
  return value;
}

const std::string* LookupVar(const std::vector<std::pair<std::string, std::string>>& vars,
                             const std::string& key) {
  for (const auto& [k, v] : vars) {
    if (k == key) return &v;
  }
  return nullptr;
}

// The quoting in force after character `c` of shell text (POSIX sh: no escape inside '...').
ShellQuoting QuotingAfter(ShellQuoting q, char c, bool& escaped) {
  if (escaped) {
    escaped = false;
    return q;
  }
  if (c == '\\' && q != ShellQuoting::kSingle) {
    escaped = true;
    return q;
  }
  if (c == '\'' && q != ShellQuoting::kDouble)
    return q == ShellQuoting::kSingle ? ShellQuoting::kNone : ShellQuoting::kSingle;
  if (c == '"' && q != ShellQuoting::kSingle)
    return q == ShellQuoting::kDouble ? ShellQuoting::kNone : ShellQuoting::kDouble;
  return q;
}

}  // namespace

std::string ShellWord(const std::string& value) {
  if (PlainShellWord(value)) return value;
  return "'" + InsideSingleQuotes(value) + "'";
}

std::string Substitute(const std::string& text,
                       const std::vector<std::pair<std::string, std::string>>& vars) {
  std::string out;
  ShellQuoting q = ShellQuoting::kNone;
  bool escaped = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '{' && !escaped) {
      const std::size_t close = text.find('}', i + 1);
      if (close != std::string::npos) {
        if (const std::string* v = LookupVar(vars, text.substr(i + 1, close - i - 1))) {
          out += QuotedForPlace(q, *v);
          i = close;
          continue;
        }
      }
    }
    out += text[i];
    q = QuotingAfter(q, text[i], escaped);
  }
  return out;
}

}  // namespace hil::harness

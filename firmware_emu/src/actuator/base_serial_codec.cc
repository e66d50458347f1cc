#include "hil/firmware_emu/actuator/base_serial_codec.h"

#include <algorithm>
#include <vector>

namespace hil::actuator {
namespace {

// atoi semantics: skip leading blanks, optional sign, digits; stops at the first other character.
long AtoiLike(std::string_view s) {
  std::size_t i = 0;
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  bool negative = false;
  if (i < s.size() && (s[i] == '-' || s[i] == '+')) negative = s[i++] == '-';
  long v = 0;
  for (; i < s.size() && s[i] >= '0' && s[i] <= '9'; ++i) v = v * 10 + (s[i] - '0');
  return negative ? -v : v;
}

std::vector<std::string_view> Split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i) {
    if (i == s.size() || s[i] == sep) {
      if (i > start) out.push_back(s.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

}  // namespace

BaseCommand ParseBaseCommand(std::string_view line) {
  BaseCommand c;
  const std::vector<std::string_view> tok = Split(line, ' ');
  if (tok.empty()) return c;
  switch (tok[0].back()) {  // the firmware keeps the last character before the first space
    case 'b':
      c.kind = BaseCommandKind::kGetBaud;
      break;
    case 'e':
      c.kind = BaseCommandKind::kReadEncoders;
      break;
    case 'r':
      c.kind = BaseCommandKind::kResetEncoders;
      break;
    case 'm':
      c.kind = BaseCommandKind::kMotorSpeeds;
      for (std::size_t i = 1; i < tok.size() && i <= 2; ++i) c.args[i - 1] = AtoiLike(tok[i]);
      c.arg_count = static_cast<int>(std::min<std::size_t>(tok.size() - 1, 2));
      break;
    case 'u': {
      c.kind = BaseCommandKind::kUpdatePid;
      if (tok.size() < 2) break;
      const std::vector<std::string_view> gains = Split(tok[1], ':');
      for (std::size_t i = 0; i < gains.size() && i < 4; ++i) c.args[i] = AtoiLike(gains[i]);
      c.arg_count = static_cast<int>(std::min<std::size_t>(gains.size(), 4));
      break;
    }
    default:
      break;
  }
  return c;
}

std::string FormatBaseOk() { return "OK\r\n"; }
std::string FormatBaseInvalid() { return "Invalid Command\r\n"; }
std::string FormatBaseBaud(long baud) { return std::to_string(baud) + "\r\n"; }
std::string FormatBaseEncoders(std::int32_t left, std::int32_t right) {
  return std::to_string(left) + " " + std::to_string(right) + "\r\n";
}

}  // namespace hil::actuator

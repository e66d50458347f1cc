#include "hil/harness/core/json_solution_line.h"

#include <array>
#include <charconv>

namespace hil::harness {
namespace {

/// A read position in one line. Every method returns false for what the scanner does not answer
/// (the line then goes to the DOM): it never guesses.
struct Cursor {
  const char* p;
  const char* end;

  void Ws() {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
  }
  /// After white space, the character `c`, taken.
  bool Eat(char c) {
    Ws();
    if (p == end || *p != c) return false;
    ++p;
    return true;
  }
  /// After white space, what comes next (0 at the end).
  char Peek() {
    Ws();
    return p == end ? '\0' : *p;
  }
  bool String(std::string_view& out);
  bool Number(std::optional<double>& value, std::optional<std::int64_t>& integer);
  bool Literal(std::string_view word);
  bool Skip(int depth);
  bool SkipMembers(char close, int depth);
};

bool IsDigit(char c) { return c >= '0' && c <= '9'; }

// A string of printable ASCII without escapes (a backslash, a control character or a byte of a
// multi-byte UTF-8 sequence: the DOM decodes and validates those).
bool Cursor::String(std::string_view& out) {
  if (!Eat('"')) return false;
  const char* start = p;
  for (; p < end; ++p) {
    const auto c = static_cast<unsigned char>(*p);
    if (c == '"') {
      out = std::string_view(start, static_cast<std::size_t>(p - start));
      ++p;
      return true;
    }
    if (c < 0x20 || c >= 0x80 || c == '\\') return false;
  }
  return false;
}

// A JSON number: an integer that fits int64 (nlohmann's integer, exact), or a number with a
// fraction or exponent (its double, correctly rounded as strtod gives it).
bool Cursor::Number(std::optional<double>& value, std::optional<std::int64_t>& integer) {
  Ws();
  const char* start = p;
  if (p < end && *p == '-') ++p;
  const char* digits = p;
  if (p == end || !IsDigit(*p)) return false;
  if (*p == '0') {
    ++p;
  } else {
    while (p < end && IsDigit(*p)) ++p;
  }
  const std::ptrdiff_t int_digits = p - digits;
  bool is_integer = true;
  if (p < end && *p == '.') {
    const char* f = ++p;
    while (p < end && IsDigit(*p)) ++p;
    if (p == f) return false;
    is_integer = false;
  }
  if (p < end && (*p == 'e' || *p == 'E')) {
    ++p;
    if (p < end && (*p == '+' || *p == '-')) ++p;
    const char* e = p;
    while (p < end && IsDigit(*p)) ++p;
    if (p == e) return false;
    is_integer = false;
  }
  if (is_integer) {
    if (int_digits > 19) return false;
    std::int64_t v = 0;
    const auto r = std::from_chars(start, p, v);
    if (r.ec != std::errc() || r.ptr != p) return false;  // beyond int64: the DOM's unsigned
    integer = v;
    value = static_cast<double>(v);
    return true;
  }
  double d = 0;
  const auto r = std::from_chars(start, p, d);
  if (r.ec != std::errc() || r.ptr != p) return false;
  value = d;
  return true;
}

bool Cursor::Literal(std::string_view word) {
  if (static_cast<std::size_t>(end - p) < word.size() || std::string_view(p, word.size()) != word)
    return false;
  p += word.size();
  return true;
}

// Members of an object (close '}') or elements of an array (close ']'), the opening taken.
bool Cursor::SkipMembers(char close, int depth) {
  if (Eat(close)) return true;
  for (;;) {
    std::string_view key;
    if (close == '}' && (!String(key) || !Eat(':'))) return false;
    if (!Skip(depth)) return false;
    if (Eat(',')) continue;
    return Eat(close);
  }
}

// Any value, checked and passed over.
bool Cursor::Skip(int depth) {
  if (depth > JsonSolutionScanner::kMaxDepth) return false;
  std::string_view s;
  std::optional<double> d;
  std::optional<std::int64_t> i;
  switch (Peek()) {
    case '"':
      return String(s);
    case '{':
      ++p;
      return SkipMembers('}', depth + 1);
    case '[':
      ++p;
      return SkipMembers(']', depth + 1);
    case 't':
      return Literal("true");
    case 'f':
      return Literal("false");
    case 'n':
      return Literal("null");
    default:
      return Number(d, i);
  }
}

bool StartsNumber(char c) { return c == '-' || IsDigit(c); }

// A member the readers take as a number (anything else is passed over).
bool NumberMember(Cursor& c, std::optional<double>& value,
                  std::optional<std::int64_t>* integer = nullptr) {
  if (!StartsNumber(c.Peek())) return c.Skip(1);
  std::optional<std::int64_t> i;
  if (!c.Number(value, i)) return false;
  if (integer) *integer = i;
  return true;
}

// A member the readers take as an array of exactly three numbers.
bool Vec3Member(Cursor& c, std::optional<Eigen::Vector3d>& out) {
  if (c.Peek() != '[') return c.Skip(1);
  ++c.p;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  std::size_t n = 0;
  bool numbers = true;
  if (!c.Eat(']')) {
    for (;;) {
      std::optional<double> d;
      std::optional<std::int64_t> i;
      if (StartsNumber(c.Peek())) {
        if (!c.Number(d, i)) return false;
        if (n < 3) v[static_cast<Eigen::Index>(n)] = *d;
      } else {
        if (!c.Skip(2)) return false;
        numbers = false;
      }
      ++n;
      if (c.Eat(',')) continue;
      if (!c.Eat(']')) return false;
      break;
    }
  }
  if (numbers && n == 3) out = v;
  return true;
}

// The strings of the health object's `flags` array (other elements passed over).
bool FlagsMember(Cursor& c, std::vector<std::string>& flags) {
  ++c.p;  // '['
  if (c.Eat(']')) return true;
  for (;;) {
    if (c.Peek() == '"') {
      std::string_view s;
      if (!c.String(s)) return false;
      flags.emplace_back(s);
    } else if (!c.Skip(2)) {
      return false;
    }
    if (c.Eat(',')) continue;
    return c.Eat(']');
  }
}

/// The health object as scanned: its keys (views into the line) and numbers.
struct HealthScan {
  std::array<std::string_view, JsonSolutionScanner::kMaxHealthKeys> keys;
  std::size_t n = 0;
  std::vector<std::optional<double>> values;
  std::vector<std::string> flags;
};

// The members of `health`, the '{' next.
bool HealthMembers(Cursor& c, HealthScan& h) {
  ++c.p;  // '{'
  if (c.Eat('}')) return true;
  for (;;) {
    std::string_view key;
    if (h.n == h.keys.size() || !c.String(key) || !c.Eat(':')) return false;
    h.keys[h.n++] = key;
    std::optional<double> value;
    if (StartsNumber(c.Peek())) {
      std::optional<std::int64_t> i;
      if (!c.Number(value, i)) return false;
    } else if (key == "flags" && c.Peek() == '[') {
      if (!FlagsMember(c, h.flags)) return false;
    } else if (!c.Skip(2)) {
      return false;
    }
    h.values.push_back(value);
    if (c.Eat(',')) continue;
    return c.Eat('}');
  }
}

enum Member : int {
  kTovUnixNs,
  kTovUtcS,
  kLatDeg,
  kLonDeg,
  kHeightM,
  kYawDeg,
  kVelEnu,
  kPosStdEnu,
  kHealth,
  kOther
};

Member MemberOf(std::string_view key) {
  static constexpr std::array<std::string_view, kOther> kKeys = {
      "tov_unix_ns", "tov_utc_s",   "lat_deg",       "lon_deg", "height_m",
      "yaw_deg",     "vel_enu_mps", "pos_std_enu_m", "health"};
  for (int k = 0; k < kOther; ++k) {
    if (kKeys[static_cast<std::size_t>(k)] == key) return static_cast<Member>(k);
  }
  return kOther;
}

// The members read as numbers, kTovUtcS to kYawDeg in order.
constexpr std::array<std::optional<double> JsonSolutionLine::*, kYawDeg - kTovUtcS + 1> kNumbers = {
    &JsonSolutionLine::tov_utc_s, &JsonSolutionLine::lat_deg, &JsonSolutionLine::lon_deg,
    &JsonSolutionLine::height_m, &JsonSolutionLine::yaw_deg};

bool ReadMember(Cursor& c, Member m, JsonSolutionLine& out, HealthScan& health) {
  if (m >= kTovUtcS && m <= kYawDeg)
    return NumberMember(c, out.*kNumbers[static_cast<std::size_t>(m - kTovUtcS)]);
  switch (m) {
    case kTovUnixNs: {
      std::optional<double> unused;
      return NumberMember(c, unused, &out.tov_unix_ns);
    }
    case kVelEnu:
      return Vec3Member(c, out.vel_enu_mps);
    case kPosStdEnu:
      return Vec3Member(c, out.pos_std_enu_m);
    case kHealth:
      if (c.Peek() != '{') return c.Skip(1);
      out.health = true;
      return HealthMembers(c, health);
    default:
      return c.Skip(1);
  }
}

// Whether the object's members are all read (the '{' taken) with no key the readers use twice.
bool TopMembers(Cursor& c, JsonSolutionLine& out, HealthScan& health) {
  if (c.Eat('}')) return true;
  unsigned seen = 0;
  for (;;) {
    std::string_view key;
    if (!c.String(key) || !c.Eat(':')) return false;
    const Member m = MemberOf(key);
    if (m != kOther) {
      const unsigned bit = 1u << static_cast<unsigned>(m);
      if (seen & bit) return false;  // the DOM keeps the last; the readers then see that one
      seen |= bit;
    }
    if (!ReadMember(c, m, out, health)) return false;
    if (c.Eat(',')) continue;
    return c.Eat('}');
  }
}

bool SameKeys(const std::vector<std::string>* layout, const HealthScan& h) {
  if (!layout || layout->size() != h.n) return false;
  for (std::size_t i = 0; i < h.n; ++i) {
    if ((*layout)[i] != h.keys[i]) return false;
  }
  return true;
}

bool HasDuplicateKey(const HealthScan& h) {
  for (std::size_t i = 0; i < h.n; ++i) {
    for (std::size_t j = i + 1; j < h.n; ++j) {
      if (h.keys[i] == h.keys[j]) return true;
    }
  }
  return false;
}

}  // namespace

std::optional<JsonSolutionLine> JsonSolutionScanner::Scan(std::string_view text) {
  Cursor c{text.data(), text.data() + text.size()};
  JsonSolutionLine out;
  HealthScan health;
  health.values.reserve(layout_ ? layout_->size() : 32);
  if (!c.Eat('{') || !TopMembers(c, out, health)) return std::nullopt;
  c.Ws();
  if (c.p != c.end) return std::nullopt;
  if (!out.health) return out;
  if (!SameKeys(layout_.get(), health)) {
    if (HasDuplicateKey(health)) return std::nullopt;
    layout_ = std::make_shared<const std::vector<std::string>>(
        health.keys.begin(), health.keys.begin() + static_cast<std::ptrdiff_t>(health.n));
  }
  out.health_keys = layout_;
  out.health_values = std::move(health.values);
  out.health_flags = std::move(health.flags);
  return out;
}

}  // namespace hil::harness

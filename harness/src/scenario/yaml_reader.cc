#include "hil/harness/scenario/yaml_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>

namespace hil::harness {

ScenarioError::ScenarioError(std::string file, int line, std::string field,
                             const std::string& message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         (field.empty() ? "" : field + ": ") + message),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)) {}

namespace {

struct NonText {
  int line = 0;
  std::string message;
};

// The first byte that cannot be in a YAML text file (a control character other than tab and line
// ends, or a byte that does not start or continue valid UTF-8), named by its line, column and
// value: yaml-cpp's own message would print the byte itself, which a terminal does not show.
std::optional<NonText> FirstNonText(const std::string& text) {
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
      return NonText{line, "column " + std::to_string(column) + ": byte " + hex +
                               " is not text (a scenario is a UTF-8 YAML text file; is this a "
                               "binary file?)"};
    }
    if (c == '\n') ++line, column = 0;
    i += len;
  }
  return std::nullopt;
}

}  // namespace

int EditDistance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      cur[j] =
          std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

YamlReader::YamlReader(YAML::Node node, std::string file, std::string path)
    : node_(std::move(node)), file_(std::move(file)), path_(std::move(path)) {}

YamlReader YamlReader::LoadFile(const std::string& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw ScenarioError(file, 0, "", "is a folder, not a scenario file");
  std::ifstream probe(file, std::ios::binary);
  if (!probe) throw ScenarioError(file, 0, "", "cannot read the file (missing or not readable)");
  const std::string text{std::istreambuf_iterator<char>(probe), std::istreambuf_iterator<char>()};
  if (const auto bad = FirstNonText(text)) throw ScenarioError(file, bad->line, "", bad->message);
  try {
    YAML::Node root = YAML::Load(text);
    if (root.IsNull() || !root.IsDefined())
      throw ScenarioError(file, 1, "", "the file is empty (a scenario is a mapping of keys)");
    if (!root.IsMap())
      throw ScenarioError(file, root.Mark().line + 1, "", "the document must be a mapping of keys");
    return YamlReader(root, file, "");
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(file, e.mark.line + 1, "", "YAML syntax error: " + e.msg);
  }
}

const std::string& YamlReader::FileOf(const std::string& key) const {
  const auto it = key_file_.find(key);
  return it == key_file_.end() ? file_ : it->second;
}

void YamlReader::ResolveIncludes(const std::string& base_dir_in,
                                 const std::vector<std::string>& lib_dirs, int depth) {
  namespace fs = std::filesystem;
  // a scenario named without a folder ("my.yaml") lives in the current one
  const std::string base_dir = base_dir_in.empty() ? "." : base_dir_in;
  const auto inc = Get("include");
  if (!inc) return;
  if (depth > 8) Fail("include", "includes nested more than 8 deep (a cycle?)");
  std::vector<std::string> names;
  if (inc->IsScalar()) {
    names.push_back(inc->Scalar());
  } else if (inc->IsSequence()) {
    for (const auto& el : *inc) {
      if (!el.IsScalar())
        throw ScenarioError(file_, el.Mark().line + 1, FieldOf("include"), "expected a file name");
      names.push_back(el.Scalar());
    }
  } else {
    Fail("include", "expected a file name or a list of file names");
  }
  std::map<std::string, std::string> added;  // key -> the include that added it
  for (const std::string& name : names) {
    std::vector<fs::path> candidates{fs::path(base_dir) / name};
    for (const auto& d : lib_dirs) candidates.push_back(fs::path(d) / name);
    std::string found;
    for (const auto& c : candidates) {
      std::error_code ec;
      if (fs::is_regular_file(c, ec)) {
        found = c.lexically_normal().string();
        break;
      }
    }
    if (found.empty()) {
      std::string where = base_dir;
      for (const auto& d : lib_dirs) where += ", " + d;
      Fail("include", "cannot find included file '" + name + "' (looked in " + where + ")");
    }
    YamlReader sub = LoadFile(found);
    sub.ResolveIncludes(fs::path(found).parent_path().string(), lib_dirs, depth + 1);
    for (const auto& kv : sub.node_) {
      const std::string key = kv.first.Scalar();
      if (key == "include" || Has(key)) {
        if (added.count(key)) {
          throw ScenarioError(found, kv.first.Mark().line + 1, key,
                              "also defined by the included file " + added[key] +
                                  " (give it in the scenario itself)");
        }
        continue;  // the including document wins
      }
      node_[key] = kv.second;
      key_file_[key] = sub.FileOf(key);
      added[key] = found;
    }
  }
}

int YamlReader::line() const { return node_.Mark().line + 1; }

std::string YamlReader::FieldOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void YamlReader::Fail(const std::string& message) const {
  throw ScenarioError(file_, line(), path_, message);
}

void YamlReader::Fail(const std::string& key, const std::string& message) const {
  const auto n = Get(key);
  const int ln = n ? n->Mark().line + 1 : line();
  throw ScenarioError(n ? FileOf(key) : file_, ln, FieldOf(key), message);
}

std::optional<YAML::Node> YamlReader::Get(const std::string& key) const {
  if (!node_.IsMap()) return std::nullopt;
  for (const auto& kv : node_) {
    if (kv.first.Scalar() == key) return kv.second;
  }
  return std::nullopt;
}

void YamlReader::CheckKeys(std::initializer_list<const char*> allowed) const {
  CheckKeys(std::vector<std::string>(allowed.begin(), allowed.end()));
}

void YamlReader::CheckKeys(const std::vector<std::string>& allowed) const {
  if (!node_.IsMap()) Fail("expected a mapping of keys");
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string best;
    int best_d = 3;
    for (const auto& a : allowed) {
      const int d = EditDistance(key, a);
      if (d < best_d) {
        best_d = d;
        best = a;
      }
    }
    std::string msg = "unknown key";
    if (!best.empty())
      msg += " (did you mean '" + best + "'?)";
    else {
      msg += " (known keys:";
      for (const auto& a : allowed) msg += " " + a;
      msg += ")";
    }
    throw ScenarioError(FileOf(key), kv.first.Mark().line + 1, FieldOf(key), msg);
  }
}

bool YamlReader::Has(const std::string& key) const { return Get(key).has_value(); }

YamlReader YamlReader::Child(const std::string& key) const {
  const auto n = Get(key);
  if (!n) Fail("missing required key '" + key + "'");
  return YamlReader(*n, FileOf(key), FieldOf(key));
}

std::optional<YamlReader> YamlReader::OptionalChild(const std::string& key) const {
  const auto n = Get(key);
  if (!n || n->IsNull()) return std::nullopt;
  return YamlReader(*n, FileOf(key), FieldOf(key));
}

std::vector<YamlReader> YamlReader::Elements() const {
  if (!node_.IsSequence()) Fail("expected a list");
  std::vector<YamlReader> out;
  std::size_t i = 0;
  for (const auto& el : node_) out.emplace_back(el, file_, path_ + "[" + std::to_string(i++) + "]");
  return out;
}

std::string YamlReader::Scalar() const {
  if (!node_.IsScalar()) Fail("expected a single value");
  return node_.Scalar();
}

double YamlReader::Double(const std::string& key) const {
  const auto found = Get(key);
  if (!found) Fail("missing required key '" + key + "'");
  const YAML::Node n = *found;
  if (!n.IsScalar()) Fail(key, "expected a number");
  try {
    const double v = n.as<double>();
    if (!std::isfinite(v)) Fail(key, "expected a finite number, got '" + n.Scalar() + "'");
    return v;
  } catch (const YAML::Exception&) {
    Fail(key, "expected a number, got '" + n.Scalar() + "'");
  }
}

double YamlReader::Double(const std::string& key, double fallback) const {
  return Has(key) ? Double(key) : fallback;
}

double YamlReader::DoubleIn(const std::string& key, double fallback, double lo, double hi) const {
  const double v = Double(key, fallback);
  if (v < lo || v > hi) {
    char buf[160];
    std::snprintf(buf, sizeof buf, "value %g out of range [%g, %g]", v, lo, hi);
    Fail(key, buf);
  }
  return v;
}

std::int64_t YamlReader::Int(const std::string& key, std::int64_t fallback, std::int64_t lo,
                             std::int64_t hi) const {
  const auto found = Get(key);
  if (!found) return fallback;
  const YAML::Node n = *found;
  if (!n.IsScalar()) Fail(key, "expected an integer");
  std::int64_t v = 0;
  try {
    v = n.as<std::int64_t>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected an integer, got '" + n.Scalar() + "'");
  }
  if (v < lo || v > hi)
    Fail(key, "value " + std::to_string(v) + " out of range [" + std::to_string(lo) + ", " +
                  std::to_string(hi) + "]");
  return v;
}

bool YamlReader::Bool(const std::string& key, bool fallback) const {
  const auto found = Get(key);
  if (!found) return fallback;
  const YAML::Node n = *found;
  try {
    return n.as<bool>();
  } catch (const YAML::Exception&) {
    Fail(key, "expected true or false, got '" +
                  (n.IsScalar() ? n.Scalar() : std::string("a structure")) + "'");
  }
}

std::string YamlReader::String(const std::string& key) const {
  const auto found = Get(key);
  if (!found) Fail("missing required key '" + key + "'");
  const YAML::Node n = *found;
  if (!n.IsScalar()) Fail(key, "expected a string");
  return n.Scalar();
}

std::string YamlReader::String(const std::string& key, const std::string& fallback) const {
  return Has(key) ? String(key) : fallback;
}

std::string YamlReader::Choice(const std::string& key, const std::string& fallback,
                               std::initializer_list<const char*> choices) const {
  const std::string v = String(key, fallback);
  for (const char* c : choices) {
    if (v == c) return v;
  }
  std::string msg = "unknown value '" + v + "' (one of:";
  for (const char* c : choices) msg += std::string(" ") + c;
  Fail(key, msg + ")");
}

std::size_t YamlReader::ChoiceIndex(const std::string& key, std::size_t fallback,
                                    std::span<const std::string_view> names) const {
  const std::string v = String(key, std::string(names[fallback]));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (v == names[i]) return i;
  }
  std::string msg = "unknown value '" + v + "' (one of:";
  for (const std::string_view c : names) msg += " " + std::string(c);
  Fail(key, msg + ")");
}

std::vector<double> YamlReader::Doubles(const std::string& key, std::size_t n,
                                        std::vector<double> fallback) const {
  const auto found = Get(key);
  if (!found) return fallback;
  const YAML::Node node = *found;
  if (!node.IsSequence() || node.size() != n)
    Fail(key, "expected a list of " + std::to_string(n) + " numbers");
  std::vector<double> out;
  for (const auto& el : node) {
    try {
      out.push_back(el.as<double>());
    } catch (const YAML::Exception&) {
      throw ScenarioError(FileOf(key), el.Mark().line + 1, FieldOf(key),
                          "expected a number, got '" + el.Scalar() + "'");
    }
  }
  return out;
}

}  // namespace hil::harness

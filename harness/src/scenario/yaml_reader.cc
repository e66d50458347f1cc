#include "hil/harness/scenario/yaml_reader.h"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>

#include <sys/stat.h>

#include "hil/harness/scenario/yaml_text_checks.h"

namespace hil::harness {

ScenarioError::ScenarioError(std::string file, int line, std::string field,
                             const std::string& message)
    : std::runtime_error(file + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                         (field.empty() ? "" : field + ": ") + message),
      file_(std::move(file)),
      line_(line),
      field_(std::move(field)) {}

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

namespace {

constexpr std::size_t kMaxScenarioBytes = 16u << 20;

// The whole of a regular file, refusing a folder, a FIFO, a device or a socket at once: opened
// without blocking and checked before a byte is read.
std::string ReadRegularFile(const std::string& file) {
  const int fd = open(file.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0)
    throw ScenarioError(file, 0, "",
                        std::string("cannot read the file (") + std::strerror(errno) + ")");
  struct stat st {};
  std::string why;
  if (fstat(fd, &st) != 0)
    why = std::string("cannot read the file (") + std::strerror(errno) + ")";
  else if (S_ISDIR(st.st_mode))
    why = "is a folder, not a scenario file";
  else if (!S_ISREG(st.st_mode))
    why = "is not a regular file (a FIFO, device or socket is never read as a scenario)";
  else if (static_cast<std::size_t>(st.st_size) > kMaxScenarioBytes)
    why = "is larger than 16 MiB: not a scenario file";
  std::string text;
  if (why.empty()) {
    text.resize(static_cast<std::size_t>(st.st_size));
    std::size_t got = 0;
    while (got < text.size()) {
      const ssize_t n = read(fd, text.data() + got, text.size() - got);
      if (n < 0 && errno == EINTR) continue;
      if (n <= 0) break;
      got += static_cast<std::size_t>(n);
    }
    text.resize(got);
  }
  close(fd);
  if (!why.empty()) throw ScenarioError(file, 0, "", why);
  return text;
}

}  // namespace

YamlReader YamlReader::LoadFile(const std::string& file) {
  return FromText(ReadRegularFile(file), file);
}

YamlReader YamlReader::FromText(const std::string& text, const std::string& file) {
  if (const auto bad = FirstNonText(text)) throw ScenarioError(file, bad->line, "", bad->message);
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    if (const auto tab = FirstTabIndent(text))
      throw ScenarioError(file, tab->line, "", tab->message);
    throw ScenarioError(file, e.mark.line + 1, "", "YAML syntax error: " + e.msg);
  }
  if (root.IsNull() || !root.IsDefined())
    throw ScenarioError(file, 1, "", "the file is empty (a scenario is a mapping of keys)");
  if (!root.IsMap())
    throw ScenarioError(file, root.Mark().line + 1, "", "the document must be a mapping of keys");
  CheckNoDuplicateKeys(root, file, "");
  return YamlReader(root, file, "");
}

const std::string& YamlReader::FileOf(const std::string& key) const {
  const auto it = key_file_.find(key);
  return it == key_file_.end() ? file_ : it->second;
}

void YamlReader::NoteOrigin(const YAML::Node& value, const std::string& origin) {
  if (!origins_) origins_ = std::make_shared<std::vector<std::pair<YAML::Node, std::string>>>();
  origins_->emplace_back(value, origin);
}

const std::string* YamlReader::OriginOf(const YAML::Node& n) const {
  if (!origins_) return nullptr;
  for (const auto& [node, origin] : *origins_) {
    if (node.is(n)) return &origin;
  }
  return nullptr;
}

YamlReader YamlReader::Sub(const YAML::Node& n, const std::string& file,
                           const std::string& path) const {
  YamlReader r(n, file, path);
  r.origins_ = origins_;
  r.from_origin_ = from_origin_;
  if (const std::string* o = OriginOf(n)) {
    r.file_ = *o;
    r.from_origin_ = true;
  }
  return r;
}

ScenarioError YamlReader::ErrorAt(const YAML::Node& n, const std::string& file,
                                  const std::string& field, const std::string& message) const {
  if (from_origin_) return ScenarioError(file_, 0, field, message);
  if (const std::string* o = OriginOf(n)) return ScenarioError(*o, 0, field, message);
  return ScenarioError(file, n.Mark().line + 1, field, message);
}

int YamlReader::line() const { return node_.Mark().line + 1; }

std::string YamlReader::FieldOf(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

void YamlReader::Fail(const std::string& message) const {
  throw ErrorAt(node_, file_, path_, message);
}

void YamlReader::Fail(const std::string& key, const std::string& message) const {
  const auto n = Get(key);
  if (!n) throw ErrorAt(node_, file_, FieldOf(key), message);
  throw ErrorAt(*n, FileOf(key), FieldOf(key), message);
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
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : std::string();
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    if (key.empty()) {
      throw ErrorAt(kv.first.Mark().line >= 0 ? kv.first : kv.second, FileOf(key), path_,
                    "an empty key (a line starting with ':', or a key that is not a name)");
    }
    if (!IsPlainKey(key)) {
      throw ErrorAt(kv.first.Mark().line >= 0 ? kv.first : kv.second, FileOf(key), path_,
                    "a key that is not a scenario key name (" + std::to_string(key.size()) +
                        " characters; keys are letters, digits and '_'); is this a scenario "
                        "file?");
    }
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
    throw ErrorAt(kv.first.Mark().line >= 0 ? kv.first : kv.second, FileOf(key), FieldOf(key), msg);
  }
}

bool YamlReader::Has(const std::string& key) const { return Get(key).has_value(); }

YamlReader YamlReader::Child(const std::string& key) const {
  const auto n = Get(key);
  if (!n) Fail("missing required key '" + key + "'");
  return Sub(*n, FileOf(key), FieldOf(key));
}

std::optional<YamlReader> YamlReader::OptionalChild(const std::string& key) const {
  const auto n = Get(key);
  if (!n || n->IsNull()) return std::nullopt;
  return Sub(*n, FileOf(key), FieldOf(key));
}

std::vector<YamlReader> YamlReader::Elements() const {
  if (!node_.IsSequence()) Fail("expected a list");
  std::vector<YamlReader> out;
  std::size_t i = 0;
  for (const auto& el : node_)
    out.push_back(Sub(el, file_, path_ + "[" + std::to_string(i++) + "]"));
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
      throw ErrorAt(el, FileOf(key), FieldOf(key), "expected a number, got '" + el.Scalar() + "'");
    }
    if (!std::isfinite(out.back()))
      throw ErrorAt(el, FileOf(key), FieldOf(key),
                    "expected a finite number, got '" + el.Scalar() + "'");
  }
  return out;
}

}  // namespace hil::harness

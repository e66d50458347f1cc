#include "hil/harness/scenario/scenario_overrides.h"

#include <cctype>
#include <stdexcept>

#include "hil/harness/scenario/yaml_reader.h"
#include "hil/harness/scenario/yaml_text_checks.h"

namespace hil::harness {
namespace {

bool IsIndex(const std::string& seg) { return !seg.empty() && seg.front() == '['; }

std::size_t IndexOf(const std::string& seg) {
  return static_cast<std::size_t>(std::stoul(seg.substr(1, seg.size() - 2)));
}

YAML::Node ParseValue(const ScenarioOverride& o, const std::string& origin) {
  YAML::Node value;
  try {
    value = YAML::Load(o.value);
  } catch (const YAML::ParserException& e) {
    throw ScenarioError(origin, 0, o.field, "value '" + o.value + "' is not YAML: " + e.msg);
  }
  CheckNoDuplicateKeys(value, origin, o.field);
  return value;
}

}  // namespace

std::vector<std::string> SplitFieldPath(const std::string& field) {
  std::vector<std::string> segs;
  std::size_t i = 0;
  while (i < field.size()) {
    if (field[i] == '[') {
      const std::size_t close = field.find(']', i);
      if (close == std::string::npos || close == i + 1)
        throw std::invalid_argument("malformed list index in '" + field + "'");
      for (std::size_t k = i + 1; k < close; ++k) {
        if (!std::isdigit(static_cast<unsigned char>(field[k])))
          throw std::invalid_argument("list index in '" + field + "' is not a number");
      }
      segs.push_back(field.substr(i, close - i + 1));
      i = close + 1;
      if (i < field.size() && field[i] == '.') ++i;
      continue;
    }
    const std::size_t end = field.find_first_of(".[", i);
    const std::string key = field.substr(i, end == std::string::npos ? end : end - i);
    if (key.empty()) throw std::invalid_argument("empty key in field path '" + field + "'");
    segs.push_back(key);
    i = end == std::string::npos ? field.size() : end + (field[end] == '.' ? 1 : 0);
  }
  if (segs.empty() || IsIndex(segs.front()))
    throw std::invalid_argument("field path '" + field + "' must start with a key");
  return segs;
}

ScenarioOverride ParseOverride(const std::string& text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0)
    throw std::invalid_argument("expected FIELD=VALUE (e.g. gnss.baud=38400), got '" + text + "'");
  ScenarioOverride o{text.substr(0, eq), text.substr(eq + 1), ""};
  SplitFieldPath(o.field);  // throws for a malformed path
  return o;
}

void ApplyOverrides(YamlReader& root, const std::vector<ScenarioOverride>& overrides) {
  for (const ScenarioOverride& o : overrides) {
    // errors name the override, never a line of the scenario file it did not come from
    const std::string origin = o.origin.empty() ? "--set " + o.field + "=" + o.value : o.origin;
    std::vector<std::string> segs;
    try {
      segs = SplitFieldPath(o.field);
    } catch (const std::invalid_argument& e) {
      throw ScenarioError(origin, 0, o.field, e.what());
    }
    const YAML::Node value = ParseValue(o, origin);
    YAML::Node node = root.node();  // shares the document: assignments change the root
    std::string walked;
    for (std::size_t k = 0; k + 1 < segs.size(); ++k) {
      const std::string& s = segs[k];
      const YAML::Node& view = node;  // const lookups: never add a key while looking
      YAML::Node next;
      if (IsIndex(s) && view.IsSequence() && IndexOf(s) < view.size())
        next.reset(view[IndexOf(s)]);
      else if (!IsIndex(s) && view.IsMap() && view[s])
        next.reset(view[s]);
      else
        throw ScenarioError(origin, 0, o.field,
                            "cannot set it: the scenario " + root.file() + " has no '" + walked +
                                (IsIndex(s) || walked.empty() ? "" : ".") + s + "'");
      walked += (IsIndex(s) || walked.empty() ? "" : ".") + s;
      node.reset(next);
    }
    const std::string& last = segs.back();
    if (IsIndex(last)) {
      if (!node.IsSequence() || IndexOf(last) >= node.size())
        throw ScenarioError(origin, 0, o.field,
                            "cannot set it: '" + walked + "' has no element " + last);
      node[IndexOf(last)] = value;
      root.NoteOrigin(value, origin);
    } else {
      if (!node.IsMap())
        throw ScenarioError(
            origin, 0, o.field,
            "cannot set it: '" + (walked.empty() ? "the document" : walked) + "' is not a mapping");
      node[last] = value;
      root.NoteOrigin(value, origin);
    }
  }
}

}  // namespace hil::harness

#pragma once
/// @file
/// The scenario file's keys as tables: one table per section (`vehicle`, `closed_loop.actuator`,
/// ...), one row per key with its type, unit, default, allowed range, meaning and the source of
/// its default. The section's reader validates with its table (KeyedReader: the known keys, the
/// ranges and the choices come from the rows), and `hil scenario-keys` prints every table as the
/// scenario reference (docs/scenario_reference.md, checked against the tables by
/// scenario_reference_test), so the documentation cannot drift from what the reader takes;
/// scenario_key_coverage_test checks that every top-level section has a table, that each reader
/// takes exactly its table's keys and that the printed defaults are the readers'.
///
/// Adding a key is one row in its section's table, then one read of it in the reader:
///   {.name = "mask_deg", .type = KeyType::kNumber, .unit = "deg", .default_text = "10",
///    .lo = 0, .hi = 90, .meaning = "elevation mask"},
/// A reader naming a key its table does not list does not compile (KeyIn's consteval lookup).

#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

/// What a key's value is.
enum class KeyType {
  kNumber,   ///< a finite number in [lo, hi]
  kInteger,  ///< a whole number in [lo, hi]
  kBool,     ///< true or false
  kString,   ///< any text (a file name, a command line)
  kChoice,   ///< one of `choices`
  kPoint,    ///< a list of numbers ([east, north] unless the meaning says otherwise)
  kTime,     ///< an ISO 8601 UTC time
  kList,     ///< a list of entries (their keys in the section named `<path>[]`)
  kMapping,  ///< a mapping (its keys in the section named `<path>`)
};

/// One key of a section: a row of its table.
struct ScenarioKey {
  std::string_view name;
  KeyType type = KeyType::kNumber;
  std::string_view unit;          ///< SI unit ("m", "deg", "m/s"), empty when none
  std::string_view default_text;  ///< the default as a reader sees it ("required", "by model")
  double lo = 0, hi = 0;          ///< kNumber, kInteger: the allowed range, inclusive
  std::string_view meaning;
  std::span<const std::string_view> choices = {};  ///< kChoice: the values taken
  /// Replaces the printed [lo, hi] when the bound depends on other keys ("±max_steer_deg").
  std::string_view range_text = {};
  /// Where the default comes from: a document the code's comment cites, or "ours: REASON" when
  /// the code chose it; empty when the default is no physical figure (a name, "none").
  std::string_view source = {};
};

/// A row's empty `choices` and `range_text`, by name: a row that states its source after them reads
/// (and clang-format packs) as a row.
inline constexpr std::span<const std::string_view> kNoChoices{};
inline constexpr std::string_view kAnyRange{};

/// A section of the scenario file and its table.
struct KeySection {
  std::string_view path;  ///< dotted ("closed_loop.actuator"); "" for the top level
  std::string_view meaning;
  std::span<const ScenarioKey> keys;
};

/// The sections of the scenario stage's readers that have a table, in the reference's order
/// (scenario_key_sections.cc); the devices' are the device stage's (devices/scenario_file.h).
std::span<const KeySection* const> ScenarioKeySections();

/// The scenario reference (Markdown) generated from the tables `sections`; the top-level keys
/// whose sections have no table yet (`without_table`) are listed by name.
std::string ScenarioReferenceMarkdown(std::span<const KeySection* const> sections,
                                      std::span<const std::string> without_table);

/// The key `name` of table `Table`, found at compile time: a name the table does not list is a
/// compile error ("not in the section's table").
template <const auto& Table>
struct KeyIn {
  consteval KeyIn(const char* name) : index(Find(name)) {}  // NOLINT: implicit on purpose
  std::size_t index;

 private:
  static consteval std::size_t Find(std::string_view name) {
    for (std::size_t i = 0; i < std::size(Table); ++i) {
      if (Table[i].name == name) return i;
    }
    throw "a key that is not in the section's table (scenario_keys.h)";
  }
};

/// The reader of one section that validates with its table: the keys it accepts, the range of a
/// number and the values of a choice are the table's. Errors are YamlReader's ("FILE:LINE:
/// FIELD: MESSAGE").
template <const auto& Table>
class KeyedReader {
 public:
  using Key = KeyIn<Table>;
  explicit KeyedReader(const YamlReader& r) : r_(r) {}

  /// Fails on a key the table does not list.
  void CheckKeys() const {
    std::vector<std::string> names;
    for (const ScenarioKey& k : Table) names.emplace_back(k.name);
    r_.CheckKeys(names);
  }
  /// Fails on a key outside `keys` (the table's keys that apply here, e.g. to one path type).
  void CheckKeys(std::span<const Key> keys) const {
    std::vector<std::string> names;
    for (const Key& k : keys) names.emplace_back(Row(k).name);
    r_.CheckKeys(names);
  }
  void CheckKeys(std::initializer_list<Key> keys) const {
    CheckKeys(std::span<const Key>(keys.begin(), keys.size()));
  }
  bool Has(Key k) const { return r_.Has(Name(k)); }
  /// A number in the table's range.
  double Number(Key k, double fallback) const {
    const ScenarioKey& row = Row(k);
    return r_.DoubleIn(Name(k), fallback, row.lo, row.hi);
  }
  /// A number in [lo, hi], a range narrower than the table's that other keys set.
  double NumberIn(Key k, double fallback, double lo, double hi) const {
    return r_.DoubleIn(Name(k), fallback, lo, hi);
  }
  std::int64_t Integer(Key k, std::int64_t fallback) const {
    const ScenarioKey& row = Row(k);
    return r_.Int(Name(k), fallback, IntBound(row.lo), IntBound(row.hi));
  }
  bool Bool(Key k, bool fallback) const { return r_.Bool(Name(k), fallback); }
  std::string String(Key k) const { return r_.String(Name(k)); }
  std::string String(Key k, const std::string& fallback) const {
    return r_.String(Name(k), fallback);
  }
  /// One of the table's choices (`fallback` when absent).
  std::string Choice(Key k, std::string_view fallback) const {
    return std::string(
        Row(k).choices[r_.ChoiceIndex(Name(k), IndexOf(k, fallback), Row(k).choices)]);
  }
  /// The choice as the enum whose names (in its order) are the table's choices.
  template <class Enum>
  requires std::is_enum_v<Enum> Enum Choice(Key k, Enum fallback)
  const {
    return static_cast<Enum>(
        r_.ChoiceIndex(Name(k), static_cast<std::size_t>(fallback), Row(k).choices));
  }
  std::vector<double> Doubles(Key k, std::size_t n, std::vector<double> fallback) const {
    return r_.Doubles(Name(k), n, std::move(fallback));
  }
  YamlReader Child(Key k) const { return r_.Child(Name(k)); }
  std::optional<YamlReader> OptionalChild(Key k) const { return r_.OptionalChild(Name(k)); }
  [[noreturn]] void Fail(Key k, const std::string& message) const { r_.Fail(Name(k), message); }
  [[noreturn]] void Fail(const std::string& message) const { r_.Fail(message); }
  const YamlReader& yaml() const { return r_; }
  static const ScenarioKey& Row(Key k) { return Table[k.index]; }
  static std::string Name(Key k) { return std::string(Table[k.index].name); }

 private:
  static std::int64_t IntBound(double b) {
    constexpr double kLimit = 9.2e18;  // beyond: the int64 limit itself
    if (b >= kLimit) return INT64_MAX;
    if (b <= -kLimit) return INT64_MIN;
    return static_cast<std::int64_t>(b);
  }
  static std::size_t IndexOf(Key k, std::string_view choice) {
    const auto& c = Row(k).choices;
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] == choice) return i;
    }
    return 0;
  }
  YamlReader r_;
};

}  // namespace hil::harness

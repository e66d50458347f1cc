#pragma once
/// @file
/// Strict, position-aware reading of YAML documents (scenario files and their includes). Every
/// error is a ScenarioError naming the file, the 1-based line and the dotted field path
/// (`devices.gps.baud`), with a suggestion for a misspelt key.

#include <array>
#include <functional>
#include <initializer_list>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace hil::harness {

/// A scenario error: "FILE:LINE: FIELD: MESSAGE". Exit code 2 territory.
class ScenarioError : public std::runtime_error {
 public:
  ScenarioError(std::string file, int line, std::string field, const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
};

/// A view of one YAML node with the file and field path it came from.
class YamlReader {
 public:
  YamlReader(YAML::Node node, std::string file, std::string path);

  /// Loads a file. @throws ScenarioError for a missing/unreadable file, a folder, a FIFO or
  /// other non-regular file (refused before any read, so never blocks), a YAML syntax error, a
  /// tab in the indentation or a key given twice in one mapping (at any depth).
  static YamlReader LoadFile(const std::string& file);
  /// The same checks on a document's text; `file` names it in errors.
  static YamlReader FromText(const std::string& text, const std::string& file);

  /// Resolves `include: [a.yaml, vehicles/tractor.yaml]` in a root mapping: each named file is
  /// looked up beside `base_dir`, then in each of `lib_dirs` (e.g. vectors/scenarios/lib); its
  /// top-level keys are added where this document does not define them (the document wins), and
  /// errors in them name the included file. Included files may include others (depth ≤ 8).
  /// An included file, its symbolic links followed, must lie under `base_dir` (the folder of the
  /// scenario named on the command line) or under one of `lib_dirs`.
  /// @throws ScenarioError for a missing include, a folder, a non-regular file, a file outside
  /// those folders, a cycle or a key two includes both define.
  void ResolveIncludes(const std::string& base_dir, const std::vector<std::string>& lib_dirs);

  /// Marks `value` (a node set into this document from outside, e.g. `--set seed=abc`) so that
  /// an error in it, or below it, names `origin` instead of this file and a line.
  void NoteOrigin(const YAML::Node& value, const std::string& origin);

  /// Fails on any key of this mapping that is not in `allowed` (suggesting the closest one).
  void CheckKeys(std::initializer_list<const char*> allowed) const;
  void CheckKeys(const std::vector<std::string>& allowed) const;
  bool Has(const std::string& key) const;
  /// The child mapping/sequence at `key`. @throws ScenarioError when missing (if required).
  YamlReader Child(const std::string& key) const;
  std::optional<YamlReader> OptionalChild(const std::string& key) const;
  /// Elements of a sequence. @throws ScenarioError when this node is not a sequence.
  std::vector<YamlReader> Elements() const;

  double Double(const std::string& key) const;
  double Double(const std::string& key, double fallback) const;
  /// A number in [lo, hi].
  double DoubleIn(const std::string& key, double fallback, double lo, double hi) const;
  std::int64_t Int(const std::string& key, std::int64_t fallback, std::int64_t lo,
                   std::int64_t hi) const;
  bool Bool(const std::string& key, bool fallback) const;
  std::string String(const std::string& key) const;
  std::string String(const std::string& key, const std::string& fallback) const;
  /// A string that must be one of `choices`.
  std::string Choice(const std::string& key, const std::string& fallback,
                     std::initializer_list<const char*> choices) const;
  /// Choice() for an enum: the index of the value in `names` (`fallback` when the key is absent).
  std::size_t ChoiceIndex(const std::string& key, std::size_t fallback,
                          std::span<const std::string_view> names) const;
  /// ChoiceIndex() as the enum whose names array (in the enum's order) is `names`.
  template <class Enum, std::size_t N>
  Enum Choice(const std::string& key, Enum fallback,
              const std::array<std::string_view, N>& names) const {
    return static_cast<Enum>(ChoiceIndex(key, static_cast<std::size_t>(fallback), names));
  }
  /// A sequence of exactly `n` numbers.
  std::vector<double> Doubles(const std::string& key, std::size_t n,
                              std::vector<double> fallback) const;

  /// Throws a ScenarioError located at this node (or at `key` within it).
  [[noreturn]] void Fail(const std::string& message) const;
  [[noreturn]] void Fail(const std::string& key, const std::string& message) const;

  const YAML::Node& node() const { return node_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }
  int line() const;
  bool IsMap() const { return node_.IsMap(); }
  bool IsSequence() const { return node_.IsSequence(); }
  bool IsScalar() const { return node_.IsScalar(); }
  std::string Scalar() const;

 private:
  void ResolveIncludes(const std::string& base_dir, const std::vector<std::string>& lib_dirs,
                       const std::vector<std::string>& roots, int depth);
  std::string FindInclude(const std::string& name, const std::string& base_dir,
                          const std::vector<std::string>& lib_dirs,
                          const std::vector<std::string>& roots) const;
  std::string FieldOf(const std::string& key) const;
  std::optional<YAML::Node> Get(const std::string& key) const;
  const std::string& FileOf(const std::string& key) const;
  const std::string* OriginOf(const YAML::Node& n) const;
  /// A reader of a node below this one (keeping the origins of set values).
  YamlReader Sub(const YAML::Node& n, const std::string& file, const std::string& path) const;
  /// An error located at `n`: its origin when it was set from outside, else `file` and its line.
  ScenarioError ErrorAt(const YAML::Node& n, const std::string& file, const std::string& field,
                        const std::string& message) const;
  YAML::Node node_;
  std::map<std::string, std::string> key_file_;  // top-level keys that came from an included file
  std::string file_;
  std::string path_;
  std::shared_ptr<std::vector<std::pair<YAML::Node, std::string>>> origins_;
  bool from_origin_ = false;  // this node lies inside a value set from outside
};

/// The folders (canonical) an include may be read from: the libraries and `base_dir`.
std::vector<std::string> IncludeRoots(const std::string& base_dir,
                                      const std::vector<std::string>& lib_dirs);

/// Edit distance, for "did you mean" suggestions.
int EditDistance(const std::string& a, const std::string& b);

}  // namespace hil::harness

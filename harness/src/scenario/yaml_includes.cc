// `include:` of a scenario: where an included file may be found and what may be read.
#include <filesystem>
#include <map>

#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

bool InsideFolder(const fs::path& file, const fs::path& root) {
  const fs::path rel = file.lexically_relative(root);
  return !rel.empty() && *rel.begin() != "..";
}

}  // namespace

std::vector<std::string> IncludeRoots(const std::string& base_dir,
                                      const std::vector<std::string>& lib_dirs) {
  std::vector<std::string> roots;
  for (const std::string& d : lib_dirs) roots.push_back(d);
  roots.push_back(base_dir.empty() ? "." : base_dir);
  std::vector<std::string> out;
  for (const std::string& d : roots) {
    std::error_code ec;
    const fs::path c = fs::canonical(d, ec);
    if (!ec) out.push_back(c.string());
  }
  return out;
}

std::string YamlReader::FindInclude(const std::string& name, const std::string& base_dir,
                                    const std::vector<std::string>& lib_dirs,
                                    const std::vector<std::string>& roots) const {
  std::vector<fs::path> candidates{fs::path(base_dir) / name};
  for (const auto& d : lib_dirs) candidates.push_back(fs::path(d) / name);
  for (const auto& c : candidates) {
    std::error_code ec;
    const fs::file_status st = fs::status(c, ec);
    if (ec || !fs::exists(st)) continue;
    if (fs::is_directory(st)) Fail("include", "'" + name + "' is a folder, not a scenario file");
    if (!fs::is_regular_file(st)) {
      Fail("include",
           "'" + name + "' is not a regular file (a FIFO, device or socket is never read)");
    }
    const fs::path real = fs::canonical(c, ec);
    bool inside = false;
    for (const auto& r : roots) inside = inside || (!ec && InsideFolder(real, r));
    if (!inside) {
      std::string where;
      for (const auto& r : roots) where += (where.empty() ? "" : ", ") + r;
      Fail("include", "'" + name + "' is " + real.string() +
                          ", outside the scenario's folder and the scenario libraries (" + where +
                          "): an include may not leave them (by an absolute path, '..' or a "
                          "symbolic link); add its folder to HIL_SCENARIO_LIB to allow it");
    }
    return c.lexically_normal().string();
  }
  std::string where = base_dir;
  for (const auto& d : lib_dirs) where += ", " + d;
  Fail("include", "cannot find included file '" + name + "' (looked in " + where + ")");
}

void YamlReader::ResolveIncludes(const std::string& base_dir_in,
                                 const std::vector<std::string>& lib_dirs) {
  // a scenario named without a folder ("my.yaml") lives in the current one
  const std::string base_dir = base_dir_in.empty() ? "." : base_dir_in;
  ResolveIncludes(base_dir, lib_dirs, IncludeRoots(base_dir, lib_dirs), 0);
}

void YamlReader::ResolveIncludes(const std::string& base_dir_in,
                                 const std::vector<std::string>& lib_dirs,
                                 const std::vector<std::string>& roots, int depth) {
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
    if (name.empty()) Fail("include", "an empty file name");
    const std::string found = FindInclude(name, base_dir, lib_dirs, roots);
    YamlReader sub = LoadFile(found);
    sub.ResolveIncludes(fs::path(found).parent_path().string(), lib_dirs, roots, depth + 1);
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

}  // namespace hil::harness

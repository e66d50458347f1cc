#include "hil/harness/eval/path_file_reader.h"

#include <fstream>
#include <map>
#include <sstream>

#include "path_file_boustrophedon.h"

namespace hil::harness {
namespace {

struct Line {
  int number = 0;
  std::string keyword;
  std::map<std::string, std::string> fields;
};

[[noreturn]] void Fail(const std::string& file, int line, const std::string& field,
                       const std::string& msg) {
  throw PathFileReadError(file + ":" + std::to_string(line) + ": field '" + field + "': " + msg);
}

Eigen::Vector2d Point(const std::string& file, const Line& l, const std::string& key) {
  const auto it = l.fields.find(key);
  if (it == l.fields.end()) Fail(file, l.number, key, "missing");
  std::istringstream in(it->second);
  double e = 0, n = 0;
  char comma = 0;
  if (!(in >> e >> comma >> n) || comma != ',' || !in.eof())
    Fail(file, l.number, key, "expected E,N in metres: '" + it->second + "'");
  return {e, n};
}

std::vector<Line> Lines(const std::string& file) {
  std::ifstream in(file);
  if (!in) throw PathFileReadError(file + ": cannot read the path file");
  std::vector<Line> out;
  int n = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++n;
    std::istringstream words(raw.substr(0, raw.find('#')));
    Line l;
    l.number = n;
    if (!(words >> l.keyword)) continue;
    for (std::string kv; words >> kv;) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos) {
        l.fields[kv] = "";
        continue;
      }
      if (!l.fields.emplace(kv.substr(0, eq), kv.substr(eq + 1)).second)
        Fail(file, n, kv.substr(0, eq), "given twice");
    }
    out.push_back(l);
  }
  return out;
}

}  // namespace

std::vector<Eigen::Vector2d> ReadPathVertices(const std::string& file) {
  return ReadPathFile(file).vertices;
}

PathFileShape ReadPathFile(const std::string& file) {
  const std::vector<Line> lines = Lines(file);
  if (lines.empty() || lines[0].keyword != "hil-path" || !lines[0].fields.count("1"))
    Fail(file, lines.empty() ? 1 : lines[0].number, "hil-path", "the header 'hil-path 1' first");
  if (lines.size() < 2) Fail(file, lines[0].number, "shape", "no shape after the header");
  const Line& shape = lines[1];
  if (shape.keyword == "boustrophedon") {
    if (lines.size() > 2) Fail(file, lines[2].number, lines[2].keyword, "one shape per file");
    return BoustrophedonShape(file, shape.number, shape.fields);
  }
  std::vector<Eigen::Vector2d> v;
  if (shape.keyword == "ab_line") {
    const Eigen::Vector2d a = Point(file, shape, "a_m"), b = Point(file, shape, "b_m");
    double extend = 0;
    if (const auto it = shape.fields.find("extend_m"); it != shape.fields.end())
      extend = std::stod(it->second);
    if ((b - a).norm() < 1e-6) Fail(file, shape.number, "b_m", "A and B coincide");
    v = {a, b + (b - a).normalized() * extend};
  } else if (shape.keyword == "polyline") {
    for (std::size_t i = 2; i < lines.size(); ++i) {
      if (lines[i].keyword != "vertex")
        Fail(file, lines[i].number, lines[i].keyword, "not a vertex");
      v.push_back(Point(file, lines[i], "p_m"));
    }
    if (v.size() < 2) Fail(file, shape.number, "vertex", "a polyline needs at least 2 vertices");
  } else {
    Fail(file, shape.number, shape.keyword,
         "the evaluator scores ab_line, polyline and boustrophedon paths");
  }
  PathFileShape out;
  for (std::size_t e = 0; e + 1 < v.size(); ++e) out.spans.push_back({e, e + 1, false});
  out.vertices = std::move(v);
  return out;
}

}  // namespace hil::harness

#pragma once
// A planned-path file (`hil-path 1`, vectors/paths/README.md) as a polyline: this example reads
// the ab_line and polyline shapes only. Errors name the file, the line and the field.
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace hil_example {

using Point = std::array<double, 2>;  // metres east, north of the scenario's origin

inline Point ParsePoint(const std::string& where, const std::string& field,
                        const std::string& value) {
  Point p{};
  char comma = 0;
  std::istringstream in(value);
  if (!(in >> p[0] >> comma >> p[1]) || comma != ',' || !in.eof())
    throw std::runtime_error(where + ": field '" + field + "': expected E,N in metres: '" + value +
                             "'");
  return p;
}

// The statements of the file: line number and words, comments and blank lines left out.
inline std::vector<std::pair<int, std::vector<std::string>>> PathStatements(
    const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read");
  std::vector<std::pair<int, std::vector<std::string>>> out;
  int no = 0;
  for (std::string line; std::getline(in, line);) {
    ++no;
    std::istringstream words(line.substr(0, line.find('#')));
    std::vector<std::string> w;
    for (std::string s; words >> s;) w.push_back(s);
    if (!w.empty()) out.emplace_back(no, std::move(w));
  }
  return out;
}

// "key=value" of a statement, or "" when absent.
inline std::string Field(const std::vector<std::string>& words, const std::string& key) {
  for (const std::string& w : words)
    if (w.rfind(key + "=", 0) == 0) return w.substr(key.size() + 1);
  return {};
}

inline std::vector<Point> ReadPathPolyline(const std::string& path) {
  const auto st = PathStatements(path);
  if (st.empty() || st[0].second != std::vector<std::string>{"hil-path", "1"})
    throw std::runtime_error(path + ":" + std::to_string(st.empty() ? 1 : st[0].first) +
                             ": expected the header 'hil-path 1'");
  if (st.size() < 2) throw std::runtime_error(path + ": no shape after the header");
  const auto& [no, words] = st[1];
  const std::string where = path + ":" + std::to_string(no);
  if (words[0] == "ab_line") {
    for (const char* key : {"a_m", "b_m"})
      if (Field(words, key).empty())
        throw std::runtime_error(where + ": field '" + key + "' missing");
    const Point a = ParsePoint(where, "a_m", Field(words, "a_m"));
    const Point b = ParsePoint(where, "b_m", Field(words, "b_m"));
    const std::string ext_s = Field(words, "extend_m");
    const double ext = ext_s.empty() ? 0.0 : std::stod(ext_s);
    const double len = std::hypot(b[0] - a[0], b[1] - a[1]);
    if (len == 0) throw std::runtime_error(where + ": field 'b_m': A and B are the same point");
    return {a, {b[0] + ext * (b[0] - a[0]) / len, b[1] + ext * (b[1] - a[1]) / len}};
  }
  if (words[0] != "polyline")
    throw std::runtime_error(where + ": shape '" + words[0] +
                             "': this example reads ab_line and polyline only");
  std::vector<Point> v;
  for (std::size_t i = 2; i < st.size(); ++i) {
    const std::string at = path + ":" + std::to_string(st[i].first);
    if (st[i].second[0] != "vertex" || Field(st[i].second, "p_m").empty())
      throw std::runtime_error(at + ": expected 'vertex p_m=E,N'");
    v.push_back(ParsePoint(at, "p_m", Field(st[i].second, "p_m")));
  }
  if (v.size() < 2) throw std::runtime_error(path + ": a polyline needs at least 2 vertices");
  return v;
}

}  // namespace hil_example

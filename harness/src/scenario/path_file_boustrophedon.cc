// The evaluator's boustrophedon: N rows of length L, S apart, alternating direction, joined by
// headland turns (a quarter arc of R, a straight of S − 2R, a quarter arc), every arc as chords of
// at most step_m. Written from the format (vectors/paths/README.md), not from the controller's
// reader.
#include "path_file_boustrophedon.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

namespace hil::harness {
namespace {

struct Fields {
  const std::string& file;
  int line;
  const std::map<std::string, std::string>& kv;

  [[noreturn]] void Fail(const std::string& field, const std::string& msg) const {
    throw PathFileReadError(file + ":" + std::to_string(line) + ": field '" + field + "': " + msg);
  }
  const std::string* Find(const std::string& key) const {
    const auto it = kv.find(key);
    return it == kv.end() ? nullptr : &it->second;
  }
  double Number(const std::string& key, std::optional<double> fallback) const {
    const std::string* v = Find(key);
    if (!v) {
      if (!fallback) Fail(key, "missing");
      return *fallback;
    }
    std::istringstream in(*v);
    double x = 0;
    if (!(in >> x) || !in.eof() || !std::isfinite(x)) Fail(key, "not a number: '" + *v + "'");
    return x;
  }
  Eigen::Vector2d Point(const std::string& key) const {
    const std::string* v = Find(key);
    if (!v) Fail(key, "missing");
    std::istringstream in(*v);
    double e = 0, n = 0;
    char comma = 0;
    if (!(in >> e >> comma >> n) || comma != ',' || !in.eof())
      Fail(key, "expected E,N in metres: '" + *v + "'");
    return {e, n};
  }
};

// Appends the chords of a quarter arc about `c` from c + r·a to c + r·b (a ⟂ b, unit).
void QuarterArc(const Eigen::Vector2d& c, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                double r, double step_m, std::vector<Eigen::Vector2d>& v) {
  const double len = 0.5 * std::numbers::pi * r;
  const int n = std::max(1, static_cast<int>(std::ceil(len / step_m - 1e-9)));
  for (int i = 1; i <= n; ++i) {
    const double phi = 0.5 * std::numbers::pi * i / n;
    v.push_back(c + r * (a * std::cos(phi) + b * std::sin(phi)));
  }
}

}  // namespace

PathFileShape BoustrophedonShape(const std::string& file, int line,
                                 const std::map<std::string, std::string>& fields) {
  const Fields f{file, line, fields};
  for (const auto& [key, value] : fields) {
    (void)value;
    static const char* const kKnown[] = {"start_m",       "heading_deg", "row_length_m",
                                         "row_spacing_m", "rows",        "turn_radius_m",
                                         "first_turn",    "step_m"};
    bool known = false;
    for (const char* k : kKnown) known = known || key == k;
    if (!known) f.Fail(key, "unknown field");
  }
  const Eigen::Vector2d start = f.Point("start_m");
  const double h = f.Number("heading_deg", std::nullopt) * std::numbers::pi / 180.0;
  const double len = f.Number("row_length_m", std::nullopt);
  const double spacing = f.Number("row_spacing_m", std::nullopt);
  const double rows_d = f.Number("rows", std::nullopt);
  const double r = f.Number("turn_radius_m", std::nullopt);
  const double step = f.Number("step_m", 0.1);
  if (!(len > 0)) f.Fail("row_length_m", "must be positive");
  if (!(spacing > 0)) f.Fail("row_spacing_m", "must be positive");
  if (!(rows_d >= 1) || rows_d != std::floor(rows_d)) f.Fail("rows", "a whole number ≥ 1");
  if (!(r > 0) || r > 0.5 * spacing + 1e-12) f.Fail("turn_radius_m", "must be in (0, S/2]");
  if (!(step > 0)) f.Fail("step_m", "must be positive");
  const std::string* turn = f.Find("first_turn");
  if (turn && *turn != "right" && *turn != "left") f.Fail("first_turn", "right or left");
  const Eigen::Vector2d u(std::sin(h), std::cos(h));  // compass heading → east, north
  const Eigen::Vector2d right(u.y(), -u.x());
  const Eigen::Vector2d side = (turn && *turn == "left") ? Eigen::Vector2d(-right) : right;
  PathFileShape out;
  std::vector<Eigen::Vector2d>& v = out.vertices;
  v.push_back(start);
  const int rows = static_cast<int>(rows_d);
  for (int k = 0; k < rows; ++k) {
    const Eigen::Vector2d d = (k % 2 == 0) ? u : Eigen::Vector2d(-u);
    const Eigen::Vector2d end = v.back() + len * d;
    v.push_back(end);
    out.spans.push_back({v.size() - 2, v.size() - 1, false});
    if (k + 1 == rows) break;
    const std::size_t first = v.size() - 1;
    QuarterArc(end + r * side, -side, d, r, step, v);
    if (spacing - 2 * r > 1e-9) v.push_back(end + (spacing - r) * side + r * d);
    QuarterArc(end + (spacing - r) * side, d, side, r, step, v);
    out.spans.push_back({first, v.size() - 1, true});
  }
  return out;
}

}  // namespace hil::harness

#include "hil/estimator/guidance/path_file.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>
#include <vector>

namespace hil::estimator::guidance {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

// One `keyword field=value …` line.
struct Statement {
  int line = 0;
  std::string keyword;
  std::map<std::string, std::string> fields;
};

struct Context {
  std::string file;
  [[noreturn]] void Fail(int line, const std::string& field, const std::string& msg) const {
    throw PathFileError(file, line, field, msg);
  }
};

std::vector<Statement> Tokenize(std::string_view text, const Context& cx) {
  std::vector<Statement> out;
  std::istringstream in{std::string(text)};
  int n = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++n;
    const std::string line = raw.substr(0, raw.find('#'));
    std::istringstream words(line);
    Statement st;
    st.line = n;
    if (!(words >> st.keyword)) continue;
    if (st.keyword == "hil-path") {  // header: "hil-path <version>"
      std::string version;
      words >> version;
      st.fields["version"] = version;
      out.push_back(st);
      continue;
    }
    for (std::string kv; words >> kv;) {
      const auto eq = kv.find('=');
      if (eq == std::string::npos || eq == 0 || eq + 1 == kv.size())
        cx.Fail(n, kv, "expected field=value");
      const std::string key = kv.substr(0, eq);
      if (!st.fields.emplace(key, kv.substr(eq + 1)).second) cx.Fail(n, key, "given twice");
    }
    out.push_back(st);
  }
  return out;
}

class Fields {
 public:
  Fields(const Statement& st, const Context& cx, std::set<std::string> allowed) : st_(st), cx_(cx) {
    for (const auto& [k, v] : st.fields)
      if (!allowed.count(k)) cx.Fail(st.line, k, "unknown field for '" + st.keyword + "'");
  }
  bool Has(const std::string& k) const { return st_.fields.count(k) != 0; }
  double Number(const std::string& k) const { return Parse(k, Text(k)); }
  double Number(const std::string& k, double fallback) const {
    return Has(k) ? Number(k) : fallback;
  }
  double Positive(const std::string& k) const {
    const double v = Number(k);
    if (!(v > 0)) Fail(k, "must be > 0");
    return v;
  }
  Eigen::Vector2d Point(const std::string& k) const {
    const std::string& s = Text(k);
    const auto comma = s.find(',');
    if (comma == std::string::npos) Fail(k, "expected east,north in metres");
    return {Parse(k, s.substr(0, comma)), Parse(k, s.substr(comma + 1))};
  }
  std::string Choice(const std::string& k, const std::string& a, const std::string& b) const {
    if (!Has(k)) return a;
    const std::string& v = Text(k);
    if (v != a && v != b) Fail(k, "expected '" + a + "' or '" + b + "'");
    return v;
  }
  [[noreturn]] void Fail(const std::string& k, const std::string& msg) const {
    cx_.Fail(st_.line, k, msg);
  }

 private:
  const std::string& Text(const std::string& k) const {
    const auto it = st_.fields.find(k);
    if (it == st_.fields.end()) cx_.Fail(st_.line, k, "missing");
    return it->second;
  }
  double Parse(const std::string& k, const std::string& s) const {
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used != s.size() || !std::isfinite(v)) Fail(k, "not a number: '" + s + "'");
    return v;
  }
  const Statement& st_;
  const Context& cx_;
};

// Unit vector of a compass heading (0 = north, 90 = east) in east-north.
Eigen::Vector2d Heading(double heading_deg) {
  return {std::sin(heading_deg * kDegToRad), std::cos(heading_deg * kDegToRad)};
}
Eigen::Vector2d Left(const Eigen::Vector2d& u) { return {-u.y(), u.x()}; }

// Appends an arc of `angle_rad` from the path's last vertex, tangent `t0`, turning left (sign +1)
// or right (−1), in chords of at most `step_m`. Returns the end tangent.
Eigen::Vector2d AppendArc(PlannedPath& path, const Eigen::Vector2d& t0, double radius_m,
                          double sign, double angle_rad, double step_m, int segment) {
  const Eigen::Vector2d start = path.vertex(path.vertex_count() - 1);
  const Eigen::Vector2d n0 = Left(t0);
  const int n = std::max(1, static_cast<int>(std::ceil(radius_m * angle_rad / step_m)));
  for (int k = 1; k <= n; ++k) {
    const double th = angle_rad * k / n;
    path.Append(start + radius_m * std::sin(th) * t0 + sign * radius_m * (1 - std::cos(th)) * n0,
                SegmentKind::kTurn, segment);
  }
  const double c = std::cos(angle_rad), s = std::sin(angle_rad) * sign;
  return {c * t0.x() - s * t0.y(), s * t0.x() + c * t0.y()};
}

// Marks the last vertex as the start of a new segment of `kind`.
void StartSegment(PlannedPath& path, SegmentKind kind, int segment) {
  path.Append(path.vertex(path.vertex_count() - 1), kind, segment);
}

}  // namespace

PathFileError::PathFileError(const std::string& file, int line, const std::string& field,
                             const std::string& message)
    : std::runtime_error(file + ":" + std::to_string(line) + ": field '" + field + "': " + message),
      file_(file),
      line_(line),
      field_(field) {}

namespace {

PlannedPath AbLine(const Statement& st, const Context& cx) {
  const Fields f(st, cx, {"a_m", "b_m", "extend_m"});
  const Eigen::Vector2d a = f.Point("a_m"), b = f.Point("b_m");
  if ((b - a).norm() < 1e-3) f.Fail("b_m", "A and B closer than 1 mm");
  const double ext = f.Number("extend_m", 0.0);
  if (ext < 0) f.Fail("extend_m", "must be >= 0");
  const Eigen::Vector2d u = (b - a).normalized();
  PlannedPath p;
  p.Append(a, SegmentKind::kStraight, 0);
  p.Append(b + ext * u, SegmentKind::kStraight, 0);
  return p;
}

PlannedPath Polyline(const std::vector<Statement>& sts, std::size_t at, const Context& cx) {
  const Fields head(sts[at], cx, {});
  PlannedPath p;
  int vertices = 0;
  for (std::size_t i = at + 1; i < sts.size(); ++i) {
    if (sts[i].keyword != "vertex") cx.Fail(sts[i].line, sts[i].keyword, "expected 'vertex'");
    const Fields f(sts[i], cx, {"p_m"});
    const Eigen::Vector2d v = f.Point("p_m");
    if (vertices > 0 && (v - p.vertex(p.vertex_count() - 1)).norm() < 1e-3)
      f.Fail("p_m", "same as the previous vertex");
    p.Append(v, SegmentKind::kStraight, vertices);
    ++vertices;
  }
  if (vertices < 2) head.Fail("vertex", "a polyline needs at least 2 vertex lines");
  return p;
}

PlannedPath Circle(const Statement& st, const Context& cx) {
  const Fields f(st, cx, {"center_m", "radius_m", "direction", "laps", "step_m"});
  const Eigen::Vector2d c = f.Point("center_m");
  const double r = f.Positive("radius_m");
  const double sign = f.Choice("direction", "ccw", "cw") == "ccw" ? 1.0 : -1.0;
  const double laps = f.Number("laps", 1.0);
  if (!(laps > 0) || laps > 1000) f.Fail("laps", "must be in (0, 1000]");
  const double step = f.Number("step_m", 0.1);
  if (!(step > 0)) f.Fail("step_m", "must be > 0");
  PlannedPath p;
  p.Append(c + Eigen::Vector2d(r, 0), SegmentKind::kTurn, 0);
  AppendArc(p, Eigen::Vector2d(0, sign), r, sign, 2 * std::numbers::pi * laps, step, 0);
  return p;
}

PlannedPath Rectangle(const Statement& st, const Context& cx) {
  const Fields f(
      st, cx,
      {"corner_m", "length_m", "width_m", "heading_deg", "turn", "corner_radius_m", "step_m"});
  const double len = f.Positive("length_m"), wid = f.Positive("width_m");
  const double r = f.Number("corner_radius_m", 0.0);
  if (r < 0 || 2 * r > std::min(len, wid))
    f.Fail("corner_radius_m", "must be in [0, min(length_m, width_m)/2]");
  const double sign = f.Choice("turn", "right", "left") == "left" ? 1.0 : -1.0;
  const double step = f.Number("step_m", 0.1);
  if (!(step > 0)) f.Fail("step_m", "must be > 0");
  Eigen::Vector2d u = Heading(f.Number("heading_deg"));
  PlannedPath p;
  int seg = 0;
  // With rounded corners the loop starts (and ends) r along the first side.
  p.Append(f.Point("corner_m") + r * u, SegmentKind::kStraight, seg);
  const double sides[4] = {len, wid, len, wid};
  for (int k = 0; k < 4; ++k) {
    p.Append(p.vertex(p.vertex_count() - 1) + (sides[k] - 2 * r) * u, SegmentKind::kStraight, seg);
    StartSegment(p, SegmentKind::kTurn, ++seg);
    if (r > 0)
      u = AppendArc(p, u, r, sign, std::numbers::pi / 2, step, seg);
    else
      u = sign > 0 ? Left(u) : Eigen::Vector2d(-Left(u));
    if (k < 3) StartSegment(p, SegmentKind::kStraight, ++seg);
  }
  return p;
}

PlannedPath Boustrophedon(const Statement& st, const Context& cx) {
  const Fields f(st, cx,
                 {"start_m", "heading_deg", "row_length_m", "row_spacing_m", "rows",
                  "turn_radius_m", "first_turn", "step_m"});
  const double len = f.Positive("row_length_m"), spacing = f.Positive("row_spacing_m");
  const double rows_d = f.Number("rows");
  if (rows_d < 1 || rows_d > 10000 || rows_d != std::floor(rows_d))
    f.Fail("rows", "must be a whole number in [1, 10000]");
  const double r = f.Positive("turn_radius_m");
  if (2 * r > spacing + 1e-9)
    f.Fail("turn_radius_m", "must be <= row_spacing_m/2 (omega turns are not supported)");
  double sign = f.Choice("first_turn", "right", "left") == "left" ? 1.0 : -1.0;
  const double step = f.Number("step_m", 0.1);
  if (!(step > 0)) f.Fail("step_m", "must be > 0");
  Eigen::Vector2d u = Heading(f.Number("heading_deg"));
  PlannedPath p;
  int seg = 0;
  p.Append(f.Point("start_m"), SegmentKind::kStraight, seg);
  const int rows = static_cast<int>(rows_d);
  for (int row = 0; row < rows; ++row) {
    p.Append(p.vertex(p.vertex_count() - 1) + len * u, SegmentKind::kStraight, seg);
    if (row + 1 == rows) break;
    StartSegment(p, SegmentKind::kTurn, ++seg);
    u = AppendArc(p, u, r, sign, std::numbers::pi / 2, step, seg);
    p.Append(p.vertex(p.vertex_count() - 1) + (spacing - 2 * r) * u, SegmentKind::kTurn, seg);
    u = AppendArc(p, u, r, sign, std::numbers::pi / 2, step, seg);
    StartSegment(p, SegmentKind::kStraight, ++seg);
    sign = -sign;
  }
  return p;
}

}  // namespace

PlannedPath ParsePathText(std::string_view text, const std::string& name) {
  const Context cx{name};
  const std::vector<Statement> sts = Tokenize(text, cx);
  if (sts.empty() || sts[0].keyword != "hil-path")
    cx.Fail(sts.empty() ? 1 : sts[0].line, "header", "the first line must be 'hil-path 1'");
  if (sts[0].fields.at("version") != "1")
    cx.Fail(sts[0].line, "version", "unsupported version '" + sts[0].fields.at("version") + "'");
  if (sts.size() < 2) cx.Fail(sts[0].line, "shape", "no shape after the header");
  const Statement& shape = sts[1];
  const bool single = shape.keyword != "polyline";
  if (single && sts.size() > 2) cx.Fail(sts[2].line, sts[2].keyword, "one shape per file");
  if (shape.keyword == "ab_line") return AbLine(shape, cx);
  if (shape.keyword == "polyline") return Polyline(sts, 1, cx);
  if (shape.keyword == "circle") return Circle(shape, cx);
  if (shape.keyword == "rectangle") return Rectangle(shape, cx);
  if (shape.keyword == "boustrophedon") return Boustrophedon(shape, cx);
  cx.Fail(shape.line, shape.keyword,
          "unknown shape (ab_line, polyline, circle, rectangle, boustrophedon)");
}

PlannedPath ReadPathFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw PathFileError(path, 0, "file", "cannot be read");
  std::stringstream buffer;
  buffer << in.rdbuf();
  return ParsePathText(buffer.str(), path);
}

}  // namespace hil::estimator::guidance

#include "hil/harness/scenario/path_file_reader.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <initializer_list>
#include <map>
#include <numbers>
#include <sstream>

namespace hil::harness {
namespace {

constexpr double kMaxVertices = 2e6;  // a step_m so small that the path would not fit

struct Line {
  int number = 0;
  std::string keyword;
  std::map<std::string, std::string> fields;
};

[[noreturn]] void Fail(const std::string& file, int line, const std::string& field,
                       const std::string& msg) {
  throw PathFileReadError(file + ":" + std::to_string(line) + ": field '" + field + "': " + msg);
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

// The fields of one statement, checked against those its keyword takes.
class Fields {
 public:
  Fields(const std::string& file, const Line& l, std::initializer_list<const char*> known)
      : file_(file), l_(l) {
    for (const auto& field : l.fields) {
      const std::string& key = field.first;
      if (std::none_of(known.begin(), known.end(), [&](const char* k) { return key == k; }))
        Fail(key, "not a field of '" + l.keyword + "'");
    }
  }
  [[noreturn]] void Fail(const std::string& key, const std::string& msg) const {
    harness::Fail(file_, l_.number, key, msg);
  }
  bool Has(const std::string& key) const { return l_.fields.count(key) > 0; }
  const std::string& Text(const std::string& key) const {
    const auto it = l_.fields.find(key);
    if (it == l_.fields.end()) Fail(key, "missing");
    return it->second;
  }
  double Number(const std::string& key) const {
    const std::string& s = Text(key);
    std::size_t used = 0;
    double v = 0;
    try {
      v = std::stod(s, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (s.empty() || used != s.size() || !std::isfinite(v)) Fail(key, "not a number: '" + s + "'");
    return v;
  }
  double Number(const std::string& key, double fallback) const {
    return Has(key) ? Number(key) : fallback;
  }
  double Positive(const std::string& key) const {
    const double v = Number(key);
    if (!(v > 0)) Fail(key, "must be > 0");
    return v;
  }
  // +1 for `plus`, −1 for `minus`; `fallback` when absent
  double Sign(const std::string& key, const char* plus, const char* minus, double fallback) const {
    if (!Has(key)) return fallback;
    const std::string& s = Text(key);
    if (s == plus) return 1;
    if (s == minus) return -1;
    Fail(key, "expected " + std::string(plus) + " or " + minus + ": '" + s + "'");
  }
  Eigen::Vector2d Point(const std::string& key) const {
    std::istringstream in(Text(key));
    double e = 0, n = 0;
    char comma = 0;
    if (!(in >> e >> comma >> n) || comma != ',' || !in.eof() || !std::isfinite(e) ||
        !std::isfinite(n))
      Fail(key, "expected E,N in metres: '" + Text(key) + "'");
    return {e, n};
  }
  double Step(double path_length_m) const {
    const double step = Number("step_m", 0.1);
    if (!(step > 0)) Fail("step_m", "must be > 0");
    if (path_length_m / step > kMaxVertices) Fail("step_m", "too small for the path's length");
    return step;
  }

 private:
  const std::string& file_;
  const Line& l_;
};

// Unit vector of a compass heading (0 = north, 90 = east) in east-north.
Eigen::Vector2d Compass(double heading_deg) {
  const double a = heading_deg * std::numbers::pi / 180;
  return {std::sin(a), std::cos(a)};
}
Eigen::Vector2d Rotated(const Eigen::Vector2d& u, double angle_rad) {
  const double c = std::cos(angle_rad), s = std::sin(angle_rad);
  return {c * u.x() - s * u.y(), s * u.x() + c * u.y()};
}

// Builds the polyline edge by edge, each edge in the current segment.
class Builder {
 public:
  explicit Builder(const Eigen::Vector2d& start) { g_.vertices = {start}; }
  const Eigen::Vector2d& end() const { return g_.vertices.back(); }
  void Segment(bool turn) { g_.segment_is_turn.push_back(turn); }
  void LineTo(const Eigen::Vector2d& p) {
    if ((p - end()).norm() < 1e-9) return;
    g_.vertices.push_back(p);
    g_.edge_segment.push_back(static_cast<int>(g_.segment_is_turn.size()) - 1);
  }
  // An arc about `centre` from the end, sweeping `angle_rad` (+ counter-clockwise), in
  // ceil(R·|angle| / step) equal chords.
  void ArcAbout(const Eigen::Vector2d& centre, double angle_rad, double step_m) {
    const Eigen::Vector2d r0 = end() - centre;
    const double radius = r0.norm(), a0 = std::atan2(r0.y(), r0.x());
    const int n = std::max(1, static_cast<int>(std::ceil(radius * std::fabs(angle_rad) / step_m)));
    for (int k = 1; k <= n; ++k) {
      const double a = a0 + angle_rad * k / n;
      LineTo(centre + radius * Eigen::Vector2d(std::cos(a), std::sin(a)));
    }
  }
  // A turn of `radius_m` from the end, heading `u`, to the left (sign +1) or the right (−1).
  Eigen::Vector2d Turn(const Eigen::Vector2d& u, double radius_m, double sign, double angle_rad,
                       double step_m) {
    ArcAbout(end() + sign * radius_m * Eigen::Vector2d(-u.y(), u.x()), sign * angle_rad, step_m);
    return Rotated(u, sign * angle_rad);
  }
  PathGeometry Take() { return std::move(g_); }

 private:
  PathGeometry g_;
};

PathGeometry AbLine(const Fields& f) {
  const Eigen::Vector2d a = f.Point("a_m"), b = f.Point("b_m");
  if ((b - a).norm() < 1e-3) f.Fail("b_m", "A and B closer than 1 mm");
  const double extend = f.Number("extend_m", 0);
  if (extend < 0) f.Fail("extend_m", "must be >= 0");
  Builder p(a);
  p.Segment(false);
  p.LineTo(b + (b - a).normalized() * extend);
  return p.Take();
}

PathGeometry Polyline(const std::string& file, const std::vector<Line>& lines) {
  std::vector<Eigen::Vector2d> v;
  for (std::size_t i = 2; i < lines.size(); ++i) {
    if (lines[i].keyword != "vertex") Fail(file, lines[i].number, lines[i].keyword, "not a vertex");
    const Fields f(file, lines[i], {"p_m"});
    v.push_back(f.Point("p_m"));
    if (v.size() > 1 && (v.back() - v[v.size() - 2]).norm() < 1e-3)
      f.Fail("p_m", "same as the previous vertex");
  }
  if (v.size() < 2) Fail(file, lines[1].number, "vertex", "a polyline needs at least 2 vertices");
  Builder p(v[0]);
  for (std::size_t i = 1; i < v.size(); ++i) {
    p.Segment(false);
    p.LineTo(v[i]);
  }
  return p.Take();
}

PathGeometry Circle(const Fields& f) {
  const Eigen::Vector2d c = f.Point("center_m");
  const double r = f.Positive("radius_m");
  const double sign = f.Sign("direction", "ccw", "cw", 1);
  const double laps = f.Number("laps", 1);
  if (!(laps > 0) || laps > 1000) f.Fail("laps", "must be in (0, 1000]");
  const double angle = 2 * std::numbers::pi * laps;
  const double step = f.Step(r * angle);
  Builder p(c + Eigen::Vector2d(r, 0));
  p.Segment(true);
  p.ArcAbout(c, sign * angle, step);
  return p.Take();
}

PathGeometry Rectangle(const Fields& f) {
  const double len = f.Positive("length_m"), wid = f.Positive("width_m");
  const double r = f.Number("corner_radius_m", 0);
  if (r < 0 || 2 * r > std::min(len, wid))
    f.Fail("corner_radius_m", "must be in [0, min(length_m, width_m)/2]");
  const double sign = f.Sign("turn", "left", "right", -1);
  const double step = f.Step(2 * (len + wid));
  Eigen::Vector2d u = Compass(f.Number("heading_deg"));
  Builder p(f.Point("corner_m") + r * u);  // rounded corners: r along the first side
  const double sides[4] = {len, wid, len, wid};
  for (const double side : sides) {
    if (side - 2 * r > 1e-9) {
      p.Segment(false);
      p.LineTo(p.end() + (side - 2 * r) * u);
    }
    if (r > 0) {
      p.Segment(true);
      u = p.Turn(u, r, sign, std::numbers::pi / 2, step);
    } else {
      u = Rotated(u, sign * std::numbers::pi / 2);  // a sharp corner: no segment
    }
  }
  return p.Take();
}

PathGeometry Boustrophedon(const Fields& f) {
  const double len = f.Positive("row_length_m"), spacing = f.Positive("row_spacing_m");
  const double rows = f.Number("rows");
  if (rows < 1 || rows > 10000 || rows != std::floor(rows))
    f.Fail("rows", "must be a whole number in [1, 10000]");
  const double r = f.Positive("turn_radius_m");
  if (2 * r > spacing + 1e-9)
    f.Fail("turn_radius_m", "must be <= row_spacing_m/2 (omega turns are not supported)");
  double sign = f.Sign("first_turn", "left", "right", -1);
  const double step = f.Step(rows * (len + spacing * std::numbers::pi));
  Eigen::Vector2d u = Compass(f.Number("heading_deg"));
  Builder p(f.Point("start_m"));
  for (int row = 0; row < static_cast<int>(rows); ++row) {
    p.Segment(false);
    p.LineTo(p.end() + len * u);
    if (row + 1 == static_cast<int>(rows)) break;
    p.Segment(true);  // the headland turn: quarter arc, straight, quarter arc
    u = p.Turn(u, r, sign, std::numbers::pi / 2, step);
    p.LineTo(p.end() + (spacing - 2 * r) * u);
    u = p.Turn(u, r, sign, std::numbers::pi / 2, step);
    sign = -sign;
  }
  return p.Take();
}

}  // namespace

PathGeometry ReadPathGeometry(const std::string& file) {
  const std::vector<Line> lines = Lines(file);
  if (lines.empty() || lines[0].keyword != "hil-path" || !lines[0].fields.count("1"))
    Fail(file, lines.empty() ? 1 : lines[0].number, "hil-path", "the header 'hil-path 1' first");
  if (lines.size() < 2) Fail(file, lines[0].number, "shape", "no shape after the header");
  const Line& shape = lines[1];
  if (shape.keyword == "polyline") return Polyline(file, lines);
  if (lines.size() > 2) Fail(file, lines[2].number, lines[2].keyword, "one shape per file");
  if (shape.keyword == "ab_line") return AbLine(Fields(file, shape, {"a_m", "b_m", "extend_m"}));
  if (shape.keyword == "circle")
    return Circle(Fields(file, shape, {"center_m", "radius_m", "direction", "laps", "step_m"}));
  if (shape.keyword == "rectangle") {
    return Rectangle(Fields(
        file, shape,
        {"corner_m", "length_m", "width_m", "heading_deg", "turn", "corner_radius_m", "step_m"}));
  }
  if (shape.keyword == "boustrophedon") {
    return Boustrophedon(Fields(file, shape,
                                {"start_m", "heading_deg", "row_length_m", "row_spacing_m", "rows",
                                 "turn_radius_m", "first_turn", "step_m"}));
  }
  Fail(file, shape.number, shape.keyword,
       "unknown shape (ab_line, polyline, circle, rectangle, boustrophedon)");
}

std::vector<Eigen::Vector2d> ReadPathVertices(const std::string& file) {
  return ReadPathGeometry(file).vertices;
}

}  // namespace hil::harness

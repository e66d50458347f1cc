// The scenario's `uwb:` and `wt901c:` sections: paper 003's UWB tag (firmware_emu/uwb) and WT901C
// attitude sensor (firmware_emu/attitude). Format in vectors/scenarios/README.md; the error figures
// and their reasons in vectors/uwb/README.md and vectors/wt901c/README.md.
#include <cmath>

#include "scenario_sections.h"

namespace hil::harness {
namespace {

constexpr double kFieldLimit_m = 10000.0;

Eigen::Vector2d Vec2(const YamlReader& r, const std::string& key, const Eigen::Vector2d& fallback) {
  const auto v = r.Doubles(key, 2, {fallback.x(), fallback.y()});
  return {v[0], v[1]};
}

std::string Link(const YamlReader& r, const std::string& fallback) {
  const std::string link = r.String("link", fallback);
  if (link.empty() || link.find('/') != std::string::npos)
    r.Fail("link", "must be a plain file name such as " + fallback);
  return link;
}

void ReadNlosZones(const YamlReader& r, std::vector<uwb::NlosZone>& zones) {
  for (const YamlReader& e : r.Elements()) {
    e.CheckKeys({"centre_m", "radius_m", "burst_probability", "burst_duration_s", "bias_m",
                 "bias_sigma_m"});
    uwb::NlosZone z;
    z.centre_W_m = Vec2(e, "centre_m", z.centre_W_m);
    z.radius_m = e.DoubleIn("radius_m", z.radius_m, 0.01, 1000);
    z.burst_probability = e.DoubleIn("burst_probability", z.burst_probability, 0, 1);
    z.burst_duration_s = e.DoubleIn("burst_duration_s", z.burst_duration_s, 0.001, 3600);
    z.bias_m = e.DoubleIn("bias_m", z.bias_m, 0, 100);
    z.bias_sigma_m = e.DoubleIn("bias_sigma_m", z.bias_sigma_m, 0, 100);
    zones.push_back(z);
  }
}

// anchors_m: [x1, y1, x2, y2, x3, y3, x4, y4], BS1–BS4 in the ENU plane (m).
void ReadAnchors(const YamlReader& r, uwb::UwbTagConfig& c) {
  std::vector<double> fallback;
  for (const Eigen::Vector2d& a : c.p_W_anchor_m) fallback.insert(fallback.end(), {a.x(), a.y()});
  const std::vector<double> v = r.Doubles("anchors_m", 8, fallback);
  for (double x : v)
    if (!(x >= -kFieldLimit_m && x <= kFieldLimit_m)) r.Fail("anchors_m", "out of range");
  for (std::size_t i = 0; i < 4; ++i) c.p_W_anchor_m[i] = {v[2 * i], v[2 * i + 1]};
  const Eigen::Vector2d e2 = c.p_W_anchor_m[1] - c.p_W_anchor_m[0];
  const Eigen::Vector2d e3 = c.p_W_anchor_m[2] - c.p_W_anchor_m[0];
  if (std::fabs(e2.x() * e3.y() - e2.y() * e3.x()) < 1e-3)
    r.Fail("anchors_m", "BS1, BS2 and BS3 are collinear: no TDOA solution");
}

void ReadUwb(const YamlReader& r, UwbDeviceSpec& u) {
  r.CheckKeys({"link", "baud", "rate_hz", "output", "tag_id", "anchors_m", "anchor_height_m",
               "tag_height_m", "output_latency_s", "systematic_field", "white_sigma_m",
               "residual_sigma_m", "nlos_zones", "tx_buffer_bytes"});
  u.enabled = true;
  uwb::UwbTagConfig& c = u.config;
  u.link = Link(r, u.link);
  c.baud = static_cast<int>(r.Int("baud", c.baud, 1200, 4000000));
  c.rate_hz = r.DoubleIn("rate_hz", c.rate_hz, 1, 50);
  const std::string out = r.Choice("output", "tag_frame0", {"tag_frame0", "tdoa", "both"});
  c.output = out == "tag_frame0" ? uwb::UwbOutput::kTagFrame0
             : out == "tdoa"     ? uwb::UwbOutput::kTdoa
                                 : uwb::UwbOutput::kBoth;
  c.tag_id = static_cast<std::uint8_t>(r.Int("tag_id", 0, 0, 255));
  ReadAnchors(r, c);
  c.anchor_height_m = r.DoubleIn("anchor_height_m", c.anchor_height_m, -100, 100);
  c.tag_height_m = r.DoubleIn("tag_height_m", c.tag_height_m, -100, 100);
  c.output_lag = DurationFromSeconds(r.DoubleIn("output_latency_s", ToSeconds(c.output_lag), 0, 1));
  c.errors.systematic_field = r.Bool("systematic_field", c.errors.systematic_field);
  c.errors.white_sigma_m = Vec2(r, "white_sigma_m", c.errors.white_sigma_m);
  c.errors.residual_sigma_m = Vec2(r, "residual_sigma_m", c.errors.residual_sigma_m);
  for (const Eigen::Vector2d* v : {&c.errors.white_sigma_m, &c.errors.residual_sigma_m})
    if (v->minCoeff() < 0 || v->maxCoeff() > 100)
      r.Fail(v == &c.errors.white_sigma_m ? "white_sigma_m" : "residual_sigma_m",
             "each 1σ must be within [0, 100] m");
  if (auto z = r.OptionalChild("nlos_zones")) ReadNlosZones(*z, c.errors.nlos_zones);
  u.tx_buffer_bytes = static_cast<std::size_t>(
      r.Int("tx_buffer_bytes", static_cast<std::int64_t>(u.tx_buffer_bytes), 128, 1 << 20));
}

void ReadWt901c(const YamlReader& r, Wt901cDeviceSpec& w) {
  r.CheckKeys({"link", "baud", "rate_hz", "require_unlock", "gyro_bias_sigma_dps",
               "angle_noise_sigma_deg", "yaw_drift_sigma_dps", "tx_buffer_bytes"});
  w.enabled = true;
  wit::Wt901cConfig& c = w.config;
  w.link = Link(r, w.link);
  const auto baud = r.Int("baud", 9600, 4800, 921600);
  c.baud_code = 0;
  for (std::uint16_t code = 1; code <= 9; ++code)
    if (wit::BaudOfCode(code) == baud) c.baud_code = code;
  if (c.baud_code == 0)
    r.Fail("baud", "not a WT901C baud (4800 … 921600, BAUD register codes 1–9)");
  const double rate = r.DoubleIn("rate_hz", 10, 0.2, 200);
  c.rrate_code = 0;
  for (std::uint16_t code = 1; code <= 0x0B; ++code)
    if (wit::RateHzOfCode(code) == rate) c.rrate_code = code;
  if (c.rrate_code == 0)
    r.Fail("rate_hz", "not an RRATE value (0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 125, 200 Hz)");
  c.require_unlock = r.Bool("require_unlock", c.require_unlock);
  c.errors.gyro_turn_on_bias_sigma_dps =
      r.DoubleIn("gyro_bias_sigma_dps", c.errors.gyro_turn_on_bias_sigma_dps, 0, 10);
  c.errors.angle_noise_sigma_deg =
      r.DoubleIn("angle_noise_sigma_deg", c.errors.angle_noise_sigma_deg, 0, 10);
  c.errors.yaw_drift_sigma_dps =
      r.DoubleIn("yaw_drift_sigma_dps", c.errors.yaw_drift_sigma_dps, 0, 10);
  w.tx_buffer_bytes = static_cast<std::size_t>(
      r.Int("tx_buffer_bytes", static_cast<std::int64_t>(w.tx_buffer_bytes), 64, 1 << 20));
}

}  // namespace

const std::vector<std::string> kPaper003SectionKeys{"uwb", "wt901c"};

void ReadPaper003Sections(const YamlReader& root, UwbDeviceSpec& u, Wt901cDeviceSpec& w) {
  if (auto r = root.OptionalChild("uwb")) ReadUwb(*r, u);
  if (auto r = root.OptionalChild("wt901c")) ReadWt901c(*r, w);
}

}  // namespace hil::harness

// The scenario's `uwb:` section: the UWB tag (firmware_emu/uwb; paper 003's LinkTrack). Format in
// vectors/scenarios/README.md; the error figures and their reasons in vectors/uwb/README.md.
#include <cmath>

#include "uwb_tag.h"

namespace hil::harness {
namespace {

constexpr double kFieldLimit_m = 10000.0;

Eigen::Vector2d Vec2(const YamlReader& r, const std::string& key, const Eigen::Vector2d& fallback) {
  const auto v = r.Doubles(key, 2, {fallback.x(), fallback.y()});
  return {v[0], v[1]};
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
  u.link = ReadLinkName(r, u.link);
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

}  // namespace

void ReadUwbTagSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("uwb")) ReadUwb(*r, s.uwb);
}

}  // namespace hil::harness

// The scenario's `uwb:` section: the UWB tag (firmware_emu/uwb; paper 003's LinkTrack). Format in
// vectors/scenarios/README.md; the error figures and their reasons in vectors/uwb/README.md.
#include <array>
#include <cmath>
#include <string_view>

#include "uwb_tag.h"

namespace hil::harness {
namespace uwb_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::array<std::string_view, 3> kOutputs{"tag_frame0", "tdoa", "both"};

inline constexpr ScenarioKey kUwb[] = {
    {"link", kString, "", "ttyUWB", 0, 0, "its pty in the run folder (a plain file name)"},
    {"baud", kInteger, "Bd", "921600", 1200, 4000000, "the line rate (Nooploop's ROS default)"},
    {"rate_hz", kNumber, "Hz", "5", 1, 50, "fix rate (paper 003's sampling frequency)"},
    {"output", kChoice, "", "tag_frame0", 0, 0,
     "LinkTrack Tag_Frame0 positions, TDOA frames, or both (vectors/uwb/README.md)", kOutputs},
    {"tag_id", kInteger, "", "0", 0, 255, "the tag's id in its frames"},
    {"anchors_m", kPoint, "m", "[-10, -10, 10, -10, 10, 10, -10, 10]", 0, 0,
     "BS1–BS4 as [x1, y1, … x4, y4] in the ENU plane (within 10 km; BS1–BS3 not collinear); the "
     "default is a 20 m square (paper 003 prints no coordinates)"},
    {"anchor_height_m", kNumber, "m", "1.6", -100, 100, "the anchors' height"},
    {"tag_height_m", kNumber, "m", "1.6", -100, 100, "the tag's height"},
    {"output_latency_s", kNumber, "s", "0.005", 0, 1, "fix epoch to its first byte"},
    {"systematic_field", kBool, "", "true", 0, 0, "apply paper 003's Table 1 error field"},
    {"white_sigma_m", kPoint, "m", "[0.045, 0.045]", 0, 0,
     "white noise per fix, [x, y] (1σ, each within [0, 100])"},
    {"residual_sigma_m", kPoint, "m", "[0.035, 0.060]", 0, 0,
     "static residual error field, [x, y] (1σ, each within [0, 100])"},
    {"nlos_zones", kList, "", "none", 0, 0,
     "zones where an anchor is blocked in bursts (uwb.nlos_zones[])"},
    {"tx_buffer_bytes", kInteger, "B", "4096", 128, 1 << 20, "its UART's transmit buffer"},
};

inline constexpr ScenarioKey kNlosZone[] = {
    {"centre_m", kPoint, "m", "[0, 0]", 0, 0, "the zone's centre [x, y]"},
    {"radius_m", kNumber, "m", "1", 0.01, 1000, "its radius"},
    {"burst_probability", kNumber, "", "0.1", 0, 1,
     "chance per fix inside the zone that a burst starts"},
    {"burst_duration_s", kNumber, "s", "1", 0.001, 3600, "a burst's length"},
    {"bias_m", kNumber, "m", "0.3", 0, 100, "mean extra range of the blocked anchor"},
    {"bias_sigma_m", kNumber, "m", "0.1", 0, 100,
     "spread of that bias (half-normal added to the mean)"},
};

}  // namespace uwb_keys

extern const KeySection kUwbSection{"uwb", "paper 003's UWB tag (LinkTrack; vectors/uwb/README.md)",
                                    uwb_keys::kUwb};
extern const KeySection kNlosZoneSection{"uwb.nlos_zones[]", "one NLOS zone", uwb_keys::kNlosZone};

namespace {

using uwb_keys::kNlosZone;
using uwb_keys::kUwb;

constexpr double kFieldLimit_m = 10000.0;

template <const auto& T>
Eigen::Vector2d Vec2(const KeyedReader<T>& r, typename KeyedReader<T>::Key key,
                     const Eigen::Vector2d& fallback) {
  const auto v = r.Doubles(key, 2, {fallback.x(), fallback.y()});
  return {v[0], v[1]};
}

void ReadNlosZones(const YamlReader& r, std::vector<uwb::NlosZone>& zones) {
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kNlosZone> e(y);
    e.CheckKeys();
    uwb::NlosZone z;
    z.centre_W_m = Vec2(e, "centre_m", z.centre_W_m);
    z.radius_m = e.Number("radius_m", z.radius_m);
    z.burst_probability = e.Number("burst_probability", z.burst_probability);
    z.burst_duration_s = e.Number("burst_duration_s", z.burst_duration_s);
    z.bias_m = e.Number("bias_m", z.bias_m);
    z.bias_sigma_m = e.Number("bias_sigma_m", z.bias_sigma_m);
    zones.push_back(z);
  }
}

// anchors_m: [x1, y1, x2, y2, x3, y3, x4, y4], BS1–BS4 in the ENU plane (m).
void ReadAnchors(const KeyedReader<kUwb>& r, uwb::UwbTagConfig& c) {
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

void ReadUwb(const YamlReader& y, UwbDeviceSpec& u) {
  const KeyedReader<kUwb> r(y);
  r.CheckKeys();
  u.enabled = true;
  uwb::UwbTagConfig& c = u.config;
  u.link = ReadLinkName(r, u.link);
  c.baud = static_cast<int>(r.Integer("baud", c.baud));
  c.rate_hz = r.Number("rate_hz", c.rate_hz);
  const std::string out = r.Choice("output", "tag_frame0");
  c.output = out == "tag_frame0" ? uwb::UwbOutput::kTagFrame0
             : out == "tdoa"     ? uwb::UwbOutput::kTdoa
                                 : uwb::UwbOutput::kBoth;
  c.tag_id = static_cast<std::uint8_t>(r.Integer("tag_id", 0));
  ReadAnchors(r, c);
  c.anchor_height_m = r.Number("anchor_height_m", c.anchor_height_m);
  c.tag_height_m = r.Number("tag_height_m", c.tag_height_m);
  c.output_lag = DurationFromSeconds(r.Number("output_latency_s", ToSeconds(c.output_lag)));
  c.errors.systematic_field = r.Bool("systematic_field", c.errors.systematic_field);
  c.errors.white_sigma_m = Vec2(r, "white_sigma_m", c.errors.white_sigma_m);
  c.errors.residual_sigma_m = Vec2(r, "residual_sigma_m", c.errors.residual_sigma_m);
  for (const Eigen::Vector2d* v : {&c.errors.white_sigma_m, &c.errors.residual_sigma_m}) {
    if (v->minCoeff() < 0 || v->maxCoeff() > 100) {
      if (v == &c.errors.white_sigma_m)
        r.Fail("white_sigma_m", "each 1σ must be within [0, 100] m");
      r.Fail("residual_sigma_m", "each 1σ must be within [0, 100] m");
    }
  }
  if (auto z = r.OptionalChild("nlos_zones")) ReadNlosZones(*z, c.errors.nlos_zones);
  u.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(u.tx_buffer_bytes)));
}

}  // namespace

void ReadUwbTagSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("uwb")) ReadUwb(*r, s.uwb);
}

}  // namespace hil::harness

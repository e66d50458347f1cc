// The `rangefinders:` section: paper 001's four Benewake rangefinders, each on a pty, cast against
// the `greenhouse:` map. Models, mounts and rates are scenario parameters (the paper gives none,
// seeds_001_003.md A.5, A.14); defaults in vectors/scenarios/README.md.
#include <array>
#include <cstdint>
#include <string_view>

#include "rangefinders.h"

namespace hil::harness {
namespace rangefinders_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::array<std::string_view, 2> kModels{"tf_luna", "tfmini_s"};
inline constexpr std::array<std::string_view, 2> kFormats{"cm", "mm"};

inline constexpr ScenarioKey kRangefinders[] = {
    {"model", kChoice, "", "tf_luna", 0, 0,
     "Benewake TF-Luna, or TFmini-S (its invalid codes: −1, −2)", kModels},
    {"baud", kInteger, "Bd", "115200", 9600, 921600,
     "the modules' power-up baud (one of the TF-Luna manual's)"},
    {"rate_hz", kInteger, "Hz", "100", 1, 250, "the modules' power-up frame rate"},
    {"format", kChoice, "", "cm", 0, 0, "output format: 9-byte cm, or mm (format 0x06)", kFormats},
    {"units", kList, "",
     "four: 0.2 m ahead and behind, 0.25 m either side, 0.15 m up, looking "
     "square to each side",
     0, 0, "the units (rangefinders.units[])"},
    {"reflectivity", kMapping, "", "ridge 0.25, post 0.5, wall 0.05", 0, 0,
     "what the beams see (as lidar.reflectivity)"},
    {"tx_buffer_bytes", kInteger, "B", "4096", 64, 1 << 20, "each unit's UART transmit buffer"},
};

inline constexpr ScenarioKey kUnit[] = {
    {"name", kString, "", "required", 0, 0, "the unit's name (unique)"},
    {"link", kString, "", "ttyRF_<name>", 0, 0, "its pty in the run folder (unique)"},
    {"mount_m", kPoint, "m", "[0, 0, 0.15]", 0, 0,
     "[x, y, z] in the body frame FLU (z ≥ 0: its height above the floor)"},
    {"yaw_deg", kNumber, "deg", "-90", -360, 360,
     "its beam's direction, counter-clockwise from forward"},
};

}  // namespace rangefinders_keys

extern const KeySection kRangefindersSection{
    "rangefinders",
    "paper 001's Benewake rangefinders, each on a pty, cast against the greenhouse (needs "
    "greenhouse)",
    rangefinders_keys::kRangefinders};
extern const KeySection kRangefinderUnitSection{"rangefinders.units[]", "one unit",
                                                rangefinders_keys::kUnit};

namespace {

using rangefinders_keys::kRangefinders;
using rangefinders_keys::kUnit;

// The default layout (this project's choice): the units 0.4 m apart (p_dist), 0.25 m either side
// of the centre line, 0.15 m above the floor (below the ridge tops), looking square to each side.
std::vector<RangefinderUnitSpec> DefaultUnits() {
  auto unit = [](const char* name, const char* link, double x, double y, double yaw) {
    return RangefinderUnitSpec{name, link, {x, y, 0.15, yaw}};
  };
  return {unit("right_front", "ttyRF_RF", 0.2, -0.25, -90),
          unit("right_rear", "ttyRF_RR", -0.2, -0.25, -90),
          unit("left_front", "ttyRF_LF", 0.2, 0.25, 90),
          unit("left_rear", "ttyRF_LR", -0.2, 0.25, 90)};
}

std::vector<RangefinderUnitSpec> ReadUnits(const YamlReader& r) {
  std::vector<RangefinderUnitSpec> units;
  for (const YamlReader& y : r.Elements()) {
    const KeyedReader<kUnit> u(y);
    u.CheckKeys();
    RangefinderUnitSpec spec;
    spec.name = u.String("name");
    spec.link = u.String("link", "ttyRF_" + spec.name);
    const std::vector<double> m = u.Doubles("mount_m", 3, {0, 0, 0.15});
    spec.mount = {m[0], m[1], m[2], u.Number("yaw_deg", -90)};
    if (m[2] < 0) u.Fail("mount_m", "the height must not be negative");
    for (const auto& other : units) {
      if (other.name == spec.name) u.Fail("name", "two units named '" + spec.name + "'");
      if (other.link == spec.link) u.Fail("link", "two units on link '" + spec.link + "'");
    }
    units.push_back(spec);
  }
  if (units.empty()) r.Fail("needs at least one unit");
  return units;
}

void ReadRangefinders(const YamlReader& y, RangefinderSpec& spec) {
  const KeyedReader<kRangefinders> r(y);
  r.CheckKeys();
  spec.enabled = true;
  rangefinder::TfLunaConfig& m = spec.module;
  m.model.model = r.Choice("model", "tf_luna") == "tf_luna" ? rangefinder::ModuleModel::kTfLuna
                                                            : rangefinder::ModuleModel::kTfminiS;
  m.settings.baud = static_cast<std::uint32_t>(r.Integer("baud", 115200));
  if (!rangefinder::IsSupportedBaud(m.settings.baud))
    r.Fail("baud", "not a baud rate of the TF-Luna manual");
  m.settings.frame_rate_hz = static_cast<std::uint16_t>(r.Integer("rate_hz", 100));
  m.settings.format = r.Choice("format", "cm") == "cm" ? rangefinder::OutputFormat::kCm9Byte
                                                       : rangefinder::OutputFormat::kMm9Byte;
  if (auto f = r.OptionalChild("reflectivity")) ReadSurfaceReflectivity(*f, m.reflectivity);
  spec.units = r.Has("units") ? ReadUnits(r.Child("units")) : DefaultUnits();
  spec.tx_buffer_bytes = static_cast<std::size_t>(r.Integer("tx_buffer_bytes", 4096));
}

}  // namespace

void ReadRangefindersSpec(const YamlReader& root, Scenario& s) {
  if (root.Has("rangefinders") && !s.greenhouse)
    root.Fail("rangefinders", "needs a greenhouse: section to sense");
  if (auto r = root.OptionalChild("rangefinders")) ReadRangefinders(*r, s.rangefinders);
}

}  // namespace hil::harness

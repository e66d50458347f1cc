// The rangefinders' row of the device table: section `rangefinders:`, one TfLunaDevice per unit,
// each on its own pty, casting against the scenario's greenhouse (paper 001).
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include "rangefinders.h"

namespace hil::harness {
namespace {

constexpr std::uint64_t kUnitStride = 104729;  // each rangefinder unit's own stream

void BuildRangefinders(const Scenario& s, std::uint64_t seed, const std::string& dir,
                       DeviceBuild& set) {
  if (!s.greenhouse || !s.rangefinders.enabled) return;
  const world::GreenhouseWorld& world = GreenhouseWorldOf(s, set);
  for (std::size_t i = 0; i < s.rangefinders.units.size(); ++i) {
    const RangefinderUnitSpec& u = s.rangefinders.units[i];
    rangefinder::TfLunaConfig cfg = s.rangefinders.module;
    cfg.name = "rf_" + u.name;
    cfg.mount = u.mount;
    AddSerialDevice(std::make_unique<rangefinder::TfLunaDevice>(cfg, world, seed + kUnitStride * i),
                    u.link, s.rangefinders.tx_buffer_bytes, dir, set);
  }
}

std::vector<std::string> RangefinderLinks(const Scenario& s) {
  std::vector<std::string> links;
  if (!s.rangefinders.enabled) return links;
  for (const RangefinderUnitSpec& u : s.rangefinders.units) links.push_back(u.link);
  return links;
}

constexpr std::string_view kRangefindersSections[] = {"rangefinders"};

// The header's line: how many units.
std::string RangefindersProfile(const Scenario& s) {
  return ProfileText("%zu TF-Luna laser rangefinder(s)", s.rangefinders.units.size());
}

}  // namespace

extern const DeviceKind kRangefindersKind;
const DeviceKind kRangefindersKind{.name = "rangefinders",
                                   .sections = kRangefindersSections,
                                   .spec = "rangefinders: (needs greenhouse:)",
                                   .read = ReadRangefindersSpec,
                                   .seed_stream = 5,
                                   .build = BuildRangefinders,
                                   .navd_keys = {},
                                   .write_navd = nullptr,
                                   .links = RangefinderLinks,
                                   .navd_links = nullptr,
                                   .report_section = "link_integrity",
                                   .link_role = "",
                                   .profile = RangefindersProfile};

}  // namespace hil::harness

// The WT901C's row of the device table: section `wt901c:`, a Wt901cDevice on its own pty
// (RUN_DIR/ttyWIT by default); navd's UWB mode reads it as its attitude device ([uwb] attitude_*).
#include <filesystem>

#include "hil/firmware_emu/attitude/wt901c_device.h"

#include "wt901c.h"

namespace hil::harness {
namespace {

void BuildWt901c(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.wt901c.enabled) return;
  auto dev = std::make_unique<wit::Wt901cDevice>(s.wt901c.config, seed);
  const int baud = dev->baud(0);
  AddSerialDevice(std::move(dev), s.wt901c.link, s.wt901c.tx_buffer_bytes, dir, set, baud);
}

// After the UWB tag's [uwb] lines (the row before this one).
void WriteWt901cNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                     std::ostream& out) {
  if (slot != NavdConfSlot::kSections || s.estimator.navd_mode != NavdMode::kUwb) return;
  if (!s.wt901c.enabled) return;
  const std::filesystem::path dir = std::filesystem::path(gnss_device).parent_path();
  out << "attitude_device = " << (dir / s.wt901c.link).string()
      << "\nattitude_baud = " << wit::BaudOfCode(s.wt901c.config.baud_code)
      << "\nattitude_rate_hz = " << wit::RateHzOfCode(s.wt901c.config.rrate_code) << "\n";
}

std::vector<std::string> Wt901cLinks(const Scenario& s) {
  if (!s.wt901c.enabled) return {};
  return {s.wt901c.link};
}

constexpr std::string_view kWt901cSections[] = {"wt901c"};
constexpr std::string_view kWt901cNavdKeys[] = {"uwb.attitude_device", "uwb.attitude_baud",
                                                "uwb.attitude_rate_hz"};

// navd's UWB mode reads the WT901C beside the tag.
std::vector<std::string> Wt901cNavdLinks(const Scenario& s) {
  if (s.estimator.navd_mode != NavdMode::kUwb || !s.wt901c.enabled) return {};
  return {s.wt901c.link};
}

// The header's line: the output rate its RRATE register sets.
std::string Wt901cProfile(const Scenario& s) {
  return ProfileText("WitMotion WT901C, %g Hz (RRATE 0x%02X), BAUD code 0x%02X",
                     wit::RateHzOfCode(s.wt901c.config.rrate_code), s.wt901c.config.rrate_code,
                     s.wt901c.config.baud_code);
}

}  // namespace

extern const DeviceKind kWt901cKind;
const DeviceKind kWt901cKind{.name = "wt901c",
                             .sections = kWt901cSections,
                             .spec = "wt901c:",
                             .read = ReadWt901cSpec,
                             .seed_stream = 4,
                             .build = BuildWt901c,
                             .navd_keys = kWt901cNavdKeys,
                             .write_navd = WriteWt901cNavd,
                             .links = Wt901cLinks,
                             .navd_links = Wt901cNavdLinks,
                             .report_section = "link_integrity",
                             .link_role = "",
                             .profile = Wt901cProfile};

}  // namespace hil::harness

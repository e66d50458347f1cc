// The UWB tag's row of the device table: section `uwb:`, a UwbTagDevice on its own pty
// (RUN_DIR/ttyUWB by default), navd's [uwb] section.
#include "hil/firmware_emu/uwb/uwb_tag_device.h"

#include "uwb_tag.h"

namespace hil::harness {
namespace {

void BuildUwbTag(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.uwb.enabled) return;
  auto dev = std::make_unique<uwb::UwbTagDevice>(s.uwb.config, seed);
  const int baud = dev->baud(0);
  AddSerialDevice(std::move(dev), s.uwb.link, s.uwb.tx_buffer_bytes, dir, set, baud);
}

std::vector<std::string> UwbTagLinks(const Scenario& s) {
  if (!s.uwb.enabled) return {};
  return {s.uwb.link};
}

constexpr std::string_view kUwbTagSections[] = {"uwb"};
constexpr std::string_view kUwbTagNavdKeys[] = {
    "uwb.device",         "uwb.baud",           "uwb.format",          "uwb.anchors_m",
    "uwb.origin_lat_deg", "uwb.origin_lon_deg", "uwb.origin_height_m", "uwb.time_zero_unix_ns"};

// navd's UWB mode reads the tag (and the WT901C) only.
std::vector<std::string> UwbTagNavdLinks(const Scenario& s) {
  if (s.estimator.navd_mode != NavdMode::kUwb) return {};
  return {s.uwb.link};
}

// The header's line: the tag's rate and baud.
std::string UwbTagProfile(const Scenario& s) {
  return ProfileText("Nooploop LinkTrack tag, %g Hz, %d Bd, 4 anchors", s.uwb.config.rate_hz,
                     s.uwb.config.baud);
}

}  // namespace

extern const DeviceKind kUwbTagKind;
const DeviceKind kUwbTagKind{.name = "uwb_tag",
                             .sections = kUwbTagSections,
                             .spec = "uwb:",
                             .read = ReadUwbTagSpec,
                             .seed_stream = 3,
                             .build = BuildUwbTag,
                             .navd_keys = kUwbTagNavdKeys,
                             .write_navd = WriteUwbTagNavd,
                             .links = UwbTagLinks,
                             .navd_links = UwbTagNavdLinks,
                             .report_section = "link_integrity",
                             .link_role = "",
                             .profile = UwbTagProfile};

}  // namespace hil::harness

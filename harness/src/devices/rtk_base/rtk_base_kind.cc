// The RTK base's row of the device table: section `rtk_base:`, its RTCM 3 stream, after the
// correction radio, on its own pty with a capture, as a radio modem's UART would deliver it to
// the rover (RUN_DIR/ttyRTCM by default). navd does not read it: an RTK rover takes it.
#include "hil/firmware_emu/rtk/rtk_base_device.h"

#include "rtk_base.h"

namespace hil::harness {
namespace {

void BuildRtkBase(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.rtk_base.enabled) return;
  AddSerialDevice(std::make_unique<rtk::RtkBaseDevice>(s.rtk_base.config, seed), s.rtk_base.link,
                  s.rtk_base.tx_buffer_bytes, dir, set);
}

std::vector<std::string> RtkBaseLinks(const Scenario& s) {
  if (!s.rtk_base.enabled) return {};
  return {s.rtk_base.link};
}

constexpr std::string_view kRtkBaseSections[] = {"rtk_base"};

// The header's line: the station, its messages and the radio's rate.
std::string RtkBaseProfile(const Scenario& s) {
  const auto& c = s.rtk_base.config;
  return ProfileText("RTCM 3 station %d, MSM%d, %d, %g Hz, radio %d Bd", c.station_id,
                     static_cast<int>(c.msm), c.station_message, c.obs_rate_hz, c.baud);
}

}  // namespace

extern const DeviceKind kRtkBaseKind;
const DeviceKind kRtkBaseKind{.name = "rtk_base",
                              .sections = kRtkBaseSections,
                              .spec = "rtk_base: (reference station and correction radio)",
                              .read = ReadRtkBaseSpec,
                              .seed_stream = 8,
                              .build = BuildRtkBase,
                              .navd_keys = {},
                              .write_navd = nullptr,
                              .links = RtkBaseLinks,
                              .navd_links = nullptr,
                              .report_section = "link_integrity",
                              .link_role = "",
                              .profile = RtkBaseProfile};

}  // namespace hil::harness

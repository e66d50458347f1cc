// The ZED-F9P rover's row of the device table: section `zed_f9p:`, a ZedF9pDevice on its own pty
// (RUN_DIR/ttyF9P by default) with its capture; its UART2 takes the rtk_base's radio stream
// (corrections: radio). navd does not read it (navd reads the `gnss` receivers).
#include "hil/firmware_emu/rtk/zed_f9p_device.h"

#include "zed_f9p.h"

namespace hil::harness {

extern const DeviceKind kRtkBaseKind;
extern const DeviceKind kZedF9pKind;

namespace {

void BuildZedF9p(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.zed_f9p.enabled) return;
  rtk::ZedF9pConfig c = s.zed_f9p.config;
  if (s.zed_f9p.corrections == F9pCorrections::kRadio) {
    // the base device's own seed (device_set.cc: run seed × stride + its stream), so the radio
    // stream on UART2 is the bytes of RUN_DIR/ttyRTCM
    c.radio_base = s.rtk_base.config;
    c.radio_base_seed = seed - kZedF9pKind.seed_stream + kRtkBaseKind.seed_stream;
  }
  for (const Fault& f : s.faults.faults) {  // the scenario's GNSS outages reach the rover too
    if (f.kind == FaultKind::kGnssOutage) c.sky_outages.emplace_back(f.start, f.end);
  }
  auto dev = std::make_unique<rtk::ZedF9pDevice>(c, seed);
  set.rover = dev.get();
  AddSerialDevice(std::move(dev), s.zed_f9p.link, s.zed_f9p.tx_buffer_bytes, dir, set);
}

std::vector<std::string> ZedF9pLinks(const Scenario& s) {
  if (!s.zed_f9p.enabled) return {};
  return {s.zed_f9p.link};
}

constexpr std::string_view kZedF9pSections[] = {"zed_f9p"};

std::string ZedF9pProfile(const Scenario& s) {
  const char* src = s.zed_f9p.corrections == F9pCorrections::kRadio  ? "base radio on UART2"
                    : s.zed_f9p.corrections == F9pCorrections::kHost ? "host RTCM on UART1"
                    : s.zed_f9p.corrections == F9pCorrections::kMovingBase
                        ? "moving base on UART2 (dual-antenna heading)"
                        : "no corrections";
  return ProfileText("u-blox ZED-F9P class (HPG 1.32, protocol 27.31), %s; fix %g s, age %g s", src,
                     s.zed_f9p.config.rtk.time_to_fix_s, s.zed_f9p.config.rtk.fixed_max_age_s);
}

}  // namespace

const DeviceKind kZedF9pKind{.name = "zed_f9p",
                             .sections = kZedF9pSections,
                             .spec = "zed_f9p: (RTK rover, UBX protocol 27+)",
                             .read = ReadZedF9pSpec,
                             .seed_stream = 9,
                             .build = BuildZedF9p,
                             .navd_keys = {},
                             .write_navd = nullptr,
                             .links = ZedF9pLinks,
                             .navd_links = nullptr,
                             .report_section = "rtk_rover",
                             .link_role = "",
                             .profile = ZedF9pProfile};

}  // namespace hil::harness

// The ZED-F9P rover's row of the device table: section `zed_f9p:`, a ZedF9pDevice on its own pty
// (RUN_DIR/ttyF9P by default) with its capture; its UART2 takes the rtk_base's radio stream
// (corrections: radio). When the scenario's navd reads it (navd_gnss_source.h: the rover unless
// `navd_input: false`) it writes navd's [input] gnss_device and gnss_baud, navd reads its NMEA
// (GGA quality 4/5 with navd's RTK σ's) and its fixes are the raw-fix baseline.
#include <filesystem>

#include "hil/firmware_emu/rtk/zed_f9p_device.h"
#include "hil/harness/scenario/navd_gnss_source.h"

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
  if (NavdReadsRover(s)) {  // the raw-fix baseline reads the first source: the rover's fixes
    const rtk::ZedF9pDevice* raw = dev.get();
    set.fix_sources.insert(set.fix_sources.begin(), [raw] { return &raw->last_fix(); });
  }
  AddSerialDevice(std::move(dev), s.zed_f9p.link, s.zed_f9p.tx_buffer_bytes, dir, set);
}

std::vector<std::string> ZedF9pLinks(const Scenario& s) {
  if (!s.zed_f9p.enabled) return {};
  return {s.zed_f9p.link};
}

// UART1's line rate as saved in Flash (CFG-UART1-BAUDRATE), else the receiver's default.
std::int64_t Uart1Baud(const Scenario& s) {
  const std::uint32_t id = gnss::ubx::f9key::kUart1Baudrate;
  std::int64_t baud = static_cast<std::int64_t>(gnss::ubx::FindF9Key(id)->default_value);
  for (const auto& [key, value] : s.zed_f9p.config.flash) {
    if (key == id) baud = static_cast<std::int64_t>(value);
  }
  return baud;
}

// [input] gnss_device and gnss_baud: the rover's link and UART1 rate, when navd reads it (the
// gnss receivers' row then writes neither).
void WriteZedF9pNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                     std::ostream& out) {
  if (slot != NavdConfSlot::kInput || !NavdReadsRover(s)) return;
  const std::filesystem::path dir = std::filesystem::path(gnss_device).parent_path();
  out << "gnss_device = " << (dir / s.zed_f9p.link).string() << "\ngnss_baud = " << Uart1Baud(s)
      << "\n";
}

std::vector<std::string> ZedF9pNavdLinks(const Scenario& s) {
  if (!NavdReadsRover(s)) return {};
  return {s.zed_f9p.link};
}

constexpr std::string_view kZedF9pSections[] = {"zed_f9p"};
constexpr std::string_view kZedF9pNavdKeys[] = {"input.gnss_device", "input.gnss_baud"};

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
                             .navd_keys = kZedF9pNavdKeys,
                             .write_navd = WriteZedF9pNavd,
                             .links = ZedF9pLinks,
                             .navd_links = ZedF9pNavdLinks,
                             .report_section = "rtk_rover",
                             .link_role = "gnss",
                             .profile = ZedF9pProfile};

}  // namespace hil::harness

// The IMU board's row of the device table: section `mcu:`, an McuDevice on one serial link
// (RUN_DIR/<link>, e.g. ttyIMU) whose CAN frames leave through DeviceOutput::can; navd reads its
// binary frames from the link ([input] imu_*) or its J1939 frames from the bus ([imu]).
#include <filesystem>

#include "hil/firmware_emu/mcu/mcu_device.h"
#include "hil/harness/scenario/navd_gnss_source.h"

#include "mcu.h"

namespace hil::harness {
namespace {

void BuildMcu(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.mcu.enabled) return;
  mcu::McuConfig cfg = s.mcu.config;
  cfg.start_utc = s.start_utc;
  // the scenario's global fault timeline: an mcu_reset keeps the MCU silent until its end
  for (const Fault& f : s.faults.OfKind(FaultKind::kMcuReset)) {
    mcu::McuFault r;
    r.kind = mcu::FaultKind::kReset;
    r.start = f.start;
    r.duration = f.end - f.start;
    cfg.faults.push_back(r);
  }
  AddSerialDevice(std::make_unique<mcu::McuDevice>(cfg, seed), s.mcu.link, s.mcu.tx_buffer_bytes,
                  dir, set, cfg.baud);
}

// navd reads the board's binary frames (the Razor text formats are for third-party hosts), from
// the bus when the scenario sends them there.
bool NavdReadsCan(const Scenario& s) { return s.mcu.enabled && s.can.imu_to_estimator; }
bool NavdReadsImu(const Scenario& s) {
  return NavdReadsCan(s) || (s.mcu.enabled && s.mcu.config.format == mcu::SerialFormat::kBinary);
}

// [input] imu_* (or [imu] for CAN) after gnss_baud; [filter] lever_arm_m: navd's body origin is
// the IMU, so the antenna of the receiver navd reads (navd_gnss_source.h) relative to the board.
void WriteMcuNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                  std::ostream& out) {
  const bool odometry = s.estimator.navd_mode == NavdMode::kGyroOdometry;  // [odometry] instead
  if (slot == NavdConfSlot::kInput && NavdReadsCan(s)) {
    out << "\n[imu]\nsource = can\ncan_interface = " << s.can.interface << "\nsource_address = "
        << static_cast<int>(s.mcu.config.can.address.source_address) << "\n";
  } else if (slot == NavdConfSlot::kInput && NavdReadsImu(s)) {
    const std::filesystem::path dir = std::filesystem::path(gnss_device).parent_path();
    out << "imu_device = " << (dir / s.mcu.link).string() << "\nimu_baud = " << s.mcu.config.baud
        << "\nimu_format = mcu\n";
  } else if (slot == NavdConfSlot::kFilter && NavdReadsImu(s) && !odometry) {
    const Eigen::Vector3d lever = NavdAntennaB(s) - s.mcu.config.mounting.p_BI_B_m;
    out << "lever_arm_m = " << lever.x() << ", " << lever.y() << ", " << lever.z() << "\n";
  }
}

std::vector<std::string> McuLinks(const Scenario& s) {
  if (!s.mcu.enabled) return {};
  return {s.mcu.link};
}

constexpr std::string_view kMcuSections[] = {"mcu"};
constexpr std::string_view kMcuNavdKeys[] = {
    "input.imu_device",  "input.imu_baud",     "input.imu_format",  "imu.source",
    "imu.can_interface", "imu.source_address", "filter.lever_arm_m"};

// navd's odometry mode reads the board (and the FIFO) only; its fusing modes read it on its serial
// link unless the frames go to it over CAN.
std::vector<std::string> McuNavdLinks(const Scenario& s) {
  const NavdMode m = s.estimator.navd_mode;
  if (m == NavdMode::kGyroOdometry) return {s.mcu.link};
  if (m == NavdMode::kUwb || m == NavdMode::kGnssOnly || !s.mcu.enabled || s.can.imu_to_estimator)
    return {};
  return {s.mcu.link};
}

// The header's line: the IMU profile, its rates and baud.
std::string McuProfile(const Scenario& s) {
  const auto& c = s.mcu.config;
  return ProfileText("IMU profile %s, IMU %g Hz, compass %g Hz, %d Bd%s", c.profile.name.c_str(),
                     c.imu_rate_hz, c.mag_rate_hz, c.baud, c.can.enabled ? ", J1939 on CAN" : "");
}

}  // namespace

extern const DeviceKind kMcuKind;
const DeviceKind kMcuKind{.name = "mcu",
                          .sections = kMcuSections,
                          .spec = "mcu: (IMU and compass stream, serial and CAN)",
                          .read = ReadMcuSpec,
                          .seed_stream = 2,
                          .build = BuildMcu,
                          .navd_keys = kMcuNavdKeys,
                          .write_navd = WriteMcuNavd,
                          .links = McuLinks,
                          .navd_links = McuNavdLinks,
                          .report_section = "link_integrity",
                          .link_role = "imu",
                          .profile = McuProfile};

}  // namespace hil::harness

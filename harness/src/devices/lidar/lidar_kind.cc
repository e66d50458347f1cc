// The 2-D LiDAR's row of the device table: section `lidar:`, an RplidarDevice on its own pty,
// casting against the scenario's greenhouse (paper 001).
#include "hil/firmware_emu/lidar/rplidar_device.h"

#include "lidar.h"

namespace hil::harness {
namespace {

void BuildLidar(const Scenario& s, std::uint64_t seed, const std::string& dir, DeviceBuild& set) {
  if (!s.greenhouse || !s.lidar.enabled) return;
  AddSerialDevice(
      std::make_unique<lidar::RplidarDevice>(s.lidar.config, GreenhouseWorldOf(s, set), seed),
      s.lidar.link, s.lidar.tx_buffer_bytes, dir, set);
}

std::vector<std::string> LidarLinks(const Scenario& s) {
  if (!s.lidar.enabled) return {};
  return {s.lidar.link};
}

constexpr std::string_view kLidarSections[] = {"lidar"};

// The header's line: the model and its rotation.
std::string LidarProfile(const Scenario& s) {
  return ProfileText("RPLIDAR %s, %g Hz rotation, %g-%g m",
                     s.lidar.config.model == lidar::RplidarModel::kA1M8 ? "A1M8" : "A2M8",
                     s.lidar.config.rotation_hz, s.lidar.config.min_range_m,
                     s.lidar.config.max_range_m);
}

}  // namespace

extern const DeviceKind kLidarKind;
const DeviceKind kLidarKind{.name = "lidar",
                            .sections = kLidarSections,
                            .spec = "lidar: (needs greenhouse:)",
                            .read = ReadLidarSpec,
                            .seed_stream = 6,
                            .build = BuildLidar,
                            .navd_keys = {},
                            .write_navd = nullptr,
                            .links = LidarLinks,
                            .navd_links = nullptr,
                            .report_section = "link_integrity",
                            .link_role = "",
                            .profile = LidarProfile};

}  // namespace hil::harness

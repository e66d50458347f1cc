#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "uwb_tag.h"

namespace hil::harness {

void WriteUwbTagNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                     std::ostream& out) {
  if (slot != NavdConfSlot::kSections || s.estimator.navd_mode != NavdMode::kUwb) return;
  if (!s.uwb.enabled)
    throw std::runtime_error(s.file + ": estimator.navd_mode uwb needs a uwb: section");
  const std::filesystem::path dir = std::filesystem::path(gnss_device).parent_path();
  const uwb::UwbTagConfig& u = s.uwb.config;
  char origin[160];
  std::snprintf(origin, sizeof origin, "origin_lat_deg = %.10f\norigin_lon_deg = %.10f\n",
                s.truth.origin.lat_deg, s.truth.origin.lon_deg);
  out << "\n[uwb]\ndevice = " << (dir / s.uwb.link).string() << "\nbaud = " << u.baud
      << "\nformat = " << (u.output == uwb::UwbOutput::kTagFrame0 ? "tag_frame0" : "tdoa")
      << "\nanchors_m = ";
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d& a = u.p_W_anchor_m[i];
    out << (i ? ", " : "") << a.x() << ", " << a.y();
  }
  // the module's system_time counts from t = 0 of the scenario (its power-on)
  out << "\n"
      << origin << "origin_height_m = " << s.truth.origin.height_m
      << "\ntime_zero_unix_ns = " << ToNs(s.start_utc) << "\n";
}

}  // namespace hil::harness

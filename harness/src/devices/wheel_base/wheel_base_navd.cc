#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "hil/harness/devices/navd_conf.h"

#include "wheel_base.h"

namespace hil::harness {

void WriteWheelBaseNavd(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                        std::ostream& out) {
  if (slot != NavdConfSlot::kSections || s.estimator.navd_mode != NavdMode::kGyroOdometry) return;
  const std::string run_dir = std::filesystem::path(gnss_device).parent_path();
  if (!s.closed_loop.enabled)
    throw std::runtime_error(s.file +
                             ": estimator.navd_mode gyro_odometry needs a closed_loop: "
                             "section (the base's encoders)");
  const actuator::WheelMotorsConfig& m = s.closed_loop.motors;
  char origin[200];
  std::snprintf(origin, sizeof origin,
                "origin_lat_deg = %.10f\norigin_lon_deg = %.10f\norigin_height_m = %.4f\n",
                s.truth.origin.lat_deg, s.truth.origin.lon_deg, s.truth.origin.height_m);
  out << "\n[odometry]\ndevice = " << (std::filesystem::path(run_dir) / kOdometryFifo).string()
      << "\nwheel_radius_m = " << m.wheel_radius_m << "\ntrack_m = " << m.track_m
      << "\ncounts_per_rev = " << m.encoder_counts_per_rev << "\n"
      << origin << "initial_e_m = " << s.closed_loop.start_p_N_m.x()
      << "\ninitial_n_m = " << s.closed_loop.start_p_N_m.y()
      << "\ninitial_heading_deg = " << s.closed_loop.start_heading_deg << "\n";
  for (const auto& [key, value] : s.estimator.navd_filter) out << key << " = " << value << "\n";
}

}  // namespace hil::harness

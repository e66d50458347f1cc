// Which receiver navd reads (navd_gnss_source.h): the ZED-F9P rover or the `gnss` receivers.
#include "hil/harness/scenario/navd_gnss_source.h"

namespace hil::harness {

bool NavdReadsRover(const Scenario& s) {
  if (!s.zed_f9p.enabled || !s.zed_f9p.navd_input) return false;
  const NavdMode m = s.estimator.navd_mode;
  return m != NavdMode::kUwb && m != NavdMode::kGyroOdometry && m != NavdMode::kMultiGnss;
}

Eigen::Vector3d NavdAntennaB(const Scenario& s) {
  return NavdReadsRover(s) ? s.zed_f9p.config.model.p_BA_B_m : s.gnss.model.p_BA_B_m;
}

}  // namespace hil::harness

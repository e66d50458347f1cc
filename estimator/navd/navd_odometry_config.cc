#include "hil/estimator/navd/navd_odometry_config.h"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <utility>
#include <vector>

namespace hil::estimator {
namespace {

double Number(const ConfigFile& f, const ConfigEntry& e, double lo, double hi) {
  char* end = nullptr;
  const double v = std::strtod(e.value.c_str(), &end);
  if (e.value.empty() || end != e.value.c_str() + e.value.size() || !std::isfinite(v))
    FailAt(f, e, "expected a number, got '" + e.value + "'");
  if (v < lo || v > hi) {
    std::ostringstream m;
    m << "value " << e.value << " out of range [" << lo << ", " << hi << "]";
    FailAt(f, e, m.str());
  }
  return v;
}

struct NumberKey {
  const char* key;
  double NavdOdometryConfig::*field;
  double lo, hi;
};

const std::vector<NumberKey>& NumberKeys() {
  using C = NavdOdometryConfig;
  static const std::vector<NumberKey> keys{
      {"wheel_radius_m", &C::wheel_radius_m, 0.005, 5},
      {"track_m", &C::track_m, 0.05, 10},
      {"origin_lat_deg", &C::origin_lat_deg, -90, 90},
      {"origin_lon_deg", &C::origin_lon_deg, -180, 180},
      {"origin_height_m", &C::origin_height_m, -1000, 10000},
      {"initial_e_m", &C::initial_e_m, -1e6, 1e6},
      {"initial_n_m", &C::initial_n_m, -1e6, 1e6},
      {"initial_heading_deg", &C::initial_heading_deg, -360, 360},
      {"align_s", &C::align_s, 0.1, 600},
      {"gyro_arw", &C::gyro_arw, 0, 1},
      {"gyro_bias_rw", &C::gyro_bias_rw, 0, 1},
      {"init_gyro_bias_std", &C::init_gyro_bias_std, 1e-9, 1},
      {"odo_yaw_std_rad", &C::odo_yaw_std_rad, 1e-6, 1},
      {"odo_distance_std_fraction", &C::odo_distance_std_fraction, 0, 1},
      {"odo_lateral_std_fraction", &C::odo_lateral_std_fraction, 0, 1},
      {"wait_s", &C::wait_s, 0, 60},
  };
  return keys;
}

}  // namespace

void ReadNavdOdometryKey(const ConfigFile& f, const ConfigEntry& e, NavdOdometryConfig& o) {
  if (e.key == "device") {
    if (e.value.empty()) FailAt(f, e, "expected a device path");
    o.device = e.value;
    return;
  }
  if (e.key == "counts_per_rev") {
    const double v = Number(f, e, 1, 1e7);
    if (v != std::floor(v))
      FailAt(f, e, "expected a whole number of counts, got '" + e.value + "'");
    o.counts_per_rev = static_cast<int>(v);
    return;
  }
  for (const NumberKey& k : NumberKeys()) {
    if (e.key == k.key) {
      o.*k.field = Number(f, e, k.lo, k.hi);
      return;
    }
  }
  FailAt(f, e, "unknown key");
}

}  // namespace hil::estimator

#include "hil/estimator/drivers/nmea_accuracy.h"

#include <numbers>

namespace hil::estimator {

double NmeaHorizontalStd(const NmeaAccuracy& a, int quality, std::optional<double> hdop) {
  if (quality == kGgaQualityRtkFixed && a.rtk_fixed_std_m > 0) return a.rtk_fixed_std_m;
  if (quality == kGgaQualityRtkFloat && a.rtk_float_std_m > 0) return a.rtk_float_std_m;
  return hdop.value_or(5.0) * a.uere_m / std::numbers::sqrt2;
}

}  // namespace hil::estimator

#include "hil/estimator/drivers/nmea_gnss_sample.h"

#include <cmath>
#include <numbers>

namespace hil::estimator::drivers {

GnssSample ToGnssSample(const NmeaMeasurement& m, int leap_s, const NmeaAccuracy& acc) {
  GnssSample g;
  g.t = GpsTimeFromUnixNs(m.tov_unix_ns, leap_s);
  g.position = {m.lat_deg, m.lon_deg, m.height_m};
  const double sigma = NmeaHorizontalStd(acc, m.quality, m.hdop);
  // the altitude is rounded to the step it is written with: a uniform error of variance step²/12
  // (0.1 m, a common GGA format, gives 2.9 cm)
  const double up_var = 4.0 * sigma * sigma + m.altitude_step_m * m.altitude_step_m / 12.0;
  g.pos_std_enu_m = {sigma, sigma, std::sqrt(up_var)};
  // the geoid separation added back is rounded too, but its rounding is one offset for a site
  // (the separation changes by centimetres over kilometres): not a noise of the fix, an error of
  // every fix's height alike that no fix reveals, uniform over one step (step / √12: 2.9 cm for
  // 0.1 m; it was +4.3 cm on the emulated tractor rig's site, 11.657 m written 11.7)
  g.height_datum_std_m = m.geoid_step_m / std::sqrt(12.0);
  g.fix_quality = m.quality;
  g.num_sv = m.num_sv;
  g.hdop = m.hdop.value_or(0.0);
  g.vdop = m.vdop.value_or(0.0);
  g.ground_speed_mps = m.speed_mps;  // known also when the course is not (no velocity then)
  g.geoid_separation_m = m.geoid_separation_m;
  if (m.speed_mps && m.course_deg) {
    const double c = *m.course_deg * std::numbers::pi / 180.0;
    g.vel_enu_mps = {*m.speed_mps * std::sin(c), *m.speed_mps * std::cos(c), 0.0};
    g.has_velocity = true;
    g.vel_std_enu_mps = {acc.velocity_std_mps, acc.velocity_std_mps, 2.0 * acc.velocity_std_mps};
    g.vel_std_configured = true;  // RMC and VTG carry no accuracy: the σ is the host's figure
  }
  return g;
}

}  // namespace hil::estimator::drivers

#pragma once
/// @file
/// A decoded NMEA epoch (NmeaEpochAssembler) as a filter sample, the NMEA counterpart of
/// UbxEpochAssembler's output: time of validity mapped from UTC onto GPS time, horizontal 1σ per
/// axis from the fix quality and HDOP (nmea_accuracy.h; vertical twice that), velocity from RMC
/// speed and course with the configured 1σ (vertical 0 with twice that 1σ).

#include "hil/estimator/drivers/nmea_accuracy.h"
#include "hil/estimator/drivers/nmea_epoch.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

/// `leap_s`: GPS − UTC in seconds.
GnssSample ToGnssSample(const NmeaMeasurement& m, int leap_s, const NmeaAccuracy& acc);

}  // namespace hil::estimator::drivers

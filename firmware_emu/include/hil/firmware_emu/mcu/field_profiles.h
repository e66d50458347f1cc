#pragma once
/// @file
/// Named field profiles (issue 41): a sensor profile (sensor_spec.h) with the rough-model terms
/// filled in, and the vibration environment of the vehicle it rides on. A scenario names one as
/// `mcu: {imu_profile: consumer_mems_car}`; its own keys then override single terms. Every figure
/// and its source (data sheet, paper, or "scenario choice") is listed in
/// vectors/mcu/imu_error_model.md; the comments below name the source of each figure.

#include <string>
#include <vector>

#include "hil/firmware_emu/mcu/rough_imu_spec.h"
#include "hil/firmware_emu/mcu/sensor_spec.h"

namespace hil::mcu {

struct FieldProfile {
  std::string name;
  ImuProfile sensor;
  RoughImuSpec rough;
};

/// razor_small_engine_robot, consumer_mems_car, consumer_mems_tractor_cab, industrial_mems_tractor.
const std::vector<std::string>& FieldProfileNames();
/// @throws std::invalid_argument for an unknown name.
FieldProfile FieldProfileByName(const std::string& name);

}  // namespace hil::mcu

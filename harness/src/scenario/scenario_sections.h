#pragma once
// Internal to the harness: readers of the scenario file's sections, one file per owner
// (scenario_truth.cc: origin, vehicle, path; scenario_can.cc: can; ...). Each lists the top-level
// keys it reads so the root check knows them. The devices' sections are read by the device table
// (harness/src/devices/<kind>/, devices/device_kind.h).
#include <string>
#include <vector>

#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/scenario_keys.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

extern const std::vector<std::string> kTruthSectionKeys;
/// Reads origin (required), vehicle and path into the truth configuration.
void ReadTruthSections(const YamlReader& root, truth::TruthConfig& t);

extern const std::vector<std::string> kCanSectionKeys;
/// Reads the can section (optional; scenario_can.cc).
void ReadCanSection(const YamlReader& root, CanLinkSpec& c);
/// Checks what needs the bus (IMU to the estimator over CAN, output n2k_socketcan) once every
/// section is read (scenario_can.cc).
void CheckCanUse(const YamlReader& root, const Scenario& s);

extern const std::vector<std::string> kGreenhouseSectionKeys;
/// Reads the greenhouse section (optional; scenario_greenhouse.cc): the ridge map of paper 001.
void ReadGreenhouseSection(const YamlReader& root, Scenario& s);

/// Closed loop: the truth follows the actuator's commands through a first-order hold of its
/// 10 ms output (the actuator is the one model of the command path; truth_integrator.h,
/// command_hold_s), starting at the loop's pose and speed, with no planned path of its own.
void FollowActuatorCommands(const ClosedLoopSpec& c, truth::TruthConfig& t);

extern const std::vector<std::string> kClosedLoopSectionKeys;
/// Reads the closed_loop section (optional; scenario_closed_loop.cc) and makes the truth take
/// the actuator's commands.
void ReadClosedLoopSection(const YamlReader& root, Scenario& s);
/// The closed_loop section `r`: the keys of the ISOBUS channel (scenario_closed_loop_isobus.cc):
/// the transport, the set speed and the steering ECU (`actuator:`); sets up the bicycle truth.
void ReadIsobusChannel(const YamlReader& root, const YamlReader& r, Scenario& s);

extern const std::vector<std::string> kSuiteSectionKeys;
/// Reads `paper:` into s.paper and checks `short:` (scenario_suite.cc); `top_level_keys` are the
/// keys a `short:` section may replace (all but name, include, paper and short).
void ReadSuiteSections(const YamlReader& root, const std::vector<std::string>& top_level_keys,
                       Scenario& s);
/// Replaces the root's top-level keys by those of its `short:` section (nothing without one).
void ApplyShortForm(YamlReader& root);

}  // namespace hil::harness

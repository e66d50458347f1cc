// The closed_loop section: the actuator, its link, the controller and the planned path.
#include <array>
#include <filesystem>
#include <string_view>

#include "hil/harness/scenario/path_file_reader.h"

#include "scenario_closed_loop_keys.h"
#include "scenario_sections.h"

namespace hil::harness {
namespace {

// the tables read here (a using-declaration each: the unity build joins the readers' files)
using closed_loop_keys::kActuator;
using closed_loop_keys::kClosedLoop;
using closed_loop_keys::kPassToPass;

Duration Seconds(double s) { return DurationFromSeconds(s); }

void ReadActuator(const YamlReader& y, ClosedLoopSpec& c) {
  const KeyedReader<kActuator> r(y);
  r.CheckKeys();
  actuator::WheelMotorsConfig& m = c.motors;
  m.wheel_radius_m = r.Number("wheel_radius_m", m.wheel_radius_m);
  m.encoder_counts_per_rev =
      static_cast<int>(r.Integer("encoder_counts_per_rev", m.encoder_counts_per_rev));
  m.max_wheel_speed_radps = r.Number("max_wheel_speed_radps", m.max_wheel_speed_radps);
  m.max_wheel_accel_radps2 = r.Number("max_wheel_accel_radps2", m.max_wheel_accel_radps2);
  m.time_constant_s = r.Number("time_constant_s", m.time_constant_s);
  const std::vector<double> slip = r.Doubles("slip", 2, {m.slip[0], m.slip[1]});
  for (double x : slip) {
    if (x < 0 || x >= 1) r.Fail("slip", "each wheel's slip is a fraction in [0, 1)");
  }
  m.slip = {slip[0], slip[1]};
  m.command_latency = Seconds(r.Number("command_latency_s", ToSeconds(m.command_latency)));
  m.command_timeout = Seconds(r.Number("watchdog_timeout_s", ToSeconds(m.command_timeout)));
  c.pid_rate_hz = r.Number("pid_rate_hz", c.pid_rate_hz);
}

// A closed-loop fault in a scenario without a closed_loop section would do nothing: refused.
void RefuseClosedLoopFaults(const YamlReader& root) {
  const std::optional<YamlReader> faults = root.OptionalChild("faults");
  if (!faults) return;
  for (const YamlReader& e : faults->Elements()) {
    if (!e.IsMap() || !e.Has("kind")) continue;  // the fault reader names these
    const std::string kind = e.String("kind");
    for (const char* k : {"controller_stop", "command_link_loss", "command_latency",
                          "actuator_saturation", "actuator_stuck"}) {
      if (kind == k)
        e.Fail("kind", kind + " acts on a closed loop: the scenario has no closed_loop");
    }
  }
}

// `closed_loop.pass_to_pass:` the ISO 12188-2 style evaluation's parameters (pass_to_pass.h).
void ReadPassToPass(const YamlReader& y, PassToPassConfig& c) {
  const KeyedReader<kPassToPass> r(y);
  r.CheckKeys();
  c.window_s = r.Number("window_s", c.window_s);
  c.margin_m = r.Number("margin_m", c.margin_m);
  c.max_angle_deg = r.Number("max_angle_deg", c.max_angle_deg);
}

// The serial base drives the wheels of a diff_drive or skid_steer vehicle (its yaw rate through
// the tracks' ICRs: vehicle.icr_expansion).
void SetUpSerialBase(const std::optional<YamlReader>& actuator, Scenario& s) {
  ClosedLoopSpec& c = s.closed_loop;
  c.motors.track_m = s.truth.vehicle.track_m;
  if (s.truth.vehicle.model == truth::VehicleParams::Model::kSkidSteer)
    c.motors.icr_expansion = s.truth.vehicle.icr_expansion;
  if (actuator) ReadActuator(*actuator, c);
  c.motors.initial_wheel_speed_radps = c.initial_speed_mps / c.motors.wheel_radius_m;
  FollowActuatorCommands(c, s.truth);  // the wheel motors are the one model of the command path
}

}  // namespace

void FollowActuatorCommands(const ClosedLoopSpec& c, truth::TruthConfig& t) {
  t.external_commands = true;
  t.command_period_s = 0.01;
  t.path.reset();
  t.start_p_N_m = c.start_p_N_m;
  t.heading_deg = c.start_heading_deg;
  t.speed_mps = c.initial_speed_mps;
  t.start_at_speed = true;
  t.command_hold_s = t.command_period_s;
}

const std::vector<std::string> kClosedLoopSectionKeys{"closed_loop"};

extern const KeySection kClosedLoopSection{
    "closed_loop",
    "the controller under test steers the truth vehicle through an emulated actuator", kClosedLoop};
extern const KeySection kActuatorSection{"closed_loop.actuator (serial_base)",
                                         "the wheel motors of the serial_base channel", kActuator};
extern const KeySection kPassToPassSection{"closed_loop.pass_to_pass",
                                           "the pass-to-pass evaluation's parameters", kPassToPass};

void ReadClosedLoopSection(const YamlReader& root, Scenario& s) {
  const std::optional<YamlReader> y = root.OptionalChild("closed_loop");
  if (!y) {
    RefuseClosedLoopFaults(root);
    return;
  }
  const KeyedReader<kClosedLoop> r(*y);
  r.CheckKeys();
  ClosedLoopSpec& c = s.closed_loop;
  c.enabled = true;
  c.channel = r.Choice("channel", ClosedLoopSpec::Channel::kSerialBase);
  if (root.Has("path"))
    root.Fail("path", "a closed-loop scenario's path is closed_loop.path_file, not path");
  const bool isobus = c.channel == ClosedLoopSpec::Channel::kIsobus;
  if (!isobus) {
    for (const char* key : {"transport", "speed_mps", "slcan_baud"}) {
      if (y->Has(key)) y->Fail(key, "a key of the isobus channel");
    }
  }
  if (!isobus && !s.truth.vehicle.yaw_rate_commanded())
    r.Fail("channel",
           "the serial base protocol drives a vehicle of model diff_drive or skid_steer");
  c.link = r.String("link", isobus ? "ttyCAN" : c.link);
  const std::filesystem::path base = std::filesystem::path(y->file()).parent_path();
  const std::filesystem::path file = r.String("path_file");
  c.path_file = std::filesystem::absolute(file.is_absolute() ? file : base / file).string();
  try {
    ReadPathVertices(c.path_file);
  } catch (const PathFileReadError& e) {
    r.Fail("path_file", e.what());
  }
  c.controller = r.String("controller");
  c.control_period_s = r.Number("control_period_s", c.control_period_s);
  c.command_timeout_s = r.Number("command_timeout_s", c.command_timeout_s);
  c.first_command_due_s = r.Number("first_command_due_s", c.first_command_due_s);
  c.fault_window_s = r.Number("fault_window_s", c.fault_window_s);
  if (auto p2p = r.OptionalChild("pass_to_pass")) ReadPassToPass(*p2p, c.pass_to_pass);
  const std::vector<double> p = r.Doubles("start_enu_m", 2, {0, 0});
  c.start_p_N_m = {p[0], p[1]};
  c.start_heading_deg = r.Number("start_heading_deg", 0);
  c.initial_speed_mps = r.Number("initial_speed_mps", 0);
  if (isobus) {
    ReadIsobusChannel(root, *y, s);
    return;
  }
  SetUpSerialBase(r.OptionalChild("actuator"), s);
}

}  // namespace hil::harness

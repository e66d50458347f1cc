// The closed_loop section: the actuator, its link, the controller and the planned path.
#include <array>
#include <filesystem>
#include <string_view>

#include "hil/harness/scenario/path_file_reader.h"

#include "scenario_sections.h"

namespace hil::harness {
namespace {

Duration Seconds(double s) { return DurationFromSeconds(s); }

constexpr std::array<std::string_view, 2> kChannels{"serial_base", "isobus"};

void ReadActuator(const YamlReader& r, ClosedLoopSpec& c) {
  r.CheckKeys({"wheel_radius_m", "encoder_counts_per_rev", "max_wheel_speed_radps",
               "max_wheel_accel_radps2", "time_constant_s", "slip", "command_latency_s",
               "watchdog_timeout_s", "pid_rate_hz"});
  actuator::WheelMotorsConfig& m = c.motors;
  m.wheel_radius_m = r.DoubleIn("wheel_radius_m", m.wheel_radius_m, 0.01, 2);
  m.encoder_counts_per_rev =
      static_cast<int>(r.Int("encoder_counts_per_rev", m.encoder_counts_per_rev, 1, 1 << 20));
  m.max_wheel_speed_radps = r.DoubleIn("max_wheel_speed_radps", m.max_wheel_speed_radps, 0.1, 500);
  m.max_wheel_accel_radps2 =
      r.DoubleIn("max_wheel_accel_radps2", m.max_wheel_accel_radps2, 0.1, 1e4);
  m.time_constant_s = r.DoubleIn("time_constant_s", m.time_constant_s, 0.001, 10);
  const std::vector<double> slip = r.Doubles("slip", 2, {m.slip[0], m.slip[1]});
  for (double x : slip) {
    if (x < 0 || x >= 1) r.Fail("slip", "each wheel's slip is a fraction in [0, 1)");
  }
  m.slip = {slip[0], slip[1]};
  m.command_latency = Seconds(r.DoubleIn("command_latency_s", ToSeconds(m.command_latency), 0, 5));
  m.command_timeout =
      Seconds(r.DoubleIn("watchdog_timeout_s", ToSeconds(m.command_timeout), 0.01, 60));
  c.pid_rate_hz = r.DoubleIn("pid_rate_hz", c.pid_rate_hz, 1, 1000);
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
void ReadPassToPass(const YamlReader& r, PassToPassConfig& c) {
  r.CheckKeys({"window_s", "margin_m", "max_angle_deg"});
  c.window_s = r.DoubleIn("window_s", c.window_s, 1, 86400);
  c.margin_m = r.DoubleIn("margin_m", c.margin_m, 0, 1e4);
  c.max_angle_deg = r.DoubleIn("max_angle_deg", c.max_angle_deg, 0, 45);
}

}  // namespace

const std::vector<std::string> kClosedLoopSectionKeys{"closed_loop"};

void ReadClosedLoopSection(const YamlReader& root, Scenario& s) {
  const std::optional<YamlReader> r = root.OptionalChild("closed_loop");
  if (!r) {
    RefuseClosedLoopFaults(root);
    return;
  }
  r->CheckKeys({"channel", "link", "path_file", "controller", "control_period_s",
                "command_timeout_s", "first_command_due_s", "start_enu_m", "start_heading_deg",
                "initial_speed_mps", "actuator", "transport", "speed_mps", "slcan_baud",
                "fault_window_s", "pass_to_pass"});
  ClosedLoopSpec& c = s.closed_loop;
  c.enabled = true;
  c.channel = r->Choice("channel", ClosedLoopSpec::Channel::kSerialBase, kChannels);
  if (root.Has("path"))
    root.Fail("path", "a closed-loop scenario's path is closed_loop.path_file, not path");
  const bool isobus = c.channel == ClosedLoopSpec::Channel::kIsobus;
  if (!isobus) {
    for (const char* key : {"transport", "speed_mps", "slcan_baud"}) {
      if (r->Has(key)) r->Fail(key, "a key of the isobus channel");
    }
  }
  if (!isobus && s.truth.vehicle.model != truth::VehicleParams::Model::kDiffDrive)
    r->Fail("channel", "the serial base protocol drives a vehicle of model diff_drive");
  c.link = r->String("link", isobus ? "ttyCAN" : c.link);
  const std::filesystem::path base = std::filesystem::path(r->file()).parent_path();
  const std::filesystem::path file = r->String("path_file");
  c.path_file = std::filesystem::absolute(file.is_absolute() ? file : base / file).string();
  try {
    ReadPathVertices(c.path_file);
  } catch (const PathFileReadError& e) {
    r->Fail("path_file", e.what());
  }
  c.controller = r->String("controller");
  c.control_period_s = r->DoubleIn("control_period_s", c.control_period_s, 0.01, 10);
  c.command_timeout_s = r->DoubleIn("command_timeout_s", c.command_timeout_s, 0.01, 60);
  c.first_command_due_s = r->DoubleIn("first_command_due_s", c.first_command_due_s, 0, 600);
  c.fault_window_s = r->DoubleIn("fault_window_s", c.fault_window_s, 0, 3600);
  if (auto p2p = r->OptionalChild("pass_to_pass")) ReadPassToPass(*p2p, c.pass_to_pass);
  const std::vector<double> p = r->Doubles("start_enu_m", 2, {0, 0});
  c.start_p_N_m = {p[0], p[1]};
  c.start_heading_deg = r->DoubleIn("start_heading_deg", 0, -360, 360);
  c.initial_speed_mps = r->DoubleIn("initial_speed_mps", 0, 0, 10);
  if (isobus) {
    ReadIsobusChannel(root, *r, s);
    return;
  }
  c.motors.track_m = s.truth.vehicle.track_m;
  if (auto a = r->OptionalChild("actuator")) ReadActuator(*a, c);
  c.motors.initial_wheel_speed_radps = c.initial_speed_mps / c.motors.wheel_radius_m;
  // the truth obeys the wheels through a first-order hold of their 10 ms output (the wheel motors
  // are the one model of the command path; truth_integrator.h, command_hold_s)
  truth::TruthConfig& t = s.truth;
  t.external_commands = true;
  t.command_period_s = 0.01;
  t.path.reset();
  t.start_p_N_m = c.start_p_N_m;
  t.heading_deg = c.start_heading_deg;
  t.speed_mps = c.initial_speed_mps;
  t.start_at_speed = true;
  t.command_hold_s = t.command_period_s;
}

}  // namespace hil::harness

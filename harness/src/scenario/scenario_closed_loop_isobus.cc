// The closed_loop section's ISOBUS channel (vectors/scenarios/closed_loop/README.md): a
// front-steered vehicle whose steering ECU takes ISO 11783-7 curvature commands over SocketCAN
// (the scenario's `can:` bus) or over a serial SLCAN adapter on a pty.
#include <array>
#include <string_view>

#include "scenario_closed_loop_keys.h"
#include "scenario_sections.h"

namespace hil::harness {
namespace {

using closed_loop_keys::kSteeringEcu;

constexpr std::array<std::string_view, 2> kTransports{"socketcan", "slcan"};

void ReadSteeringEcu(const YamlReader& y, actuator::SteeringEcuConfig& e) {
  const KeyedReader<kSteeringEcu> r(y);
  r.CheckKeys();
  e.max_steer_deg = r.Number("max_steer_deg", e.max_steer_deg);
  e.max_steer_rate_dps = r.Number("max_steer_rate_dps", e.max_steer_rate_dps);
  e.time_constant_s = r.Number("time_constant_s", e.time_constant_s);
  e.deadband_deg = r.Number("deadband_deg", e.deadband_deg);
  e.command_latency =
      DurationFromSeconds(r.Number("command_latency_s", ToSeconds(e.command_latency)));
  e.command_timeout =
      DurationFromSeconds(r.Number("watchdog_timeout_s", ToSeconds(e.command_timeout)));
  e.status_period = DurationFromSeconds(r.Number("status_period_s", ToSeconds(e.status_period)));
  e.source_address = static_cast<std::uint8_t>(r.Integer("ecu_address", e.source_address));
  const auto guidance =
      static_cast<std::uint8_t>(r.Integer("guidance_address", e.accepted_sources[0]));
  e.accepted_sources.fill(guidance);
  e.min_engage_speed_mps = r.Number("min_engage_speed_mps", e.min_engage_speed_mps);
  e.max_engage_speed_mps = r.Number("max_engage_speed_mps", e.max_engage_speed_mps);
  e.center_on_disengage = r.Bool("center_on_disengage", e.center_on_disengage);
}

}  // namespace

void ReadIsobusChannel(const YamlReader& root, const YamlReader& r, Scenario& s) {
  ClosedLoopSpec& c = s.closed_loop;
  actuator::IsobusSteeringDeviceConfig& d = c.isobus;
  if (s.truth.vehicle.model != truth::VehicleParams::Model::kBicycle)
    r.Fail("channel", "ISOBUS guidance steers a front-steered vehicle (model bicycle or tractor)");
  d.transport = r.Choice("transport", actuator::IsobusTransport::kSocketCan, kTransports);
  if (d.transport == actuator::IsobusTransport::kSocketCan && !root.Has("can"))
    r.Fail("transport", "socketcan needs the scenario's can: {interface: …} bus");
  d.slcan_baud = static_cast<int>(r.Int("slcan_baud", d.slcan_baud, 1200, 4000000));
  d.speed_mps = r.DoubleIn("speed_mps", d.speed_mps, 0, 15);
  d.ecu.wheelbase_m = s.truth.vehicle.wheelbase_m;
  // the vehicle's steering (limit, rate, lag) is the ECU's unless its actuator says otherwise
  d.ecu.max_steer_deg = s.truth.vehicle.max_steer_deg;
  d.ecu.max_steer_rate_dps = s.truth.vehicle.max_steer_rate_dps;
  d.ecu.time_constant_s = s.truth.vehicle.steer_lag_s;
  if (auto a = r.OptionalChild("actuator")) ReadSteeringEcu(*a, d.ecu);
  d.control_period = DurationFromSeconds(c.control_period_s);
  d.command_timeout = DurationFromSeconds(c.command_timeout_s);
  d.first_command_due = TimeFromSeconds(c.first_command_due_s);
  if (!r.Has("initial_speed_mps")) c.initial_speed_mps = d.speed_mps;
  // the road wheels obey the steering ECU (first-order and rate-limited: the one model of the
  // command path); κ = tan δ / L at the rear axle
  FollowActuatorCommands(c, s.truth);
  s.truth.vehicle.max_steer_deg = d.ecu.max_steer_deg;
}

extern const KeySection kSteeringEcuSection{
    "closed_loop.actuator (isobus)",
    "the steering ECU of the isobus channel (steering_ecu.h, vectors/isobus/README.md)",
    kSteeringEcu};

}  // namespace hil::harness

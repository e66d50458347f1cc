#include "hil/harness/report/steering_ecu_report.h"

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/actuator/isobus_steering_device.h"

namespace hil::harness {
namespace {

std::string ExitReasonName(actuator::ExitReason r) {
  switch (r) {
    case actuator::ExitReason::kAllClear:
      return "all_clear";
    case actuator::ExitReason::kRemoteCommandTimeout:
      return "remote_command_timeout";
    case actuator::ExitReason::kRemoteCommandOutOfRange:
      return "remote_command_out_of_range";
    case actuator::ExitReason::kSpeedTooLow:
      return "speed_too_low";
    case actuator::ExitReason::kSpeedTooHigh:
      return "speed_too_high";
    case actuator::ExitReason::kError:
      return "error";
  }
  return "unknown";
}

}  // namespace

SteeringEcuReport MakeSteeringEcuReport(const actuator::IsobusSteeringDevice& device) {
  SteeringEcuReport r;
  const bool slcan = device.serial_port_count() > 0;
  r.transport = slcan ? "slcan" : "socketcan";
  r.frames_from_controller = device.counters().frames_from_controller;
  r.frames_lost = device.link_loss().total();
  const actuator::SteeringEcuCounters& k = device.ecu().counters();
  r.commands_accepted = k.commands_accepted;
  r.wrong_length = k.wrong_length;
  r.unknown_source = k.unknown_source;
  r.out_of_range = k.out_of_range;
  r.not_addressed = k.not_addressed;
  r.engagements = k.engagements;
  r.watchdog_trips = k.watchdog_trips;
  r.engaged = device.ecu().engaged();
  r.exit_reason_code = static_cast<int>(device.ecu().exit_reason());
  r.exit_reason = ExitReasonName(device.ecu().exit_reason());
  const double sum = device.engaged_steer_error_sq_sum_rad2();
  const std::uint64_t n = device.engaged_ticks();
  if (n > 0)
    r.commanded_steer_rms_error_deg =
        std::sqrt(sum / static_cast<double>(n)) * 180.0 / std::numbers::pi;
  if (slcan) {
    const link::SlcanAdapterCounters& a = device.adapter().counters();
    r.slcan_records = a.records;
    r.slcan_refused = a.refused;
    r.slcan_frames_to_host = a.frames_to_host;
    r.slcan_dropped_closed = a.dropped_closed;
    r.slcan_opens = a.opens;
    r.slcan_bitrate_bps = device.adapter().bitrate_bps();
  }
  return r;
}

nlohmann::json SteeringEcuJson(const SteeringEcuReport& r) {
  nlohmann::json j = {{"transport", r.transport},
                      {"frames_from_controller", r.frames_from_controller},
                      {"frames_lost", r.frames_lost},
                      {"commands_accepted", r.commands_accepted},
                      {"wrong_length", r.wrong_length},
                      {"unknown_source", r.unknown_source},
                      {"out_of_range", r.out_of_range},
                      {"not_addressed", r.not_addressed},
                      {"engagements", r.engagements},
                      {"watchdog_trips", r.watchdog_trips},
                      {"engaged", r.engaged},
                      {"exit_reason_code", r.exit_reason_code},
                      {"exit_reason", r.exit_reason},
                      {"commanded_steer_rms_error_deg", r.commanded_steer_rms_error_deg}};
  if (r.transport == "slcan") {
    j["slcan"] = {{"records", r.slcan_records},
                  {"refused", r.slcan_refused},
                  {"frames_to_host", r.slcan_frames_to_host},
                  {"dropped_closed", r.slcan_dropped_closed},
                  {"opens", r.slcan_opens},
                  {"bitrate_bps", r.slcan_bitrate_bps}};
  }
  return j;
}

void AddSteeringEcuMetrics(const std::optional<SteeringEcuReport>& r,
                           std::map<std::string, std::optional<double>>& table) {
  if (!r) return;
  const auto put = [&table](const char* key, double v) {
    table[std::string("closed_loop.steering_ecu.") + key] = v;
  };
  put("engaged", r->engaged ? 1.0 : 0.0);
  put("exit_reason_code", r->exit_reason_code);
  put("engagements", static_cast<double>(r->engagements));
  put("watchdog_trips", static_cast<double>(r->watchdog_trips));
  put("frames_lost", static_cast<double>(r->frames_lost));
  put("wrong_length", static_cast<double>(r->wrong_length));
  put("unknown_source", static_cast<double>(r->unknown_source));
  put("out_of_range", static_cast<double>(r->out_of_range));
}

}  // namespace hil::harness

// The scenario's `wt901c:` section: the WT901C attitude sensor (firmware_emu/attitude; paper
// 003's heading source). Format in vectors/scenarios/README.md; the error figures and their reasons
// in vectors/wt901c/README.md.
#include "wt901c.h"

namespace hil::harness {
namespace {

void ReadWt901c(const YamlReader& r, Wt901cDeviceSpec& w) {
  r.CheckKeys({"link", "baud", "rate_hz", "require_unlock", "gyro_bias_sigma_dps",
               "angle_noise_sigma_deg", "yaw_drift_sigma_dps", "tx_buffer_bytes"});
  w.enabled = true;
  wit::Wt901cConfig& c = w.config;
  w.link = ReadLinkName(r, w.link);
  const auto baud = r.Int("baud", 9600, 4800, 921600);
  c.baud_code = 0;
  for (std::uint16_t code = 1; code <= 9; ++code)
    if (wit::BaudOfCode(code) == baud) c.baud_code = code;
  if (c.baud_code == 0)
    r.Fail("baud", "not a WT901C baud (4800 … 921600, BAUD register codes 1–9)");
  const double rate = r.DoubleIn("rate_hz", 10, 0.2, 200);
  c.rrate_code = 0;
  for (std::uint16_t code = 1; code <= 0x0B; ++code)
    if (wit::RateHzOfCode(code) == rate) c.rrate_code = code;
  if (c.rrate_code == 0)
    r.Fail("rate_hz", "not an RRATE value (0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 125, 200 Hz)");
  c.require_unlock = r.Bool("require_unlock", c.require_unlock);
  c.errors.gyro_turn_on_bias_sigma_dps =
      r.DoubleIn("gyro_bias_sigma_dps", c.errors.gyro_turn_on_bias_sigma_dps, 0, 10);
  c.errors.angle_noise_sigma_deg =
      r.DoubleIn("angle_noise_sigma_deg", c.errors.angle_noise_sigma_deg, 0, 10);
  c.errors.yaw_drift_sigma_dps =
      r.DoubleIn("yaw_drift_sigma_dps", c.errors.yaw_drift_sigma_dps, 0, 10);
  w.tx_buffer_bytes = static_cast<std::size_t>(
      r.Int("tx_buffer_bytes", static_cast<std::int64_t>(w.tx_buffer_bytes), 64, 1 << 20));
}

}  // namespace

void ReadWt901cSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("wt901c")) ReadWt901c(*r, s.wt901c);
}

}  // namespace hil::harness

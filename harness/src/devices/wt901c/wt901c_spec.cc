// The scenario's `wt901c:` section: the WT901C attitude sensor (firmware_emu/attitude; paper
// 003's heading source). Format in vectors/scenarios/README.md; the error figures and their reasons
// in vectors/wt901c/README.md.
#include "wt901c.h"

namespace hil::harness {
namespace wt901c_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr ScenarioKey kWt901c[] = {
    {"link", kString, "", "ttyWIT", 0, 0, "its pty in the run folder (a plain file name)"},
    {"baud", kInteger, "Bd", "9600", 4800, 921600,
     "the line rate: one of the BAUD register's (4800 … 921600)"},
    {"rate_hz", kNumber, "Hz", "10", 0.2, 200,
     "output rate: an RRATE value (0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 125, 200)"},
    {"require_unlock", kBool, "", "false", 0, 0,
     "configuration writes need the unlock command first (newer firmware)"},
    {"gyro_bias_sigma_dps", kNumber, "deg/s", "0.05", 0, 10,
     "gyro turn-on bias per axis (1σ, per power-on)"},
    {"angle_noise_sigma_deg", kNumber, "deg", "0.02", 0, 10,
     "roll/pitch/yaw noise per output sample (1σ)"},
    {"yaw_drift_sigma_dps", kNumber, "deg/s", "0.005", 0, 10,
     "residual yaw drift of the sensor's fusion (1σ)"},
    {"tx_buffer_bytes", kInteger, "B", "1024", 64, 1 << 20, "its UART's transmit buffer"},
};

}  // namespace wt901c_keys

namespace {

using wt901c_keys::kWt901c;

void ReadWt901c(const YamlReader& y, Wt901cDeviceSpec& w) {
  const KeyedReader<kWt901c> r(y);
  r.CheckKeys();
  w.enabled = true;
  wit::Wt901cConfig& c = w.config;
  w.link = ReadLinkName(r, w.link);
  const auto baud = r.Integer("baud", 9600);
  c.baud_code = 0;
  for (std::uint16_t code = 1; code <= 9; ++code)
    if (wit::BaudOfCode(code) == baud) c.baud_code = code;
  if (c.baud_code == 0)
    r.Fail("baud", "not a WT901C baud (4800 … 921600, BAUD register codes 1–9)");
  const double rate = r.Number("rate_hz", 10);
  c.rrate_code = 0;
  for (std::uint16_t code = 1; code <= 0x0B; ++code)
    if (wit::RateHzOfCode(code) == rate) c.rrate_code = code;
  if (c.rrate_code == 0)
    r.Fail("rate_hz", "not an RRATE value (0.2, 0.5, 1, 2, 5, 10, 20, 50, 100, 125, 200 Hz)");
  c.require_unlock = r.Bool("require_unlock", c.require_unlock);
  c.errors.gyro_turn_on_bias_sigma_dps =
      r.Number("gyro_bias_sigma_dps", c.errors.gyro_turn_on_bias_sigma_dps);
  c.errors.angle_noise_sigma_deg =
      r.Number("angle_noise_sigma_deg", c.errors.angle_noise_sigma_deg);
  c.errors.yaw_drift_sigma_dps = r.Number("yaw_drift_sigma_dps", c.errors.yaw_drift_sigma_dps);
  w.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(w.tx_buffer_bytes)));
}

}  // namespace

extern const KeySection kWt901cSection{
    "wt901c", "paper 003's WT901C attitude sensor (vectors/wt901c/README.md)", kWt901c};

void ReadWt901cSpec(const YamlReader& root, Scenario& s) {
  if (auto r = root.OptionalChild("wt901c")) ReadWt901c(*r, s.wt901c);
}

}  // namespace hil::harness

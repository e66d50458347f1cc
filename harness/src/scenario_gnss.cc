#include "scenario_sections.h"

namespace hil::harness {
namespace {

void ReadGnss(const YamlReader& r, GnssDeviceSpec& g) {
  r.CheckKeys({"profile", "baud", "link", "rate_hz", "output_lag_s", "tx_buffer_bytes", "errors", "antenna_lever_arm_m"});
  g.profile = r.Choice("profile", g.profile, {"neo-5m"});
  g.baud = static_cast<int>(r.Int("baud", g.baud, 1200, 921600));
  g.link = r.String("link", g.link);
  if (g.link.empty() || g.link.find('/') != std::string::npos) r.Fail("link", "must be a plain file name such as ttyGPS");
  g.rate_hz = r.DoubleIn("rate_hz", g.rate_hz, 0.1, 20);
  g.output_lag_s = r.DoubleIn("output_lag_s", g.output_lag_s, 0, 0.9);
  g.tx_buffer_bytes = static_cast<std::size_t>(r.Int("tx_buffer_bytes", 1024, 64, 1 << 20));
  const auto lever = r.Doubles("antenna_lever_arm_m", 3, {0, 0, 0});
  g.model.p_BA_B_m = Eigen::Vector3d(lever[0], lever[1], lever[2]);
  if (auto e = r.OptionalChild("errors")) {
    e->CheckKeys({"horizontal_sigma_m", "vertical_sigma_m", "correlation_time_s", "velocity_sigma_mps"});
    g.model.horizontal_sigma_m = e->DoubleIn("horizontal_sigma_m", g.model.horizontal_sigma_m, 0, 100);
    g.model.vertical_sigma_m = e->DoubleIn("vertical_sigma_m", g.model.vertical_sigma_m, 0, 100);
    g.model.correlation_time_s = e->DoubleIn("correlation_time_s", g.model.correlation_time_s, 0.01, 3600);
    g.model.velocity_sigma_mps = e->DoubleIn("velocity_sigma_mps", g.model.velocity_sigma_mps, 0, 10);
  }
}

}  // namespace

const std::vector<std::string> kGnssSectionKeys{"gnss"};

void ReadGnssSection(const YamlReader& root, GnssDeviceSpec& g) {
  if (auto r = root.OptionalChild("gnss")) ReadGnss(*r, g);
}

}  // namespace hil::harness

// The scenario's `zed_f9p:` section: a ZED-F9P-class RTK rover (firmware_emu/rtk/zed_f9p_device.h)
// whose fix follows the corrections of the `rtk_base` radio on its UART2 or of the host's RTCM on
// UART1. Its RTK timing and accuracy, and its configuration as saved in Flash by the real key
// names (`config`, vectors/gnss/README.md "ZED-F9P configuration keys").
#include <array>
#include <string_view>

#include "hil/firmware_emu/gnss/ubx_f9_config.h"

#include "zed_f9p.h"

namespace hil::harness {
namespace zed_f9p_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::array<std::string_view, 4> kCorrections{"radio", "host", "none",
                                                              "moving_base"};

inline constexpr ScenarioKey kZedF9p[] = {
    {"link", kString, "", "ttyF9P", 0, 0, "its pty in the run folder (UART1; a plain file name)"},
    {"corrections", kChoice, "", "radio", 0, 0,
     "radio: the rtk_base's radio stream on UART2 (needs rtk_base); host: RTCM 3 the host writes "
     "to UART1 (an NTRIP client); none; moving_base: a second F9P on the vehicle sending 4072.0 "
     "and MSM7 into UART2 (dual-antenna heading in NAV-RELPOSNED)",
     kCorrections},
    {"navd_input", kBool, "", "true", 0, 0,
     "navd reads this rover (its NMEA on `link`) instead of the gnss receivers, and the raw-fix "
     "baseline is its fixes; false: navd keeps the gnss receivers"},
    {"antenna_lever_arm_m", kPoint, "m", "[0, 0, 0]", 0, 0,
     "the antenna in the body frame [forward, left, up]"},
    {"moving_base_antenna_m", kPoint, "m", "[0, 0, 0]", 0, 0,
     "moving base: its antenna in the body frame [forward, left, up]"},
    {"moving_base_baud", kInteger, "Bd", "460800", 9600, 921600,
     "moving base: the wire between the UART2s (ours); set CFG-UART2-BAUDRATE to match"},
    {"heading_valid_max_acc_deg", kNumber, "deg", "5", 0, 180,
     "moving base: relPosHeadingValid while accHeading is at most this (ours)"},
    {"output_lag_s", kNumber, "s", "0.05", 0, 1, "epoch to its first byte (ours)"},
    {"time_to_float_s", kNumber, "s", "1", 0, 600,
     "corrections flowing to float (ours: the receiver documents none)"},
    {"time_to_fix_s", kNumber, "s", "10", 0, 3600,
     "float to fixed with fresh corrections (data sheet: convergence < 10 s)"},
    {"time_to_fix_per_km_s", kNumber, "s/km", "0", 0, 600,
     "added to time_to_fix_s per km of baseline (ours: the receiver documents none)"},
    {"fixed_max_age_s", kNumber, "s", "5", 0.1, 600,
     "fixed held while the age of corrections stays at most this (ours)"},
    {"fixed_cep_m", kNumber, "m", "0.01", 0, 10,
     "fixed horizontal CEP at zero baseline (data sheet)"},
    {"fixed_ppm", kNumber, "ppm", "1", 0, 100, "fixed CEP growth with the baseline (data sheet)"},
    {"float_sigma_start_m", kNumber, "m", "1", 0, 100, "float error per axis at entry (1σ, ours)"},
    {"float_sigma_end_m", kNumber, "m", "0.1", 0, 100, "float error per axis converged (ours)"},
    {"float_convergence_s", kNumber, "s", "20", 0.1, 3600, "float convergence time constant"},
    {"wrong_fix_probability", kNumber, "", "0", 0, 1,
     "each fix wrong with this probability (ours: no source gives a rate)"},
    {"wrong_fix_hold_s", kNumber, "s", "30", 0, 3600,
     "a wrong fix holds this × U[0.5, 1.5] until a residual test catches it (ours)"},
    {"wrong_fix_satellites", kInteger, "", "2", 1, 12, "satellites off by whole L1 cycles"},
    {"wrong_fix_cycles", kInteger, "cycles", "1", 1, 10, "each off by ±1…± this many cycles"},
    {"config", kMapping, "", "the receiver's defaults", 0, 0,
     "configuration saved in Flash before the run (zed_f9p.config)"},
    {"tx_buffer_bytes", kInteger, "B", "4096", 256, 1 << 20, "its UART1's transmit buffer"},
    {"raw_phase_noise_m", kNumber, "m", "0.003", 0, 0.05,
     "RXM-RAWX carrier phase noise (1σ; ours: a patch antenna's PLL)"},
    {"raw_code_multipath_m", kNumber, "m", "0.5", 0, 20,
     "RXM-RAWX code multipath at the horizon (× cos elevation; ours)"},
    {"raw_carrier_multipath_m", kNumber, "m", "0.004", 0, 0.05,
     "RXM-RAWX carrier multipath at the horizon (× cos elevation; ours)"},
    {"clock_drift_ppb", kNumber, "ppb", "50", -5000, 5000,
     "receiver clock rate (RXM-RAWX; stepped by 1 ms to stay within ±0.5 ms; ours: a TCXO)"},
};

// The configuration keys a scenario may save (the emulator's table, ubx_f9_config.cc).
inline constexpr ScenarioKey kZedF9pConfig[] = {
    {"CFG-RATE-MEAS", kInteger, "ms", "1000", 25, 65535, "measurement period"},
    {"CFG-RATE-NAV", kInteger, "", "1", 1, 127, "measurements per navigation solution"},
    {"CFG-UART1-BAUDRATE", kInteger, "Bd", "38400", 4800, 921600, "UART1's line rate"},
    {"CFG-UART1INPROT-UBX", kInteger, "", "1", 0, 1, "UART1 takes UBX"},
    {"CFG-UART1INPROT-NMEA", kInteger, "", "1", 0, 1, "UART1 takes NMEA"},
    {"CFG-UART1INPROT-RTCM3X", kInteger, "", "1", 0, 1, "UART1 takes RTCM 3"},
    {"CFG-UART1OUTPROT-UBX", kInteger, "", "1", 0, 1, "UART1 sends UBX"},
    {"CFG-UART1OUTPROT-NMEA", kInteger, "", "1", 0, 1, "UART1 sends NMEA"},
    {"CFG-UART1OUTPROT-RTCM3X", kInteger, "", "1", 0, 1, "UART1 sends RTCM 3 (a rover sends none)"},
    {"CFG-UART2-BAUDRATE", kInteger, "Bd", "38400", 4800, 921600,
     "UART2's line rate (the radio's bytes arrive at the base's baud)"},
    {"CFG-UART2INPROT-UBX", kInteger, "", "1", 0, 1, "UART2 takes UBX"},
    {"CFG-UART2INPROT-NMEA", kInteger, "", "0", 0, 1, "UART2 takes NMEA"},
    {"CFG-UART2INPROT-RTCM3X", kInteger, "", "1", 0, 1, "UART2 takes RTCM 3 (the radio)"},
    {"CFG-NAVHPG-DGNSSMODE", kInteger, "", "3", 2, 3, "2: RTK float only; 3: RTK fixed allowed"},
    {"CFG-NAVSPG-DYNMODEL", kInteger, "", "0", 0, 12, "dynamic platform model (not modelled)"},
    {"CFG-NAVSPG-CONSTR_DGNSSTO", kInteger, "s", "60", 0, 255,
     "corrections older than this are not used (float → 3-D)"},
    {"CFG-MSGOUT-UBX_NAV_PVT_UART1", kInteger, "", "0", 0, 255, "NAV-PVT every N epochs"},
    {"CFG-MSGOUT-UBX_NAV_SAT_UART1", kInteger, "", "0", 0, 255, "NAV-SAT every N epochs"},
    {"CFG-MSGOUT-UBX_NAV_HPPOSLLH_UART1", kInteger, "", "0", 0, 255, "NAV-HPPOSLLH every N"},
    {"CFG-MSGOUT-UBX_NAV_RELPOSNED_UART1", kInteger, "", "0", 0, 255, "NAV-RELPOSNED every N"},
    {"CFG-MSGOUT-UBX_RXM_RTCM_UART1", kInteger, "", "0", 0, 1, "RXM-RTCM for each RTCM message"},
    {"CFG-MSGOUT-UBX_RXM_RAWX_UART1", kInteger, "", "0", 0, 255,
     "RXM-RAWX (raw observations) every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_RMC_UART1", kInteger, "", "1", 0, 255, "GNRMC every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_VTG_UART1", kInteger, "", "1", 0, 255, "GNVTG every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_GGA_UART1", kInteger, "", "1", 0, 255, "GNGGA every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_GSA_UART1", kInteger, "", "1", 0, 255, "GNGSA every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_GSV_UART1", kInteger, "", "1", 0, 255, "GPGSV every N epochs"},
    {"CFG-MSGOUT-NMEA_ID_GLL_UART1", kInteger, "", "1", 0, 255, "GNGLL every N epochs"},
};

}  // namespace zed_f9p_keys

extern const KeySection kZedF9pSection{
    "zed_f9p", "a ZED-F9P-class RTK rover (issue 44; firmware_emu/rtk/zed_f9p_device.h)",
    zed_f9p_keys::kZedF9p};
extern const KeySection kZedF9pConfigSection{
    "zed_f9p.config", "the rover's saved configuration by key name (vectors/gnss/README.md)",
    zed_f9p_keys::kZedF9pConfig};

namespace {

using zed_f9p_keys::kZedF9p;
using zed_f9p_keys::kZedF9pConfig;

void ReadConfig(const YamlReader& y, rtk::ZedF9pConfig& c) {
  const KeyedReader<kZedF9pConfig> r(y);
  r.CheckKeys();
  for (const ScenarioKey& row : kZedF9pConfig) {
    const std::string name(row.name);
    if (!y.Has(name)) continue;
    const gnss::ubx::F9Key* k = gnss::ubx::FindF9Key(row.name);
    if (k == nullptr) y.Fail(name, "not a key of the emulated receiver");  // a table typo
    const auto v =
        y.Int(name, 0, static_cast<std::int64_t>(row.lo), static_cast<std::int64_t>(row.hi));
    c.flash.emplace_back(k->id, static_cast<std::uint64_t>(v));
  }
}

void ReadRtk(const KeyedReader<kZedF9p>& r, rtk::RoverRtkConfig& k) {
  k.time_to_float_s = r.Number("time_to_float_s", k.time_to_float_s);
  k.time_to_fix_s = r.Number("time_to_fix_s", k.time_to_fix_s);
  k.time_to_fix_per_km_s = r.Number("time_to_fix_per_km_s", k.time_to_fix_per_km_s);
  k.fixed_max_age_s = r.Number("fixed_max_age_s", k.fixed_max_age_s);
  k.fixed_cep_m = r.Number("fixed_cep_m", k.fixed_cep_m);
  k.fixed_ppm = r.Number("fixed_ppm", k.fixed_ppm);
  k.float_sigma_start_m = r.Number("float_sigma_start_m", k.float_sigma_start_m);
  k.float_sigma_end_m = r.Number("float_sigma_end_m", k.float_sigma_end_m);
  k.float_convergence_s = r.Number("float_convergence_s", k.float_convergence_s);
  gnss::WrongFixConfig& w = k.wrong_fix;
  w.probability = r.Number("wrong_fix_probability", w.probability);
  w.hold_s = r.Number("wrong_fix_hold_s", w.hold_s);
  w.satellites = static_cast<int>(r.Integer("wrong_fix_satellites", w.satellites));
  w.cycles = static_cast<int>(r.Integer("wrong_fix_cycles", w.cycles));
}

// The raw observations' receiver; the atmosphere is the rtk_base's (common to both sites).
void ReadRaw(const KeyedReader<kZedF9p>& r, const Scenario& s, rtk::ZedF9pConfig& c) {
  c.raw.phase_noise_m = r.Number("raw_phase_noise_m", c.raw.phase_noise_m);
  c.raw.code_multipath_m = r.Number("raw_code_multipath_m", c.raw.code_multipath_m);
  c.raw.carrier_multipath_m = r.Number("raw_carrier_multipath_m", c.raw.carrier_multipath_m);
  c.clock_drift_ppb = r.Number("clock_drift_ppb", c.clock_drift_ppb);
  if (!s.rtk_base.enabled) return;
  const rtk::BaseObservablesConfig& b = s.rtk_base.config.observables;
  c.raw.zenith_tropo_m = b.zenith_tropo_m;
  c.raw.vertical_iono_l1_m = b.vertical_iono_l1_m;
  c.raw.iono_shell_height_m = b.iono_shell_height_m;
}

void ReadMovingBase(const KeyedReader<kZedF9p>& r, rtk::ZedF9pConfig& c) {
  rtk::MovingBaseConfig mb;
  const auto arm = r.Doubles("moving_base_antenna_m", 3, {0, 0, 0});
  mb.p_BA_B_m = Eigen::Vector3d(arm[0], arm[1], arm[2]);
  mb.baud = static_cast<int>(r.Integer("moving_base_baud", mb.baud));
  c.moving_base = mb;
  c.heading_valid_max_acc_deg = r.Number("heading_valid_max_acc_deg", c.heading_valid_max_acc_deg);
  if ((mb.p_BA_B_m - c.model.p_BA_B_m).norm() < 0.1)
    r.Fail("moving_base_antenna_m", "the two antennas are less than 0.1 m apart");
}

}  // namespace

void ReadZedF9pSpec(const YamlReader& root, Scenario& s) {
  const auto y = root.OptionalChild("zed_f9p");
  if (!y) return;
  const KeyedReader<kZedF9p> r(*y);
  r.CheckKeys();
  ZedF9pDeviceSpec& f = s.zed_f9p;
  f.enabled = true;
  f.link = ReadLinkName(r, f.link);
  f.corrections = r.Choice("corrections", F9pCorrections::kRadio);
  f.navd_input = r.Bool("navd_input", f.navd_input);
  if (f.corrections == F9pCorrections::kRadio && !s.rtk_base.enabled)
    r.Fail("corrections", "radio needs an rtk_base section (its radio feeds UART2)");
  rtk::ZedF9pConfig& c = f.config;
  c.start_utc = s.start_utc;
  c.model.geoid = s.gnss.model.geoid;  // the receivers' geoid grid
  const auto lever = r.Doubles("antenna_lever_arm_m", 3, {0, 0, 0});
  c.model.p_BA_B_m = Eigen::Vector3d(lever[0], lever[1], lever[2]);
  c.output_lag = DurationFromSeconds(r.Number("output_lag_s", ToSeconds(c.output_lag)));
  ReadRtk(r, c.rtk);
  ReadRaw(r, s, c);
  if (f.corrections == F9pCorrections::kMovingBase) ReadMovingBase(r, c);
  if (auto cfg = r.OptionalChild("config")) ReadConfig(*cfg, c);
  f.tx_buffer_bytes = static_cast<std::size_t>(
      r.Integer("tx_buffer_bytes", static_cast<std::int64_t>(f.tx_buffer_bytes)));
}

}  // namespace hil::harness

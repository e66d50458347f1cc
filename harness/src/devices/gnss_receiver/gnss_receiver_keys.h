#pragma once
// Internal to the devices stage: the tables (scenario_keys.h) of the GNSS receivers' sections
// `gnss`, its sub-sections and the top-level `obstructions:` list, read by gnss_receiver_spec.cc
// and gnss_rough_spec.cc. Defaults are the code's (receiver_profile.cc, receiver_model.h,
// neo5m_device.h, sky_shading.h, rtk_solution.h, GnssDeviceSpec in scenario.h); the sources are
// those the code's comments and vectors/scenarios/README.md cite.
#include <string_view>

#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness::gnss_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::string_view kProfiles[] = {"neo-5m", "rtk"};
inline constexpr std::string_view kStarts[] = {"cold", "warm", "hot"};
inline constexpr std::string_view kGeoids[] = {"ublox5", "egm96"};
inline constexpr std::string_view kFaultKinds[] = {"outage", "obstruction", "step", "multipath",
                                                   "data_gap"};
inline constexpr std::string_view kObstacleKinds[] = {"tree_line", "building", "greenhouse"};

inline constexpr std::string_view kNoSource = "ours (the code cites no source)";

inline constexpr ScenarioKey kGnss[] = {
    {"profile", kChoice, "", "neo-5m", 0, 0,
     "the receiver: neo-5m (u-blox NEO-5M: NMEA RMC, VTG, GGA, GSA, GSV, GLL and UBX, metre-level "
     "errors) or rtk (an RTK rover: GGA quality 5 float, then 4 fixed, centimetre errors)",
     kProfiles},
    {"baud", kInteger, "Bd", "the profile's (neo-5m 9600, rtk 115200)", 1200, 921600,
     "the UART's line rate", kNoChoices, kAnyRange,
     "neo-5m: the NEO-5M's UART1 default, 9600 8N1 (receiver_profile.h); rtk: the profile's "
     "choice for seed 004 (receiver_profile.h)"},
    {"link", kString, "", "ttyGPS", 0, 0,
     "the first receiver's pty in the run folder (a plain file name); further receivers get "
     "LINK1, LINK2, …"},
    {"rate_hz", kNumber, "Hz", "the profile's (neo-5m 1, rtk 10)", 0.1, 20, "the navigation rate",
     kNoChoices, "[0.1, the profile's maximum: neo-5m 4, rtk 20]",
     "neo-5m: 1 Hz, the NEO-5M's default; its 4 Hz maximum is a u-blox 5 data sheet figure "
     "(shared/reference/ublox5.md §4, UNVERIFIED; receiver_profile.h); rtk: the profile's "
     "choice for seed 004"},
    {"output_lag_s", kNumber, "s", "0.1", 0, 0.9, "navigation epoch to the output's first byte",
     kNoChoices, kAnyRange, kNoSource},
    {"tx_buffer_bytes", kInteger, "B", "1024", 64, 1 << 20, "each receiver's UART transmit buffer",
     kNoChoices, kAnyRange, kNoSource},
    {"errors", kMapping, "", "the profile's", 0, 0, "the position error model (gnss.errors)"},
    {"antenna_lever_arm_m", kPoint, "m", "[0, 0, 0]", 0, 0,
     "[x, y, z] of the antenna phase centre from the body reference point, body frame FLU (with "
     "count > 1: the centre of the array's circle)"},
    {"start", kChoice, "", "hot", 0, 0,
     "the power-up's start, which sets the time to first fix: cold ≈ 29 s, warm ≈ 28 s, hot ≈ 1 s "
     "(rtk: hot 5 s)",
     kStarts, kAnyRange,
     "TTFF: a u-blox-5/6-class data sheet (fix_state.h); rtk's 5 s: the profile's choice"},
    {"count", kInteger, "", "1", 1, 8,
     "receivers on a horizontal circle around antenna_lever_arm_m, the first ahead, then every "
     "360°/count counter-clockwise (ignored when receivers is given)"},
    {"array_radius_m", kNumber, "m", "0", 0, 100, "the radius of that circle"},
    {"receivers", kList, "", "count receivers on the circle", 0, 0,
     "the receivers one by one (gnss.receivers[]); replaces count and array_radius_m"},
    {"faults", kList, "", "none", 0, 0, "the receivers' own fault timeline (gnss.faults[])"},
    {"geoid", kChoice, "", "ublox5", 0, 0,
     "the geoid height N at each fix (GGA altitude = ellipsoidal height − N): ublox5, EGM96 on "
     "10° nodes rounded to whole metres as a u-blox 5 applies it; egm96, NGA's 15' grid "
     "(PROJ's egm96_15.gtx, Debian proj-data)",
     kGeoids, kAnyRange,
     "ublox5 reproduces the GGA separations of the real u-blox 5 captures in "
     "shared/vectors/gpsd-ublox5 within 3 cm (vectors/scenarios/README.md)"},
    {"geoid_separation_m", kNumber, "m", "none: the geoid model", -200, 200,
     "a fixed geoid height N in place of geoid (not both)"},
    {"multipath", kMapping, "", "the defaults below", 0, 0,
     "the receiver's signal thresholds, used with obstructions (gnss.multipath)"},
    {"rtk", kMapping, "", "none: float for 20 s after each (re)acquisition, then fixed", 0, 0,
     "profile rtk only: the rough RTK solution (gnss.rtk)", kNoChoices, kAnyRange,
     "20 s: the rtk profile's rtk_fixed_after_s (receiver_profile.h), ours"},
};

inline constexpr ScenarioKey kErrors[] = {
    {"horizontal_sigma_m", kNumber, "m", "the profile's (neo-5m 0.35, rtk 0.008)", 0, 100,
     "1σ of the east and of the north error at HDOP 1 (errors grow with the epoch's DOP)",
     kNoChoices, kAnyRange,
     "neo-5m: ours (the code cites no source); rtk: ours, the profile's \"centimetres\""},
    {"vertical_sigma_m", kNumber, "m", "the profile's (neo-5m 0.8, rtk 0.015)", 0, 100,
     "1σ of the up error at VDOP 1.6", kNoChoices, kAnyRange,
     "neo-5m: ours (the code cites no source); rtk: ours, the profile's \"centimetres\""},
    {"correlation_time_s", kNumber, "s", "the profile's (neo-5m 4.5, rtk 30)", 0.01, 3600,
     "correlation time of the first-order Gauss–Markov position errors", kNoChoices, kAnyRange,
     "neo-5m: ours, a lag-1 autocorrelation ≈ 0.8 at 1 Hz, the smooth drift of real u-blox 5 "
     "captures (receiver_model.h); rtk: ours"},
    {"velocity_sigma_mps", kNumber, "m/s", "the profile's (neo-5m 0.03, rtk 0.01)", 0, 10,
     "white velocity noise per axis (a small speed when standing)", kNoChoices, kAnyRange,
     kNoSource},
    {"common_fraction", kNumber, "", "the profile's (neo-5m 0.46, rtk 0)", 0, 1,
     "share of the position error variance common to all receivers of the scenario (atmosphere, "
     "orbits): averaging N receivers reduces the error RMS to σ·√(c + (1 − c)/N)",
     kNoChoices, kAnyRange,
     "neo-5m: seed 000's paper, 39.1 cm for one receiver and 31.3 cm for three "
     "(receiver_model.h); rtk: ours"},
};

inline constexpr ScenarioKey kReceiver[] = {
    {"link", kString, "", "gnss.link, then gnss.link + i", 0, 0,
     "the receiver's pty in the run folder (a plain file name, unique)"},
    {"antenna_lever_arm_m", kPoint, "m", "gnss.antenna_lever_arm_m", 0, 0,
     "[x, y, z] of its antenna from the body reference point, FLU"},
};

inline constexpr ScenarioKey kFault[] = {
    {"kind", kChoice, "", "outage", 0, 0,
     "outage: no fix; obstruction: satellites below elevation_deg lost; step: the position jumps "
     "by offset_m; multipath: extra error of sigma_m; data_gap: the output removed, the receiver "
     "keeps its fix",
     kFaultKinds},
    {"start_s", kNumber, "s", "0", 0, 1e7, "the fault's start (scenario time)"},
    {"end_s", kNumber, "s", "required (after start_s)", 0, 1e7, "the fault's end"},
    {"elevation_deg", kNumber, "deg", "30", 0, 90,
     "obstruction: satellites below this elevation are lost", kNoChoices, kAnyRange, kNoSource},
    {"offset_m", kPoint, "m", "[0, 0, 0]", 0, 0, "step: the position's jump [east, north, up]"},
    {"sigma_m", kNumber, "m", "3", 0, 1000,
     "multipath: 1σ per axis of the burst's extra error (2 s correlation time)", kNoChoices,
     kAnyRange, kNoSource},
};

inline constexpr ScenarioKey kMultipath[] = {
    {"track_min_dbhz", kNumber, "dBHz", "15", 0, 60, "below this C/N0 a satellite is not tracked",
     kNoChoices, kAnyRange,
     "u-blox 5 tracking sensitivity −160 dBm ≈ 14 dBHz with a 2 dB noise figure "
     "(shared/reference/ublox5.md, UNVERIFIED)"},
    {"nav_min_dbhz", kNumber, "dBHz", "20", 0, 60,
     "below this C/N0 a tracked satellite is not used (≥ track_min_dbhz)", kNoChoices, kAnyRange,
     "ours (no source found)"},
    {"correlator_spacing_chip", kNumber, "chip", "0.5", 0.01, 2,
     "early–late spacing of the code tracking loop (DLL)", kNoChoices, kAnyRange,
     "ours (the NEO-5M's is not published)"},
};

inline constexpr std::string_view kRtkChoice = "ours (a scenario choice: no source gives it)";

inline constexpr ScenarioKey kRtk[] = {
    {"time_to_fix_s", kNumber, "s", "20", 0, 3600,
     "float time after each (re)acquisition before the fix", kNoChoices, kAnyRange, kRtkChoice},
    {"time_to_fix_spread_s", kNumber, "s", "0", 0, 3600, "plus a uniform draw in [0, this]",
     kNoChoices, kAnyRange, kRtkChoice},
    {"refix_s", kNumber, "s", "5", 0, 3600, "float time after a fix was lost while tracking",
     kNoChoices, kAnyRange, kRtkChoice},
    {"float_sigma_m", kNumber, "m", "0.3", 0, 100,
     "float error per horizontal axis at the start (vertical 1.5 ×)", kNoChoices, kAnyRange,
     kRtkChoice},
    {"float_converged_sigma_m", kNumber, "m", "0.05", 0, 100,
     "the float error it converges to (≤ float_sigma_m); the fix removes it at once", kNoChoices,
     kAnyRange, kRtkChoice},
    {"float_convergence_s", kNumber, "s", "30", 0.1, 36000, "the convergence's time constant",
     kNoChoices, kAnyRange, kRtkChoice},
    {"float_correlation_s", kNumber, "s", "10", 0.1, 3600, "correlation time of the float error",
     kNoChoices, kAnyRange, kRtkChoice},
    {"min_sats_fixed", kInteger, "", "6", 4, 32,
     "fewer used line-of-sight satellites of C/N0 ≥ fix_min_dbhz and the fix falls back to float",
     kNoChoices, kAnyRange, kRtkChoice},
    {"fix_min_dbhz", kNumber, "dBHz", "0", 0, 60,
     "C/N0 from which a satellite's carrier counts for the fix", kNoChoices, kAnyRange, kRtkChoice},
    {"wrong_fix_probability", kNumber, "", "0", 0, 1,
     "probability that a fix is wrong (each fix draws once)", kNoChoices, kAnyRange, kRtkChoice},
    {"wrong_fix_hold_s", kNumber, "s", "30", 0.1, 36000,
     "a wrong fix holds this × a uniform draw in [0.5, 1.5] (or until one of its satellites is "
     "lost)",
     kNoChoices, kAnyRange, kRtkChoice},
    {"wrong_fix_satellites", kInteger, "", "2", 1, 12,
     "a wrong fix: this many satellites off by whole L1 cycles", kNoChoices, kAnyRange, kRtkChoice},
    {"wrong_fix_cycles", kInteger, "", "1", 1, 10, "… by ±1 … ±this many cycles (19 cm each)",
     kNoChoices, kAnyRange, kRtkChoice},
};

inline constexpr ScenarioKey kObstacle[] = {
    {"kind", kChoice, "", "required", 0, 0,
     "tree_line (hedgerows too), building (opaque) or greenhouse (without from_m and centre_m: the "
     "greenhouse: section's walls)",
     kObstacleKinds},
    {"from_m", kPoint, "m", "required for a segment", 0, 0,
     "a segment footprint's start [x, y] (ENU; with to_m and width_m)"},
    {"to_m", kPoint, "m", "required for a segment", 0, 0, "the segment's end [x, y]"},
    {"width_m", kNumber, "m", "4", 0.01, 1000, "the segment's width", kNoChoices, kAnyRange,
     kNoSource},
    {"centre_m", kPoint, "m", "required for a rectangle", 0, 0,
     "a rectangle footprint's centre [x, y] (with size_m; not with from_m)"},
    {"size_m", kPoint, "m", "required for a rectangle", 0, 0,
     "the rectangle's [length, width], both > 0"},
    {"heading_deg", kNumber, "deg", "0", -360, 360,
     "the rectangle's length direction, counter-clockwise from east"},
    {"height_m", kNumber, "m", "required (greenhouse from the section: its wall_height_m)", 0.01,
     1000, "height of the prism standing on the ground (z = 0)"},
    {"loss_db", kNumber, "dB", "by kind (tree_line 0, greenhouse 3)", 0, 200,
     "loss of a direct signal crossing it (not for a building)", kNoChoices, kAnyRange,
     "greenhouse 3 dB: ours (no source gives it for these structures)"},
    {"loss_db_per_m", kNumber, "dB/m", "by kind (tree_line 0.5, greenhouse 0)", 0, 100,
     "plus this per metre of slant path inside it (not for a building)", kNoChoices, kAnyRange,
     "tree_line: Weissberger's modified exponential decay model at 1.575 GHz for foliage depths "
     "below 14 m, as ITU-R P.833 quotes it (roadside trees measure 10–20 dB, ITU-R P.681: dense "
     "hedges raise it)"},
    {"max_loss_db", kNumber, "dB", "by kind (tree_line 25, greenhouse 25)", 0, 200,
     "cap of one crossing's loss (not for a building)", kNoChoices, kAnyRange,
     "ours (no source gives it for these structures)"},
    {"reflection_amplitude", kNumber, "", "by kind (tree_line 0.2, building 0.5, greenhouse 0.3)",
     0, 1,
     "amplitude, relative to the direct signal, of the specular reflection off its vertical faces",
     kNoChoices, kAnyRange, "ours (no source gives it for these structures)"},
};

}  // namespace hil::harness::gnss_keys

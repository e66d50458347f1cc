#pragma once
// Internal to the harness: the tables of the truth's sections (scenario_keys.h), read by
// scenario_truth.cc. One row per key; a key is added by adding its row and reading it.
#include <array>
#include <string_view>

#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness::truth_keys {

using enum KeyType;

inline constexpr std::array<std::string_view, 4> kVehicleModels{"bicycle", "tractor", "diff_drive",
                                                                "skid_steer"};
inline constexpr std::array<std::string_view, 6> kPathTypes{
    "line", "ab_line", "waypoints", "rectangle", "boustrophedon", "circle"};
inline constexpr std::array<std::string_view, 2> kTurnSides{"right", "left"};
inline constexpr std::array<std::string_view, 2> kDirections{"left", "right"};
inline constexpr std::array<std::string_view, 3> kTerrainTypes{"flat", "plane", "rough"};

inline constexpr ScenarioKey kOrigin[] = {
    {"lat_deg", kNumber, "deg", "required", -90, 90,
     "geodetic latitude (WGS84) of the local ENU frame's origin N"},
    {"lon_deg", kNumber, "deg", "required", -180, 180,
     "longitude (WGS84) of the origin, east positive"},
    {"height_m", kNumber, "m", "0", -500, 9000,
     "ellipsoidal height of the origin above the WGS84 ellipsoid, NOT above mean sea level: the "
     "geoid separation (gnss.geoid) lies between them (−17.2 m at the Karaj origin): a height "
     "read off a map, or a receiver's MSL altitude, needs the geoid separation added"},
};

// Where the vehicle presets' figures come from (vehicle.h): paper 003's platform for bicycle
// (shared/reference/seeds_001_003.md B.3); the other presets' figures are ours.
inline constexpr std::string_view kSrcWheelbase =
    "bicycle 0.84: paper 003's platform, track / wheelbase 550 / 840 mm "
    "(shared/reference/seeds_001_003.md B.3); tractor 2.3: ours, an LX704-class tractor "
    "(vehicle.h cites no source)";
inline constexpr std::string_view kSrcTrack =
    "bicycle 0.55: paper 003's platform (seeds_001_003.md B.3); tractor 1.6: ours (vehicle.h cites "
    "no source); diff_drive 0.5: ours (paper 001 gives no track, seeds_001_003.md A); skid_steer "
    "0.5: ours (vehicle.h)";
inline constexpr std::string_view kSrcMaxSteer =
    "bicycle 32: paper 003's steering angle −32° … +32° (seeds_001_003.md B.3); tractor 35: ours "
    "(vehicle.h cites no source)";
inline constexpr std::string_view kVehicleOurs = "ours (vehicle.h cites no source)";
inline constexpr std::string_view kSrcIcr =
    "ours: a choice, not a measurement (vehicle.h); the model is Mandow et al. 2007's";

inline constexpr ScenarioKey kVehicle[] = {
    {"model", kChoice, "", "bicycle", 0, 0,
     "the vehicle model and its preset: bicycle (seed 003's front-steered greenhouse platform), "
     "tractor (an LX704-class tractor), diff_drive (seed 001's differential drive, turns in "
     "place), skid_steer (a skid-steered base whose tracks slip in a turn: the ICR kinematics of "
     "Martínez et al. 2005 and Mandow et al. 2007, harness/truth vehicle.h)",
     kVehicleModels},
    {"wheelbase_m", kNumber, "m", "by model (bicycle 0.84, tractor 2.3)", 0.1, 20,
     "bicycle, tractor: distance L from the rear axle (the reference point) to the front axle",
     kNoChoices, kAnyRange, kSrcWheelbase},
    {"track_m", kNumber, "m", "by model (0.55, 1.6, 0.5, 0.5)", 0.1, 10,
     "distance between the left and right wheels' (tracks') centre lines", kNoChoices, kAnyRange,
     kSrcTrack},
    {"max_steer_deg", kNumber, "deg", "by model (32, 35)", 1, 60,
     "bicycle, tractor: the front wheels' angle limit", kNoChoices, kAnyRange, kSrcMaxSteer},
    {"max_steer_rate_dps", kNumber, "deg/s", "by model (30, 20)", 0.5, 360,
     "bicycle, tractor: the steering rate limit", kNoChoices, kAnyRange, kVehicleOurs},
    {"steer_lag_s", kNumber, "s", "by model (0.2, 0.3)", 0.01, 10,
     "bicycle, tractor: the steering's first-order lag", kNoChoices, kAnyRange, kVehicleOurs},
    {"speed_lag_s", kNumber, "s", "by model (0.5, 1.0, 0.3, 0.3)", 0.01, 60,
     "the forward speed's first-order lag (open loop; closed loop uses the actuator's)", kNoChoices,
     kAnyRange, kVehicleOurs},
    {"yaw_rate_lag_s", kNumber, "s", "0.2", 0.01, 10,
     "diff_drive, skid_steer: the yaw rate's first-order lag", kNoChoices, kAnyRange, kVehicleOurs},
    {"max_yaw_rate_dps", kNumber, "deg/s", "45", 1, 360,
     "diff_drive, skid_steer: the commanded yaw rate's limit", kNoChoices, kAnyRange, kVehicleOurs},
    {"icr_expansion", kNumber, "", "1.5", 1, 4,
     "skid_steer: χ = (y_l − y_r) / track_m, how much farther apart the tracks' instantaneous "
     "centres of rotation lie than the tracks (1: no skid, a differential drive); the yaw rate is "
     "(v_r − v_l) / (χ·track_m) and the turning radius χ times a differential drive's for the "
     "same track speeds (Mandow et al. 2007; the default is a choice, not a measurement)",
     kNoChoices, kAnyRange, kSrcIcr},
    {"icr_offset_m", kNumber, "m", "0.05", -2, 2,
     "skid_steer: x_v, the ICRs' distance ahead of the reference point (axle centre); the "
     "reference point slips sideways at −x_v·ω in a turn (the default is a choice)",
     kNoChoices, kAnyRange, kSrcIcr},
    {"slip_gain_rad_per_mps2", kNumber, "rad/(m/s²)", "0", 0, 0.2,
     "lateral slip of any model: the velocity turns β = −k·v·ψ̇ to the outside of a turn",
     kNoChoices, kAnyRange, "ours: no lateral slip unless a scenario sets it"},
    {"speed_variation", kMapping, "", "none", 0, 0,
     "the commanded speed × (1 + x(t)), x a Gauss–Markov process (governor droop, wheel slip on "
     "soil, load)"},
};

inline constexpr ScenarioKey kSpeedVariation[] = {
    {"std_percent", kNumber, "%", "0", 0, 50, "x's standard deviation"},
    {"correlation_time_s", kNumber, "s", "5", 0.1, 3600, "x's correlation time"},
    {"seed", kInteger, "", "1", 0, 9.3e18, "the seed of x's draws"},
};

inline constexpr ScenarioKey kPath[] = {
    {"type", kChoice, "", "line", 0, 0,
     "line: open loop from the start pose; the others are followed by pure pursuit", kPathTypes},
    {"speed_kmh", kNumber, "km/h", "1.6", 0, 100, "nominal forward speed (or speed_mps)"},
    {"speed_mps", kNumber, "m/s", "0.444", 0, 30, "nominal forward speed (or speed_kmh)"},
    {"speed_profile", kList, "", "none", 0, 0, "steps of the nominal speed (0: stop)"},
    {"start_enu_m", kPoint, "m", "the path's start", 0, 0,
     "start point [east, north] of the reference point (within 1000 km)"},
    {"heading_deg", kNumber, "deg", "the first segment's", -360, 360,
     "initial heading, clockwise from north"},
    {"steer_deg", kNumber, "deg", "0", -60, 60,
     "line, bicycle/tractor: the constant front-wheel angle, left positive", kNoChoices,
     "±vehicle.max_steer_deg"},
    {"yaw_rate_dps", kNumber, "deg/s", "0", -360, 360,
     "line, diff_drive/skid_steer: the constant commanded yaw rate, left positive (speed 0: turn "
     "in place)",
     kNoChoices, "±vehicle.max_yaw_rate_dps"},
    {"a_enu_m", kPoint, "m", "required", 0, 0, "ab_line: point A [east, north]"},
    {"b_enu_m", kPoint, "m", "required", 0, 0,
     "ab_line: point B (≥ 0.1 m from A); driven from A through B and on"},
    {"points", kList, "", "required", 0, 0,
     "waypoints: [[east, north], ...] or entries of path.points[] (≥ 2)"},
    {"corner_enu_m", kPoint, "m", "[-7, -7]", 0, 0, "rectangle: the first corner"},
    {"width_m", kNumber, "m", "15", 0.5, 1e5, "rectangle: the first side's length"},
    {"height_m", kNumber, "m", "15", 0.5, 1e5, "rectangle: the second side's length"},
    {"side_heading_deg", kNumber, "deg", "0", -360, 360,
     "rectangle: the first side's heading, clockwise from north"},
    {"clockwise", kBool, "", "true", 0, 0, "rectangle: driven clockwise"},
    {"laps", kInteger, "", "1", 1, 1000, "rectangle, circle: laps driven"},
    {"row_start_enu_m", kPoint, "m", "[0, 0]", 0, 0, "boustrophedon: the first row's start"},
    {"row_heading_deg", kNumber, "deg", "0", -360, 360,
     "boustrophedon: the first row's heading, clockwise from north"},
    {"row_length_m", kNumber, "m", "100", 1, 1e5, "boustrophedon: a row's length"},
    {"row_spacing_m", kNumber, "m", "7.5", 0.2, 1000,
     "boustrophedon: distance between rows (≥ 2 × turn_radius_m)"},
    {"rows", kInteger, "", "4", 1, 10000, "boustrophedon: number of rows"},
    {"turn_radius_m", kNumber, "m", "the tighter of 1.05 × the vehicle's and row_spacing_m / 2",
     0.1, 1000, "boustrophedon: the headland turns' radius (≥ the vehicle's minimum)"},
    {"first_turn", kChoice, "", "right", 0, 0, "boustrophedon: side of the first headland turn",
     kTurnSides},
    {"turn_speed_mps", kNumber, "m/s", "the path speed", 0.05, 30,
     "boustrophedon: speed in the headland turns"},
    {"centre_enu_m", kPoint, "m", "[0, 0]", 0, 0, "circle: the centre"},
    {"radius_m", kNumber, "m", "5", 0.2, 1e5, "circle: the radius"},
    {"start_bearing_deg", kNumber, "deg", "180", -360, 360,
     "circle: bearing of the start point from the centre, clockwise from north"},
    {"direction", kChoice, "", "left", 0, 0, "circle: turning direction", kDirections},
    {"lookahead_m", kNumber, "m", "2 (boustrophedon 3)", 0.1, 50,
     "guided types: pure pursuit's look-ahead distance"},
    {"guidance_rate_hz", kNumber, "Hz", "50", 1, 1000, "guided types: guidance update rate"},
    {"stop_decel_mps2", kNumber, "m/s²", "0.3", 0.01, 10,
     "guided types: speed limit √(2·a·distance) before a stop"},
    {"turn_in_place_deg", kNumber, "deg", "30", 1, 180,
     "guided types, diff_drive/skid_steer: a vertex turning more is taken by stopping and turning "
     "in place"},
};

inline constexpr ScenarioKey kPathPoint[] = {
    {"enu_m", kPoint, "m", "required", 0, 0, "the waypoint [east, north]"},
    {"speed_mps", kNumber, "m/s", "the path speed", 0, 30,
     "speed on the segment from here (or speed_kmh)"},
    {"speed_kmh", kNumber, "km/h", "the path speed", 0, 100, "speed on the segment from here"},
    {"stop_s", kNumber, "s", "0", 0, 86400, "stop here this long"},
};

inline constexpr ScenarioKey kSpeedStep[] = {
    {"t_s", kNumber, "s", "required", 0, 7 * 86400, "time of the step (increasing)"},
    {"speed_mps", kNumber, "m/s", "required (or speed_kmh)", 0, 30, "speed from t_s on"},
    {"speed_kmh", kNumber, "km/h", "required (or speed_mps)", 0, 100, "speed from t_s on"},
};

inline constexpr ScenarioKey kTerrain[] = {
    {"type", kChoice, "", "flat", 0, 0,
     "flat: the tangent plane at the origin; plane: a slope; rough: a seeded sum of sinusoids",
     kTerrainTypes},
    {"height_m", kNumber, "m", "0", -1000, 1000, "ground height above the tangent plane"},
    {"slope_deg", kNumber, "deg", "0", -45, 45, "plane, rough: the slope"},
    {"uphill_heading_deg", kNumber, "deg", "0", -360, 360,
     "plane, rough: the uphill direction, clockwise from north"},
    {"amplitude_m", kNumber, "m", "0.05", 0, 2, "rough: the bumps' amplitude"},
    {"min_wavelength_m", kNumber, "m", "3", 0.5, 1000, "rough: the shortest wavelength"},
    {"max_wavelength_m", kNumber, "m", "20", 0.5, 1000,
     "rough: the longest wavelength (≥ min_wavelength_m)"},
    {"waves", kInteger, "", "8", 1, 64, "rough: number of sinusoids"},
    {"seed", kInteger, "", "1", 0, 9.3e18, "rough: the sinusoids' seed"},
};

inline constexpr ScenarioKey kVibration[] = {
    {"components", kList, "", "required", 0, 0, "sinusoids (vibration.components[])"},
};

inline constexpr ScenarioKey kVibrationComponent[] = {
    {"frequency_hz", kNumber, "Hz", "required", 0.1, 200, "frequency"},
    {"heave_accel_mps2", kNumber, "m/s²", "0", 0, 50, "vertical acceleration amplitude"},
    {"roll_rate_dps", kNumber, "deg/s", "0", 0, 200, "roll rate amplitude"},
    {"pitch_rate_dps", kNumber, "deg/s", "0", 0, 200, "pitch rate amplitude"},
    {"phase_deg", kNumber, "deg", "0", -360, 360, "phase"},
};

inline constexpr ScenarioKey kTruthOptions[] = {
    {"earth_rotation", kBool, "", "true", 0, 0,
     "Earth rate in the gyro truth and Coriolis in the specific force"},
    {"rtol", kNumber, "", "1e-10", 1e-13, 1e-4, "CVODE's relative tolerance"},
    {"atol_m", kNumber, "m", "1e-9", 1e-13, 1e-3,
     "CVODE's absolute tolerance on positions (angles: atol_m / 10 rad)"},
};

}  // namespace hil::harness::truth_keys

#pragma once
// Internal to the devices stage: the tables (scenario_keys.h) of the IMU board's `mcu:` section and
// its sub-sections, read by mcu_spec.cc and mcu_rough_spec.cc. Defaults are the code's (McuConfig
// in mcu_config.h, sensor_spec.cc, rough_imu_spec.h, imu_kinematics.h, j1939_imu.h); the sources
// those its comments and vectors/mcu/ cite.
#include <string_view>

#include "hil/harness/scenario/scenario_keys.h"

namespace hil::harness::mcu_keys {  // named: the unity build joins the devices' files

using enum KeyType;

inline constexpr std::string_view kProfiles[] = {"razor-v13", "consumer-mems", "industrial-mems",
                                                 "tactical"};
inline constexpr std::string_view kFieldProfiles[] = {
    "razor_small_engine_robot", "consumer_mems_car", "consumer_mems_tractor_cab",
    "industrial_mems_tractor"};
inline constexpr std::string_view kFormats[] = {"binary", "razor-raw", "razor-v19"};
inline constexpr std::string_view kFaultKinds[] = {"drop_frames", "sequence_jump", "corrupt_bytes",
                                                   "stuck_sensor", "reset"};
inline constexpr std::string_view kSensors[] = {"accel", "gyro", "mag", "all"};

inline constexpr std::string_view kNoSource = "ours (the code cites no source)";
inline constexpr std::string_view kProfileSource =
    "the profile's: firmware_emu/src/mcu/sensor_spec.cc and vectors/mcu/imu_error_model.md cite "
    "each figure";

inline constexpr ScenarioKey kMcu[] = {
    {"profile", kChoice, "", "razor-v13", 0, 0,
     "the IMU's grade: razor-v13 (SparkFun 9DOF Razor v13, seed 000), consumer-mems (MPU-6000 "
     "class), industrial-mems (ADIS16465 class), tactical (HG1700 / ADIS16488 class)",
     kProfiles, kAnyRange, kProfileSource},
    {"imu_profile", kChoice, "", "none", 0, 0,
     "a field profile in place of profile: the sensor with its rough terms and the vehicle's "
     "vibration (vectors/mcu/imu_error_model.md)",
     kFieldProfiles, kAnyRange, kProfileSource},
    {"rough", kMapping, "", "off (the profile's)", 0, 0,
     "the field-rough model: vibration front end, error terms, temperature profile, time tag "
     "(mcu.rough)"},
    {"baud", kInteger, "Bd", "the profile's (razor-v13 57600, the others 115200)", 1200, 4000000,
     "the UART's line rate", kNoChoices, kAnyRange,
     "razor-v13: the stock firmware's default and maximum at 8 MHz (sensor_spec.cc); the others: "
     "ours"},
    {"link", kString, "", "ttyIMU", 0, 0, "its pty in the run folder (a plain file name)"},
    {"format", kChoice, "", "binary", 0, 0,
     "what it writes: binary (vectors/mcu/mcu_frame_protocol.md), razor-raw (stock Razor text "
     "`$,…,#`), razor-v19 (Razor v19 `!Data:…#`)",
     kFormats},
    {"imu_rate_hz", kNumber, "Hz", "10 × gnss.rate_hz", 0.1, 2000, "IMU sample rate", kNoChoices,
     kAnyRange, "seed 000's paper: the IMU at 10 times the GPS rate"},
    {"mag_rate_hz", kNumber, "Hz", "the profile's (10)", 0.1, 200,
     "compass output rate (its own oscillator)", kNoChoices, kAnyRange,
     "razor-v13: the HMC5843's default output rate (sensor_spec.cc); the others: ours"},
    {"crystal_ppm", kNumber, "ppm", "0", -1000, 1000,
     "the MCU tick rate's offset from its nominal 1 MHz"},
    {"mag_oscillator_ppm", kNumber, "ppm", "0", -50000, 50000,
     "the compass output-rate oscillator's offset"},
    {"jitter_us", kNumber, "µs", "0", 0, 10000,
     "interrupt latency of each sample, uniform in [0, jitter_us]"},
    {"output_latency_s", kNumber, "s", "0.0005", 0, 0.5, "sample to frame ready for the UART",
     kNoChoices, kAnyRange, kNoSource},
    {"reboot_s", kNumber, "s", "0.2", 0.001, 60, "silent time after a reset", kNoChoices, kAnyRange,
     kNoSource},
    {"time_pulse", kBool, "", "true", 0, 0, "the receiver's PPS is wired to the MCU"},
    {"tx_buffer_bytes", kInteger, "B", "4096", 64, 1 << 20, "its UART's transmit buffer",
     kNoChoices, kAnyRange, kNoSource},
    {"lever_arm_m", kPoint, "m", "[0, 0, 0]", 0, 0,
     "[x, y, z] of the board from the body reference point, body frame FLU"},
    {"mounting_rpy_deg", kPoint, "deg", "[0, 0, 0]", 0, 0,
     "the board's rotation I → B as [roll, pitch, yaw], applied yaw·pitch·roll"},
    {"magnetic", kMapping, "", "the defaults below", 0, 0,
     "the compass's magnetic environment (mcu.magnetic)"},
    {"vibration", kList, "", "none", 0, 0, "sinusoids the board feels (mcu.vibration[])"},
    {"temperature", kMapping, "", "25 °C, constant", 0, 0,
     "the board's temperature (mcu.temperature)"},
    {"can", kMapping, "", "no CAN output", 0, 0, "the J1939 IMU frames (mcu.can)"},
    {"faults", kList, "", "none", 0, 0, "the firmware's fault timeline (mcu.faults[])"},
};

inline constexpr ScenarioKey kMagnetic[] = {
    {"field_enu_uT", kPoint, "µT", "[3, 28, -40]", 0, 0, "the local Earth field [east, north, up]",
     kNoChoices, kAnyRange,
     "ours: about the field at Karaj, Iran (imu_kinematics.h names no model)"},
    {"hard_iron_uT", kPoint, "µT", "[0, 0, 0]", 0, 0, "a constant offset in the board frame"},
    {"soft_iron", kPoint, "", "[1, 0, 0, 0, 1, 0, 0, 0, 1]", 0, 0,
     "3 × 3 matrix, row by row, multiplying the field in the board frame"},
};

inline constexpr ScenarioKey kVibrationTone[] = {
    {"frequency_hz", kNumber, "Hz", "0", 0, 5000, "the tone's frequency"},
    {"accel_amplitude_mps2", kPoint, "m/s²", "[0, 0, 0]", 0, 0,
     "acceleration amplitude per board axis"},
    {"gyro_amplitude_dps", kPoint, "deg/s", "[0, 0, 0]", 0, 0, "angular rate amplitude per axis"},
};

inline constexpr ScenarioKey kTemperature[] = {
    {"start_c", kNumber, "°C", "25", -40, 85, "the board's temperature at t = 0", kNoChoices,
     kAnyRange, kNoSource},
    {"rate_c_per_h", kNumber, "°C/h", "0", -100, 100, "linear warm-up"},
};

inline constexpr ScenarioKey kCan[] = {
    {"enabled", kBool, "", "true", 0, 0, "send the J1939 frames (needs the scenario's can bus)"},
    {"source_address", kInteger, "", "226 (0xE2)", 0, 253, "the frames' J1939 source address",
     kNoChoices, kAnyRange, kNoSource},
    {"priority", kInteger, "", "3", 0, 7, "the frames' J1939 priority", kNoChoices, kAnyRange,
     kNoSource},
    {"ari_every", kInteger, "", "1", 1, 1000, "one angular rate frame (ARI) per this many samples"},
    {"accs_every", kInteger, "", "1", 1, 1000, "one acceleration frame (ACCS) per this many"},
    {"ssi2_every", kInteger, "", "1", 1, 1000, "one slope frame (SSI2) per this many"},
    {"time_pulse", kBool, "", "true", 0, 0, "HIL_TIME_PULSE once per GPS time pulse"},
    {"latency_s", kNumber, "s", "0.001", 0, 0.125, "sample instant to frame on the bus", kNoChoices,
     kAnyRange, kNoSource},
};

inline constexpr ScenarioKey kMcuFault[] = {
    {"kind", kChoice, "", "required", 0, 0,
     "drop_frames: frames lost with probability during the fault; sequence_jump: the counter "
     "jumps by amount; corrupt_bytes: one byte of a frame flipped with probability; stuck_sensor: "
     "sensor repeats its counts; reset: silent for duration_s (0: reboot_s), then a restart",
     kFaultKinds},
    {"start_s", kNumber, "s", "0", 0, 7 * 86400, "the fault's start (scenario time)"},
    {"duration_s", kNumber, "s", "0", 0, 7 * 86400,
     "its length (> 0 for drop_frames, corrupt_bytes, stuck_sensor)"},
    {"probability", kNumber, "", "1", 0, 1, "drop_frames, corrupt_bytes: per frame"},
    {"amount", kInteger, "", "1", 1, 65535, "sequence_jump: the extra counter steps"},
    {"sensor", kChoice, "", "all", 0, 0, "stuck_sensor: which", kSensors},
};

inline constexpr ScenarioKey kRough[] = {
    {"internal_rate_hz", kNumber, "Hz", "0 (the field profile's)", 0, 20000,
     "rate of the front end's internal loop (vibration, clipping, anti-alias); 0: no front end; "
     "else ≥ 4 × imu_rate_hz",
     kNoChoices, kAnyRange, kProfileSource},
    {"accel_aaf_hz", kNumber, "Hz", "0: the accelerometer's bandwidth_hz", 0, 10000,
     "second-order Butterworth anti-alias cutoff, < internal_rate_hz / 2", kNoChoices, kAnyRange,
     kProfileSource},
    {"gyro_aaf_hz", kNumber, "Hz", "0: the gyro's bandwidth_hz", 0, 10000,
     "the gyro's anti-alias cutoff, < internal_rate_hz / 2", kNoChoices, kAnyRange, kProfileSource},
    {"rpm", kList, "", "none (the field profile's)", 0, 0,
     "crank speed over time, piecewise linear (mcu.rough.rpm[])"},
    {"engine_orders", kList, "", "none (the field profile's)", 0, 0,
     "sinusoids at order × RPM / 60 (mcu.rough.engine_orders[]); a list replaces the profile's"},
    {"ride", kList, "", "none (the field profile's)", 0, 0,
     "bands of broadband ride vibration (mcu.rough.ride[])"},
    {"ride_reference_speed_mps", kNumber, "m/s", "0 (the field profile's)", 0, 100,
     "forward speed at which the ride bands' PSDs hold; each PSD scales with |speed| / this "
     "(ISO 8608 terrain, waviness 2: the acceleration PSD grows with speed), so a standing "
     "vehicle has no ride; 0: the PSDs at any speed",
     kNoChoices, kAnyRange, kProfileSource},
    {"mount", kMapping, "", "rigid (the field profile's)", 0, 0,
     "the board mount's resonance (mcu.rough.mount)"},
    {"temperature_profile", kList, "", "none: mcu.temperature", 0, 0,
     "board temperature over time, piecewise linear (mcu.rough.temperature_profile[])"},
    {"time_tag", kMapping, "", "exact (the field profile's)", 0, 0,
     "the sample's time tag (mcu.rough.time_tag)"},
    {"accel", kMapping, "", "the profile's", 0, 0,
     "the accelerometer's error terms (mcu.rough.accel)"},
    {"gyro", kMapping, "", "the profile's", 0, 0, "the gyro's error terms (mcu.rough.gyro)"},
};

inline constexpr ScenarioKey kRpmPoint[] = {
    {"t_s", kNumber, "s", "0", 0, 7 * 86400, "time of the point (increasing)"},
    {"rpm", kNumber, "rpm", "required", 0, 30000, "crank speed"},
};

inline constexpr ScenarioKey kTemperaturePoint[] = {
    {"t_s", kNumber, "s", "0", 0, 7 * 86400, "time of the point (increasing)"},
    {"c", kNumber, "°C", "required", -40, 85, "board temperature"},
};

inline constexpr ScenarioKey kEngineOrder[] = {
    {"order", kNumber, "", "1", 0.25, 32,
     "multiple of the crank rotation frequency (a four-stroke engine of n cylinders fires at "
     "n/2)"},
    {"accel_amplitude_mps2", kPoint, "m/s²", "[0, 0, 0]", 0, 0, "peak acceleration per board axis"},
    {"gyro_amplitude_dps", kPoint, "deg/s", "[0, 0, 0]", 0, 0, "peak angular rate per axis"},
};

inline constexpr ScenarioKey kRideBand[] = {
    {"band_hz", kPoint, "Hz", "[1, 20]", 0, 0,
     "[low, high] edges of the flat one-sided PSD (0 < low < high < internal_rate_hz / 2)"},
    {"accel_psd_mps2_sq_per_hz", kPoint, "(m/s²)²/Hz", "[0, 0, 0]", 0, 0,
     "acceleration PSD per axis (≥ 0)"},
    {"gyro_psd_dps_sq_per_hz", kPoint, "(deg/s)²/Hz", "[0, 0, 0]", 0, 0,
     "angular rate PSD per axis (≥ 0)"},
};

inline constexpr ScenarioKey kMount[] = {
    {"frequency_hz", kNumber, "Hz", "0 (rigid)", 0, 10000,
     "resonance of the base-excited mount (< internal_rate_hz / 2)"},
    {"damping_ratio", kNumber, "", "0.1", 0.005, 2, "its damping ratio ζ (gain 1/(2ζ) at the peak)",
     kNoChoices, kAnyRange, kNoSource},
};

inline constexpr ScenarioKey kTimeTag[] = {
    {"latency_s", kNumber, "s", "0", 0, 1, "sense instant to the tagged instant"},
    {"jitter_s", kNumber, "s", "0", 0, 0.1, "extra tag delay, uniform in [0, jitter_s]"},
    {"imu_clock_ppm", kNumber, "ppm", "0", -1e4, 1e4,
     "the IMU's own output-rate oscillator against nominal"},
};

// the rows the accelerometer and the gyro share (same keys, units and meaning)
inline constexpr ScenarioKey kFlickerTermsKey = {
    "flicker_terms",
    kInteger,
    "",
    "the profile's",
    0,
    8,
    "Gauss–Markov terms summing to the flicker (bias instability) noise",
    kNoChoices,
    kAnyRange,
    kProfileSource};
inline constexpr ScenarioKey kFlickerTauKey = {
    "flicker_tau_s",
    kPoint,
    "s",
    "the profile's",
    0,
    0,
    "[min, max] correlation times of those terms (0 < min ≤ max)",
    kNoChoices,
    kAnyRange,
    kProfileSource};
inline constexpr ScenarioKey kScaleFactorKey = {"scale_factor_ppm",
                                                kNumber,
                                                "ppm",
                                                "the profile's",
                                                0,
                                                1e5,
                                                "scale factor error (1σ, per power-on)",
                                                kNoChoices,
                                                kAnyRange,
                                                kProfileSource};
inline constexpr ScenarioKey kScaleTemperatureKey = {
    "scale_temperature_ppm_per_c",          kNumber,    "ppm/°C",  "the profile's", -1e4, 1e4,
    "scale factor temperature coefficient", kNoChoices, kAnyRange, kProfileSource};
inline constexpr ScenarioKey kMisalignmentKey = {
    "misalignment_deg",       kNumber,    "deg",     "the profile's", 0, 10,
    "axis misalignment (1σ)", kNoChoices, kAnyRange, kProfileSource};
inline constexpr ScenarioKey kBandwidthKey = {
    "bandwidth_hz",           kNumber,    "Hz",      "the profile's", 0, 20000,
    "the sensor's bandwidth", kNoChoices, kAnyRange, kProfileSource};

// A triad's error terms (sensor_spec.h TriadErrorSpec): the accelerometer's and the gyro's differ
// in the units of their first seven keys.
inline constexpr ScenarioKey kAccel[] = {
    {"noise_density_ug_rthz", kNumber, "µg/√Hz", "the profile's", 0, 1e6,
     "white noise density (velocity random walk)", kNoChoices, kAnyRange, kProfileSource},
    {"bias_instability_ug", kNumber, "µg", "the profile's", 0, 1e6, "bias instability", kNoChoices,
     kAnyRange, kProfileSource},
    {"rate_random_walk_ug_rts", kNumber, "µg/√s", "the profile's", 0, 1e6, "bias random walk",
     kNoChoices, kAnyRange, kProfileSource},
    {"turn_on_bias_mg", kNumber, "mg", "the profile's", 0, 1e6, "turn-on bias (1σ per power-on)",
     kNoChoices, kAnyRange, kProfileSource},
    {"bias_temperature_mg_per_c", kNumber, "mg/°C", "the profile's", -1e3, 1e3,
     "bias temperature coefficient", kNoChoices, kAnyRange, kProfileSource},
    {"range_g", kNumber, "g", "the profile's", 0, 1e6, "full scale: the ADC clips beyond",
     kNoChoices, kAnyRange, kProfileSource},
    {"lsb_mg", kNumber, "mg", "the profile's", 1e-9, 1e6, "one count", kNoChoices, kAnyRange,
     kProfileSource},
    kFlickerTermsKey,
    kFlickerTauKey,
    kScaleFactorKey,
    kScaleTemperatureKey,
    kMisalignmentKey,
    kBandwidthKey,
};

inline constexpr ScenarioKey kGyro[] = {
    {"noise_density_dps_rthz", kNumber, "deg/s/√Hz", "the profile's", 0, 1e6,
     "white noise density (angle random walk)", kNoChoices, kAnyRange, kProfileSource},
    {"bias_instability_degph", kNumber, "deg/h", "the profile's", 0, 1e6, "bias instability",
     kNoChoices, kAnyRange, kProfileSource},
    {"rate_random_walk_degph_rthr", kNumber, "deg/h/√h", "the profile's", 0, 1e6,
     "bias random walk", kNoChoices, kAnyRange, kProfileSource},
    {"turn_on_bias_dps", kNumber, "deg/s", "the profile's", 0, 1e6,
     "turn-on bias (1σ per power-on)", kNoChoices, kAnyRange, kProfileSource},
    {"bias_temperature_dps_per_c", kNumber, "deg/s/°C", "the profile's", -1e3, 1e3,
     "bias temperature coefficient", kNoChoices, kAnyRange, kProfileSource},
    {"range_dps", kNumber, "deg/s", "the profile's", 0, 1e6, "full scale: the ADC clips beyond",
     kNoChoices, kAnyRange, kProfileSource},
    {"lsb_dps", kNumber, "deg/s", "the profile's", 1e-9, 1e6, "one count", kNoChoices, kAnyRange,
     kProfileSource},
    kFlickerTermsKey,
    kFlickerTauKey,
    kScaleFactorKey,
    kScaleTemperatureKey,
    kMisalignmentKey,
    kBandwidthKey,
    {"g_sensitivity_dps_per_g", kNumber, "(deg/s)/g", "the profile's", -100, 100,
     "rate error per g of specific force", kNoChoices, kAnyRange, kProfileSource},
};

}  // namespace hil::harness::mcu_keys

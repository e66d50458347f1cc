#pragma once
/// @file
/// A scenario: everything one run needs, loaded from a YAML file (format in
/// vectors/scenarios/README.md; LoadScenario in devices/scenario_file.h) and immutable afterwards.
/// Loading validates every key and value and reports errors as ScenarioError (file, line, field).
/// Each kind of device has its spec here and its row in the device table (devices/device_kind.h).

#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/actuator/isobus_steering_device.h"
#include "hil/firmware_emu/actuator/wheel_motors.h"
#include "hil/firmware_emu/attitude/wt901c_config.h"
#include "hil/firmware_emu/gnss/neo5m_device.h"
#include "hil/firmware_emu/gnss/receiver_model.h"
#include "hil/firmware_emu/lidar/rplidar_device.h"
#include "hil/firmware_emu/mcu/mcu_config.h"
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"
#include "hil/firmware_emu/rtk/rtk_base_device.h"
#include "hil/firmware_emu/rtk/zed_f9p_device.h"
#include "hil/firmware_emu/uwb/uwb_tag_device.h"
#include "hil/firmware_emu/world/greenhouse_world.h"
#include "hil/harness/scenario/campaign_criterion.h"
#include "hil/harness/scenario/default_criteria.h"
#include "hil/harness/scenario/estimator_kinds.h"
#include "hil/harness/scenario/fault_timeline.h"
#include "hil/harness/scenario/pass_to_pass_spec.h"
#include "hil/harness/scenario/scenario_overrides.h"
#include "hil/truth/truth_integrator.h"

namespace hil::harness {

/// The largest seed a scenario's `seed` key (and `--seed`) takes: the key is read as a signed
/// 64-bit YAML integer.
inline constexpr std::int64_t kMaxSeed = INT64_MAX;

/// An acceptance criterion on one metric of report.json. Passes when value ≤ threshold, where the
/// threshold is `max`, or `max_ratio_to_baseline` × the same metric of the raw GNSS baseline; or,
/// with `min`, when value ≥ min (e.g. output_rate_hz).
struct Criterion {
  std::string name;  ///< e.g. "horizontal_rmse_m <= 1.0"
  std::string
      metric;  ///< a key of report.json's metrics (e.g. horizontal_rmse_m); see kCriterionMetrics
  std::optional<double> max;
  std::optional<double> min;
  std::optional<double> max_ratio_to_baseline;
  std::string default_key;  ///< a default criterion (default_criteria.h): its key; else empty
};

/// A published reference figure (section `paper:`, scenario_suite.cc): a suite report puts the
/// run's value of `metric` beside it. Any user can add their own reference figures this way.
struct PaperFigure {
  std::string source;  ///< the publication and where in it (e.g. "paper 000, table of methods")
  std::string metric;  ///< a criterion metric (kCriterionMetrics), compared in its unit
  std::optional<double> value;  ///< the figure; absent for a qualitative finding
  std::string relation =
      "about";          ///< about (a measured value), below (an upper bound), above (a lower bound)
  std::string finding;  ///< the result in words ("diverges"), required without a value
  std::string note;     ///< free text (conditions, how it maps onto this scenario)
};

/// The metric names a criterion may use.
extern const std::vector<std::string> kCriterionMetrics;
/// The families of metric names a criterion may use besides kCriterionMetrics: navd.<health
/// counter> and navd.flag.<flag> (fault_report.h), tracking.*, pass_to_pass.*, closed_loop.*,
/// rtk_rover.* (the run report's metric table names them).
extern const std::vector<std::string> kCriterionMetricPrefixes;
/// A name of kCriterionMetrics or one beginning with a prefix of kCriterionMetricPrefixes.
bool IsCriterionMetric(const std::string& metric);

/// One receiver of the scenario's GNSS section: its link and its antenna position.
struct GnssReceiverSpec {
  std::string link = "ttyGPS";                         ///< symlink name in the run folder
  Eigen::Vector3d p_BA_B_m = Eigen::Vector3d::Zero();  ///< antenna lever arm (body FLU)
};

/// The GNSS receiver device(s) of a scenario (section `gnss`, devices/gnss_receiver/). All
/// receivers share the profile, settings, faults and error grade; each has its own link and
/// antenna and its own error part beside the common one. `link` and `model.p_BA_B_m` are those of
/// the first receiver.
struct GnssDeviceSpec {
  std::string profile = "neo-5m";
  int baud = 9600;
  std::string link = "ttyGPS";  ///< symlink name in the run folder (first receiver)
  double rate_hz = 1.0;
  double output_lag_s = 0.1;  ///< epoch to first byte
  std::size_t tx_buffer_bytes = 1024;
  gnss::ReceiverModelConfig model;
  gnss::StartKind start = gnss::StartKind::kHot;
  std::vector<gnss::GnssFault> faults;
  std::vector<GnssReceiverSpec> receivers;  ///< at least one after loading
  /// The sky's obstructions (section `obstructions:`) and the signal thresholds
  /// (`gnss.multipath`); inactive without obstacles.
  gnss::ShadingConfig shading;
  /// `gnss.rtk` (profile rtk only): the rough RTK; empty: the profile's float-then-fixed timer.
  std::optional<gnss::RtkRoughness> rtk_rough;
};

/// The IMU board's microcontroller of a scenario (section `mcu:`, devices/mcu/; absent → no IMU
/// board).
struct McuDeviceSpec {
  bool enabled = false;         ///< true when the scenario has an `mcu:` section
  std::string link = "ttyIMU";  ///< symlink name in the run folder
  std::size_t tx_buffer_bytes = 4096;
  bool imu_rate_is_default = true;  ///< no imu_rate_hz given: 10 × the GNSS rate
  mcu::McuConfig config;            ///< its start_utc is the scenario's
};

/// The UWB tag (section `uwb:`, devices/uwb_tag/; absent → no UWB).
struct UwbDeviceSpec {
  bool enabled = false;
  std::string link = "ttyUWB";  ///< symlink name in the run folder
  std::size_t tx_buffer_bytes = 4096;
  uwb::UwbTagConfig config;
};

/// The WT901C attitude sensor (section `wt901c:`, devices/wt901c/; absent → none).
struct Wt901cDeviceSpec {
  bool enabled = false;
  std::string link = "ttyWIT";  ///< symlink name in the run folder
  std::size_t tx_buffer_bytes = 1024;
  wit::Wt901cConfig config;
};

/// An RTK reference station and its correction radio (section `rtk_base:`, devices/rtk_base/;
/// absent → none): RTCM 3 on its own pty.
struct RtkBaseDeviceSpec {
  bool enabled = false;
  std::string link = "ttyRTCM";  ///< symlink name in the run folder
  std::size_t tx_buffer_bytes = 4096;
  rtk::RtkBaseConfig config;  ///< its start_utc is the scenario's
};

/// Where a ZED-F9P rover's corrections come from (section `zed_f9p:` key `corrections`).
enum class F9pCorrections { kRadio, kHost, kNone, kMovingBase };

/// A ZED-F9P-class RTK rover (section `zed_f9p:`, devices/zed_f9p/; absent → none): UBX and NMEA
/// on its own pty (UART1), the `rtk_base`'s radio on its UART2 (corrections: radio), or RTCM the
/// host writes to UART1 (corrections: host, an NTRIP client), or a moving base on the vehicle
/// wired to UART2 (corrections: moving_base; dual-antenna heading in NAV-RELPOSNED).
struct ZedF9pDeviceSpec {
  bool enabled = false;
  std::string link = "ttyF9P";  ///< symlink name in the run folder
  std::size_t tx_buffer_bytes = 4096;
  F9pCorrections corrections = F9pCorrections::kRadio;
  /// navd reads this rover instead of the `gnss` receivers (key `navd_input`; the rule:
  /// navd_gnss_source.h)
  bool navd_input = true;
  rtk::ZedF9pConfig config;  ///< start_utc the scenario's; the radio base from `rtk_base`
};

/// One laser rangefinder of the `rangefinders:` section: its name, pty link and mount.
struct RangefinderUnitSpec {
  std::string name, link;
  rangefinder::RangefinderMount mount;
};

/// Laser rangefinders (section `rangefinders:`, devices/rangefinders/; needs `greenhouse:`). Each
/// unit is a TfLunaDevice on its own pty; `module` holds the settings they share.
struct RangefinderSpec {
  bool enabled = false;
  rangefinder::TfLunaConfig module;
  std::vector<RangefinderUnitSpec>
      units;  ///< default: right-front, right-rear, left-front, left-rear
  std::size_t tx_buffer_bytes = 4096;
};

/// A 2-D LiDAR (section `lidar:`, devices/lidar/; needs `greenhouse:`): an RplidarDevice on a pty.
struct LidarSpec {
  bool enabled = false;
  std::string link = "ttyLIDAR";
  lidar::RplidarConfig config;
  std::size_t tx_buffer_bytes = 16384;
};

/// How the estimator under test is started and read.
struct EstimatorSpec {
  /// Shell command; {navd}, {run_dir}, {seed} and every link name in braces ({ttyGPS}, {ttyNAV})
  /// are substituted.
  std::string command = "{navd} --config {run_dir}/navd.conf";
  /// How its solutions are read: json_stdout (navd's JSON lines), gpsd_json (gpsd TPV objects on
  /// stdout, e.g. from `gpspipe -w`), nmea_stdout (GGA/RMC on stdout), nmea_pty (GGA/RMC written
  /// into the pty RUN_DIR/ttyNAV, substituted as {ttyNAV}), n2k_candump (NMEA 2000 PGN 129029
  /// as candump -L lines on stdout), n2k_socketcan (navd's NMEA 2000 frames read back from the
  /// scenario's CAN bus: 129029 position and time, with 129026 velocity and 127250 heading of the
  /// same SID).
  EstimatorOutput output = EstimatorOutput::kJsonStdout;
  NavdMode navd_mode = NavdMode::kGnssOnly;  ///< written into the generated navd.conf
  /// Further navd.conf `[filter]` keys (noise grades, gates, …), written as given; navd validates
  /// them and names the bad key (a rejected key fails the run with navd's message).
  std::vector<std::pair<std::string, std::string>> navd_filter;
  /// Further navd.conf `[input]` keys (gnss_protocol, gnss_configure, gnss_rate_hz, …); the device
  /// paths and bauds are hil's, from the scenario's devices.
  std::vector<std::pair<std::string, std::string>> navd_input;
  /// The point of the vehicle the estimate describes: "body" (the reference point), "antenna"
  /// (the first receiver's antenna), "imu" (the IMU board), or "auto": antenna for a GNSS-only
  /// navd, the IMU for navd fusing the board, the body otherwise.
  ReferencePoint reference_point = ReferencePoint::kAuto;
  double silence_timeout_s = 10.0;  ///< no output for this long fails the run
  double startup_s = 0.0;  ///< wall time given to the program to open its devices before t = 0
};

/// The CAN bus of a scenario (links helper): devices' CAN frames go out on this SocketCAN
/// interface, captured in captures/<interface>.candump and .cap. No interface: no CAN link.
struct CanLinkSpec {
  std::string interface;  ///< e.g. vcan0; empty when the scenario has no `can` section
  bool fd = false;        ///< open the socket for CAN FD frames
  /// navd reads the IMU from the MCU's J1939 frames on this bus (navd.conf `[imu] source = can`)
  /// instead of its serial link. Needs `mcu.can.enabled` and a real-time or scaled run.
  bool imu_to_estimator = false;
};

/// Closed loop (section `closed_loop:`, scenario_closed_loop.cc): the controller under test
/// steers the truth vehicle through an emulated actuator (vectors/scenarios/closed_loop/README.md).
struct ClosedLoopSpec {
  bool enabled = false;  ///< the scenario has a `closed_loop:` section
  /// kSerialBase: the ROSArduinoBridge base (diff drive); kIsobus: ISO 11783-7 guidance to the
  /// steering ECU of a front-steered vehicle (scenario_closed_loop_isobus.cc)
  enum class Channel { kSerialBase, kIsobus } channel = Channel::kSerialBase;
  std::string link = "ttyBASE";  ///< the actuator's serial link (symlink in the run folder)
  std::string path_file;         ///< the planned path (absolute), {path_file} in the command
  /// The controller's shell command; {guidanced}, {path_file}, {nav_nmea} (the FIFO navd writes
  /// its NMEA 0183 solution into), {origin} ("lat,lon,h"), {run_dir} and the link names are
  /// substituted. It runs in the estimator's process group (the lockstep waits for both).
  std::string controller;
  double control_period_s = 0.1;   ///< the controller's tick: a host turn each
  double command_timeout_s = 0.3;  ///< a tick whose last command is older: missing
  double first_command_due_s = 3;  ///< ticks before this count no missing command
  /// tracking.faults scores each fault from its start to this long after its end (recovery)
  double fault_window_s = 10;
  /// report.json `pass_to_pass` (ISO 12188-2 style, eval/pass_to_pass.h): window, margins
  PassToPassConfig pass_to_pass;
  Eigen::Vector2d start_p_N_m{0, 0};  ///< where the vehicle starts (ENU, m)
  double start_heading_deg = 0;       ///< its heading, clockwise from north
  /// The vehicle rolls straight at this speed when the run starts (the operator drove it onto
  /// the line): the estimator aligns on the motion before the controller's first command.
  double initial_speed_mps = 0;
  actuator::WheelMotorsConfig motors;  ///< the base's wheels (track_m from the vehicle)
  double pid_rate_hz = 30;             ///< ROSArduinoBridge's PID frame rate
  /// kIsobus: the steering ECU, its transport (socketcan: the `can:` bus; slcan: a serial CAN
  /// adapter on the pty `link`) and the vehicle's set speed.
  actuator::IsobusSteeringDeviceConfig isobus;
};

/// UTC of t = 0 when a scenario gives no start_utc. Not the paper's 2013-06-10: gpsd 3.22 (Debian
/// 12) takes NMEA dates before its release (2021) for GPS week-rollover victims and reports them
/// 1024 weeks later.
inline constexpr const char* kDefaultStartUtc = "2026-06-10T08:00:00Z";

struct Scenario {
  std::string file;  ///< where it came from ("<embedded default>" for the default)
  std::string name;
  std::string description;
  UnixTime start_utc{};  ///< UTC of t = 0 (start_utc; default kDefaultStartUtc)
  double duration_s = 60;
  std::uint64_t seed = 1;
  truth::TruthConfig truth;
  GnssDeviceSpec gnss;
  McuDeviceSpec mcu;
  UwbDeviceSpec uwb;
  Wt901cDeviceSpec wt901c;
  RtkBaseDeviceSpec rtk_base;
  ZedF9pDeviceSpec zed_f9p;
  CanLinkSpec can;
  ClosedLoopSpec closed_loop;
  EstimatorSpec estimator;
  /// The greenhouse the range sensors see (section `greenhouse:`, paper 001); none without it.
  std::optional<world::GreenhouseConfig> greenhouse;
  RangefinderSpec rangefinders;
  LidarSpec lidar;
  std::vector<Criterion> criteria;
  /// Section `default_criteria:`: what the scenario says of each default criterion, by key.
  std::map<std::string, DefaultCriterionSetting> default_criteria;
  FaultTimeline faults;
  /// Seconds after the end of an outage within which the horizontal error must return below
  /// `reconverged_error_m` (reconvergence time is measured against this).
  double reconverged_error_m = 1.0;
  /// Solutions before this time are not evaluated (initial convergence).
  double evaluate_from_s = 0.0;
  /// Reference figures from publications (section `paper:`), for suite reports.
  std::vector<PaperFigure> paper;
  /// Section `statistical:` (scenario_suite.cc): the scenario's figure is a claim about a
  /// distribution; `hil suite` runs it with `statistical_seeds` seeds from its own on and judges
  /// these criteria across them, as a campaign does (0: one run, no criteria across runs).
  int statistical_seeds = 0;
  std::vector<CampaignCriterion> statistical_criteria;
  /// The file has a `short:` section (a quicker form for CI, see LoadScenario), and it was applied.
  bool has_short_form = false, short_form = false;
};

/// Where included scenario pieces live: $HIL_SCENARIO_LIB (colon-separated), the source tree's
/// vectors/scenarios/lib, and for an installed hil PREFIX/share/hil/scenarios/lib beside its bin/.
std::vector<std::string> ScenarioLibraryDirs();

/// NGA's EGM96 15' geoid grid (`gnss.geoid: egm96`): PROJ's egm96_15.gtx (Debian proj-data; found
/// when the project is configured, or $HIL_EGM96_GRID), read once per process.
/// @throws std::runtime_error when the grid cannot be read.
std::shared_ptr<const gnss::GeoidGrid> Egm96Geoid();
/// The geoid table of a u-blox 5 (`gnss.geoid: ublox5`, the default): EGM96 at 10° nodes rounded
/// to whole metres, interpolated bilinearly (see geoid_grid.h for the real captures it matches).
std::shared_ptr<const gnss::GeoidGrid> Ublox5Geoid();

}  // namespace hil::harness

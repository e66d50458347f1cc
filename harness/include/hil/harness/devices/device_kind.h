#pragma once
/// @file
/// The device table: one row per kind of emulated device a scenario can hold (the GNSS receivers,
/// the IMU board's MCU, the UWB tag, the WT901C, …), as gpsd lists its drivers in one array. A row
/// names the scenario section its spec reader reads, the builder that adds its devices and links
/// to a run, the navd.conf keys it writes and where report.json shows it. The scenario loader
/// (scenario_file.h), BuildDevices (run/device_set.h), the navd.conf writer (navd_conf.h), the
/// links the run waits for navd to open and the link check of report.json go through the table.
///
/// Adding a kind: a folder harness/src/devices/<kind>/ with its reader, builder and (if navd reads
/// it) navd.conf writer, one `extern` and one row in device_table.cc, its sources in
/// harness/src/devices/CMakeLists.txt, and its spec as a member of Scenario (scenario.h).
/// tests/harness/devices/device_table_test.cc checks the table against the loader and navd.

#include <cstdint>
#include <functional>
#include <memory>
#include <ostream>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "hil/firmware_emu/actuator/base_serial_device.h"
#include "hil/firmware_emu/actuator/isobus_steering_device.h"
#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/gnss_fix.h"
#include "hil/harness/links/can_endpoint.h"
#include "hil/harness/links/serial_endpoint.h"
#include "hil/harness/scenario/scenario.h"
#include "hil/harness/scenario/scenario_keys.h"
#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {

/// What the builders of the device table make for a run: the devices, their serial ports and
/// links, and the CAN bus. The run's DeviceSet (run/device_set.h) is this plus its threads.
struct DeviceBuild {
  /// The greenhouse the range sensors cast against (section `greenhouse:`); declared before the
  /// devices, which point to it, so it outlives them.
  std::unique_ptr<world::GreenhouseWorld> world;
  std::vector<std::unique_ptr<Device>> devices;
  /// endpoints[i][p] is serial port p of devices[i]
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  /// Latest fix of each GNSS receiver (the raw-fix baseline reads these after each event).
  std::vector<std::function<const gnss::GnssFix*()>> fix_sources;
  /// {link name, path} for substitution into the estimator command ({ttyGPS} → RUN_DIR/ttyGPS).
  std::vector<std::pair<std::string, std::string>> links;
  /// The CAN bus (scenario section `can`); null when the scenario has none. Every device's
  /// DeviceOutput::can frames go out on it.
  std::unique_ptr<CanEndpoint> can;
  /// Closed loop: the differential-drive base (owned by `devices`), null otherwise.
  actuator::BaseSerialDevice* base = nullptr;  ///< non-const: the run taps its control ticks
  /// Closed loop on the isobus channel: the steering ECU (owned by `devices`), null otherwise.
  actuator::IsobusSteeringDevice* steering =
      nullptr;  ///< non-const: the run taps its control ticks
  /// The ZED-F9P rover (owned by `devices`), null without one: its RTK timeline for the report.
  const rtk::ZedF9pDevice* rover = nullptr;
};

/// Where in navd.conf a row's writer is called (navd_conf.cc writes the rest around them):
/// kInput in [input] after gnss_device and gnss_baud; kFilter in [filter] after `mode`, before the
/// scenario's estimator.navd_filter keys; kSections after [filter]'s keys, before [output].
enum class NavdConfSlot { kInput, kFilter, kSections };

/// One kind of device.
struct DeviceKind {
  std::string_view name;  ///< the device's name (uwb_tag, wt901c), never a paper's
  /// The top-level keys of the scenario file its spec reader reads (each key has one row; a kind
  /// configured inside another section, e.g. the closed loop's actuator, has none).
  std::span<const std::string_view> sections;
  /// Where its spec is in the scenario file, in words (for the table's readers).
  std::string_view spec;
  /// Reads its sections into the scenario (called for every scenario, in table order, after
  /// start_utc, the truth, `can:` and `greenhouse:`); null when another section holds its spec.
  void (*read)(const YamlReader& root, Scenario& s);
  /// Its random stream: the builder's seed is run seed × kSeedStride + this (0: it draws none).
  std::uint64_t seed_stream;
  /// Adds its devices (in table order: the order of the devices is the order of their events at
  /// equal times) with their serial links in `run_dir`; nothing when the scenario has none.
  void (*build)(const Scenario& s, std::uint64_t seed, const std::string& run_dir,
                DeviceBuild& set);
  /// The navd.conf keys it writes ("section.key"; N stands for a receiver's index). Two rows may
  /// list a key when a scenario has only one of them write it: [input] gnss_device and gnss_baud
  /// are the gnss receivers' or the ZED-F9P rover's (scenario/navd_gnss_source.h).
  std::span<const std::string_view> navd_keys;
  /// Writes its navd.conf lines at `slot`; null when it writes none. `gnss_device` is the first
  /// receiver's link in the run folder (navd_conf.h), whose folder holds every link.
  void (*write_navd)(NavdConfSlot slot, const Scenario& s, const std::string& gnss_device,
                     std::ostream& out);
  /// Its links in the scenario (empty without the device).
  std::vector<std::string> (*links)(const Scenario& s);
  /// The links of it that navd reads, given the scenario's estimator.navd_mode (the run waits for
  /// navd to open them and gates them by its reads); null when navd reads none.
  std::vector<std::string> (*navd_links)(const Scenario& s);
  /// The report.json section that reports it ("link_integrity": its links' integrity, under
  /// `link_role`).
  std::string_view report_section;
  /// Its links' role in report.json's link_integrity: which of navd's counters speak for them
  /// (link_integrity.h); empty: each link is a role of its own.
  std::string_view link_role;
  /// The device as the scenario configures it, in words (model or profile, rate, baud), for the
  /// header of report.html; called only when `links(s)` is not empty.
  std::string (*profile)(const Scenario& s) = nullptr;
};

/// printf-style text for the rows' `profile`.
std::string ProfileText(const char* format, ...) __attribute__((format(printf, 1, 2)));

/// The seed of a kind's random stream: seed × kSeedStride + its seed_stream.
inline constexpr std::uint64_t kSeedStride = 1000003ULL;

/// The table, in build order (device_table.cc).
std::span<const DeviceKind* const> DeviceKinds();

/// The row whose links include `link`, null when none.
const DeviceKind* DeviceKindOfLink(const Scenario& s, const std::string& link);

/// A spec's `link` key: a plain file name in the run folder (default `fallback`).
std::string ReadLinkName(const YamlReader& r, const std::string& fallback);
/// ReadLinkName() for a section with a table, which must list `link`.
template <const auto& T>
std::string ReadLinkName(const KeyedReader<T>& r, const std::string& fallback) {
  static_cast<void>(KeyedReader<T>::Row("link"));  // a compile error when the table lacks it
  return ReadLinkName(r.yaml(), fallback);
}
/// The devices' sections that have a table (scenario_keys.h), in the reference's order
/// (device_key_tables.cc).
std::span<const KeySection* const> DeviceKeySections();
/// A range sensor's `reflectivity: {ridge, post, wall}` (the greenhouse's surfaces).
void ReadSurfaceReflectivity(const YamlReader& r, world::SurfaceReflectivity& f);

/// The greenhouse the range sensors cast against, made from the scenario's on first use.
const world::GreenhouseWorld& GreenhouseWorldOf(const Scenario& s, DeviceBuild& set);

/// One serial link for a device: RUN_DIR/<link> with its capture, at the device's baud on port 0
/// (or `baud` when given).
void AddSerialDevice(std::unique_ptr<Device> dev, const std::string& link, std::size_t tx_buffer,
                     const std::string& run_dir, DeviceBuild& set, int baud = 0);

}  // namespace hil::harness

#pragma once
/// @file
/// The sign-off header of report.html: what a run tested (the scenario file and its SHA-256, the
/// site, when, the devices and their profiles, the estimator and controller, the build of hil and
/// navd, the machine) and what the harness measured of itself (each link's schedule error and its
/// dropped bytes). Only report.html shows it: report.json's contract (DESIGN.md) is unchanged, and
/// the wall-clock date and the machine make no run's bytes depend on when or where it ran.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/unix_time.h"

namespace hil::harness {

/// One device of the run, from the device table (devices/device_kind.h).
struct HeaderDevice {
  std::string kind;     ///< the table's name: gnss_receiver, mcu, wheel_base…
  std::string links;    ///< its links in the run folder, comma-separated
  std::string profile;  ///< its profile in words (model, rate, baud)
};

/// One serial link or the CAN bus as the harness measured it (real time and scaled only).
struct HeaderLink {
  std::string name;
  std::uint64_t units = 0;  ///< bytes (serial) or frames (CAN) timed
  std::string unit = "bytes";
  std::optional<double> p50_us, p99_us, max_us;  ///< wall time sent − scheduled wall time
  std::uint64_t bytes_dropped_unread = 0;        ///< serial: nobody read the port
};

struct RunHeader {
  std::string scenario_sha256;  ///< of the scenario file's bytes; empty: no file (embedded)
  bool short_form = false;      ///< the file's `short:` form was applied (--short)
  double origin_lat_deg = 0, origin_lon_deg = 0;
  double origin_height_m = 0;      ///< ellipsoidal (WGS-84), as the scenario's origin.height_m
  std::string scenario_start_utc;  ///< UTC of scenario time 0 (start_utc)
  std::string run_started_utc;     ///< the wall-clock date and time the run started
  std::vector<HeaderDevice> devices;
  std::string hil_version, hil_commit;
  /// navd: "{navd}" substituted by this build's navd (path); else the external command.
  std::string estimator_build;
  std::string controller;  ///< closed loop: the controller's command; empty otherwise
  std::string cpu_model, kernel;
  long cpus_online = 0;
  std::string stepping;           ///< virtual, lockstep, free_running
  std::vector<HeaderLink> links;  ///< empty in virtual mode
};

/// Formats a UTC instant as "YYYY-MM-DD hh:mm:ss UTC".
std::string UtcText(UnixTime t);

}  // namespace hil::harness

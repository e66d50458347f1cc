#pragma once
/// @file
/// navd's fault detection: counters of everything wrong it saw on its inputs and in its filter, and
/// status flags, written into every JSON solution line as a `health` object:
///
///   "health":{"flags":["gnss_outage"],"gnss_checksum_errors":3,"gnss_garbage_bytes":41,…}
///
/// Counters (monotonic since start):
///   gnss_checksum_errors   NMEA/UBX sentences or frames with a bad checksum
///   gnss_malformed         NMEA sentences with unusable fields or overlong; overlong UBX frames
///   gnss_garbage_bytes     bytes outside any sentence/frame (line noise, framing garbage)
///   gnss_epochs            GNSS epochs decoded (with or without a fix)
///   gnss_no_fix_epochs     epochs the receiver reported without a fix
///   gnss_repeated_epochs   epochs whose time is not after the previous one (duplicates,
///   reordering) gnss_gaps              times a fix came more than 1.5 receiver periods after the
///   previous fix gnss_outages           times the gnss_outage flag was raised gnss_rejected fixes
///   the filter's innovation gate refused gnss_late              fixes older than the filter's
///   fusion horizon gnss_resets            filter resets to a GNSS fix (a gross jump persisted)
///   imu_crc_errors, imu_bad_headers, imu_garbage_bytes   MCU frame decoder errors
///   imu_sequence_gaps      MCU frame sequence numbers skipped
///   imu_repeated_frames    MCU frames repeating the previous sequence and tick (duplicates)
///   imu_gaps               IMU frames more than 2.5 sample periods (MCU ticks) after the previous
///   one mcu_resets             MCU resets seen: the tick and the sequence restarted together
///   imu_samples_dropped    IMU samples the adapter could not use (no time mapping, no scale, gap)
///   imu_losses             times the IMU fell silent while fixes kept coming (solutions = fixes)
///   imu_can_unpaired       J1939 IMU ([imu] source = can): an ARI without its ACCS or an ACCS
///                          without its ARI (reordered, lost or late frames; the sample is lost)
///   imu_can_bad_length     J1939 IMU frames shorter than 8 data bytes
///   imu_can_out_of_order   J1939 IMU frames whose receive time went back
/// Flags (current state at the solution's time of validity):
///   gnss_outage            no fix for more than max(3.5 s, 3 receiver periods + 0.5 s)
///   gnss_link_errors, imu_link_errors   decoder errors on that link in the last 5 s (for the
///                          IMU: MCU frame errors, sequence gaps, repeats, and the imu_can_*
///                          counters)
///   gnss_rejected          a fix refused by the gate in the last 5 s
///   imu_gap, mcu_reset     one in the last 5 s
///   imu_lost               the IMU is silent: the solution is the GNSS fix (Navigator::ImuLost)

#include <cstdint>
#include <optional>
#include <string>

#include "hil/estimator/drivers/j1939_imu_decoder.h"
#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/navigator.h"
#include "hil/estimator/samples.h"

namespace hil::estimator {

/// The decoders and filter whose statistics the health object reports (any may be null).
struct HealthSources {
  const drivers::NmeaDecoderStats* nmea = nullptr;
  const drivers::UbxDecoderStats* ubx = nullptr;
  const drivers::McuDecoderStats* mcu = nullptr;
  const drivers::McuAdapterStats* mcu_adapter = nullptr;
  const NavigatorStats* nav = nullptr;
  const drivers::J1939ImuStats* j1939 = nullptr;  ///< the IMU's J1939 decoder ([imu] source = can)
};

class NavdHealth {
 public:
  explicit NavdHealth(HealthSources sources = {}) : src_(sources) {}
  void set_sources(HealthSources sources) { src_ = sources; }
  /// Every GNSS epoch as it goes to the filter (fix or not).
  void OnGnss(const GnssSample& g);
  /// Every decoded MCU frame.
  void OnMcuFrame(const drivers::McuFrame& f);
  /// Updates the flags for a solution valid at `t` and returns `,"health":{…}` to append to it.
  std::string Field(GpsTime t);
  /// Inserts the health object into a JSON line ending in "}\n" (or "}").
  void AppendTo(std::string& json_line, GpsTime t);

  struct Counters {
    std::uint64_t gnss_epochs = 0, gnss_no_fix_epochs = 0, gnss_repeated_epochs = 0, gnss_gaps = 0,
                  gnss_outages = 0;
    std::uint64_t imu_repeated_frames = 0, imu_gaps = 0, mcu_resets = 0;
  };
  const Counters& counters() const { return c_; }
  bool gnss_outage() const { return outage_; }

 private:
  std::uint64_t GnssLinkErrors() const;
  std::uint64_t ImuLinkErrors() const;

  HealthSources src_;
  Counters c_;
  // GNSS
  std::optional<GpsTime> last_gnss_t_, last_fix_t_;
  Nanoseconds gnss_period_{0};  // smallest interval seen between epochs
  bool outage_ = false;
  // MCU
  bool have_frame_ = false;
  std::uint16_t last_seq_ = 0;
  std::uint32_t last_tick_ = 0;
  bool have_imu_tick_ = false;
  std::uint32_t last_imu_tick_ = 0;
  std::uint32_t imu_period_ticks_ = 0;  // from STATUS, else the smallest interval seen
  // "in the last 5 s" flags: the counter value at the previous solution and when it last rose
  struct Recent {
    std::uint64_t seen = 0;
    std::optional<GpsTime> last_rise;
  };
  bool Rose(Recent& r, std::uint64_t value, GpsTime t);
  Recent gnss_errors_, imu_errors_, rejected_, imu_gap_, mcu_reset_;
};

}  // namespace hil::estimator

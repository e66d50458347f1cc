#pragma once
/// @file
/// navd's GNSS input: one or several receivers ([input] gnss_device, gnss_device_1 …), each on its
/// own serial device with its own decoder (NMEA GGA + RMC, or UBX) and epoch assembler. In NMEA
/// mode the UBX decoder frames the line (ACKs, NAV-PVT) and hands the other bytes to the NMEA
/// decoder; a NAV-PVT fix (gnss_nav_pvt) replaces that receiver's NMEA epochs. Every decoded fix
/// becomes a GnssSample tagged with its receiver index (GnssSample::antenna), on the filter's GPS
/// time base, and goes to the handler. With `[input] gnss_configure` each receiver is configured at
/// start-up (and after its port reopens) by its own ReceiverSetup.

#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/nmea_epoch.h"
#include "hil/estimator/drivers/nmea_gnss_sample.h"
#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/drivers/ubx_nav_pvt_sample.h"
#include "hil/estimator/navd/navd_config.h"
#include "hil/estimator/samples.h"

#include "receiver_setup.h"
#include "serial_device.h"

namespace hil::navd {

class GnssReceivers {
 public:
  using Handler = std::function<void(const estimator::GnssSample&)>;
  /// One receiver per entry of cfg.GnssDevices() (none when gnss_device is empty).
  GnssReceivers(const estimator::NavdConfig& cfg, Handler handler);

  std::size_t size() const { return rx_.size(); }
  /// Receiver i's device (opened on demand by the poll loop).
  SerialDevice& device(std::size_t i) { return rx_[i]->device; }
  /// Bytes read from receiver i's device.
  void Feed(std::size_t i, const std::string& bytes);
  /// Sends the start-up configuration commands that are due on every open device.
  void Service(std::int64_t now_ns);

  /// Counters summed over the receivers.
  estimator::drivers::NmeaDecoderStats nmea_stats() const;
  estimator::drivers::UbxDecoderStats ubx_stats() const;
  /// The same sums, kept up to date by Feed (for readers that hold a pointer, e.g. NavdHealth).
  const estimator::drivers::NmeaDecoderStats& nmea_totals() const { return nmea_totals_; }
  const estimator::drivers::UbxDecoderStats& ubx_totals() const { return ubx_totals_; }
  std::uint64_t reopens() const;
  /// GPS − UTC for the solutions' UTC times: in UBX mode the first receiver's own value once it
  /// reported a valid one (NAV-TIMEGPS), else `configured` ([time] leap_seconds).
  int UtcLeapSeconds(int configured) const {
    return ubx_ && !rx_.empty() ? rx_.front()->ubx_epochs.UtcLeapSeconds(configured) : configured;
  }

 private:
  struct Receiver {
    Receiver(const std::string& path, int baud, int index, const estimator::NavdConfig& cfg,
             const Handler& h);
    SerialDevice device;
    ReceiverSetup setup;
    estimator::drivers::NmeaEpochAssembler nmea_epochs;
    estimator::drivers::NmeaDecoder nmea;
    estimator::drivers::UbxEpochAssembler ubx_epochs;
    estimator::drivers::UbxDecoder ubx;
    /// GPS time of this receiver's last NAV-PVT fix (NMEA mode with gnss_nav_pvt)
    std::optional<estimator::GpsTime> last_pvt_t;
    /// An NMEA epoch at `t` is dropped while a NAV-PVT came within kPvtHoldover of it: one fix
    /// per epoch from one receiver, NAV-PVT's (it carries the receiver's accuracy, GGA none).
    bool PvtSupersedes(estimator::GpsTime t) const;
  };
  /// 2 s: ten epochs at 5 Hz, two at 1 Hz; a receiver whose NAV-PVT output stops is read from its
  /// NMEA again after this.
  static constexpr estimator::Nanoseconds kPvtHoldover{2'000'000'000};
  bool ubx_ = false;
  std::vector<std::unique_ptr<Receiver>> rx_;
  estimator::drivers::NmeaDecoderStats nmea_totals_;
  estimator::drivers::UbxDecoderStats ubx_totals_;
};

}  // namespace hil::navd

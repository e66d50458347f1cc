#pragma once
// guidanced's rangefinder inputs (paper 001): four Benewake TF-Luna / TFmini-S units, each on its
// own serial port (the harness's ptys ttyRF_RF, ttyRF_RR, ttyRF_LF, ttyRF_LR), decoded by the
// estimator's tolerant BenewakeDecoder. The frames carry no time: at each navigation solution
// guidanced drains every port and stamps the right-front unit's frames back from the solution's
// time at the frame period, pairing each with the other units' frames at the same position in
// their queues. Fixed buffers after start-up.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "hil/estimator/drivers/benewake_decoder.h"
#include "hil/estimator/guidance/deviation_corrector.h"

namespace hil::guidanced {

class RangeInputs {
 public:
  static constexpr std::size_t kUnits = 4;  // right front, right rear, left front, left rear
  /// Opens the four ports (raw, `baud`); false (with errno set) when one cannot be opened.
  bool Open(const std::array<std::string, kUnits>& paths, int baud, bool tfmini_s, double rate_hz);
  /// Reads what port k holds into its queue (the newest kQueue frames are kept): the ports are
  /// read whenever they have bytes, so that a lockstep harness sees them read.
  void Read(std::size_t k);
  /// Reads what every port holds and hands one RangeSet per queued right-front frame to `on_set`,
  /// the last one at `t`; empties the queues.
  void Drain(estimator::GpsTime t,
             const std::function<void(const estimator::guidance::RangeSet&)>& on_set);
  std::array<int, kUnits> fds() const { return fds_; }
  std::uint64_t bad_bytes() const;

 private:
  static constexpr std::size_t kQueue = 64;
  struct Unit {
    std::array<estimator::drivers::BenewakeRange, kQueue> queue{};
    std::size_t count = 0, first = 0;  // a ring: `count` frames from `first`
    const estimator::drivers::BenewakeRange& at(std::size_t i) const {
      return queue[(first + i) % kQueue];
    }
    estimator::drivers::BenewakeRange last{};
  };
  std::array<int, kUnits> fds_{-1, -1, -1, -1};
  std::array<Unit, kUnits> units_{};
  std::array<std::unique_ptr<estimator::drivers::BenewakeDecoder>, kUnits> decoders_{};
  estimator::Nanoseconds period_{10'000'000};
};

}  // namespace hil::guidanced

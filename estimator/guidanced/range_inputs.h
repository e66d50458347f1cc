#pragma once
// guidanced's rangefinder inputs (paper 001): four Benewake TF-Luna / TFmini-S units, each on its
// own serial port (the harness's ptys ttyRF_RF, ttyRF_RR, ttyRF_LF, ttyRF_LR), decoded by the
// estimator's tolerant BenewakeDecoder.
//
// Timing. The frames carry no time, but a module sends one 9-byte frame per period from its start,
// so a frame's place in its stream is its device time: the frame whose last byte is byte b
// (counted from the stream's first byte) is frame n = round(b / 9) − 1, measured at
// start + (n + 1) · period (the first frame one period after the start), and its last byte has
// arrived 9 × 10 bits / baud later (8N1). The start is the UTC time of day the modules' first
// period began (`--rangefinder-start-tod`, in a hil run the run's start `{start_tod}`); without it
// the newest frame read at the first solution is taken to have just arrived then. At each
// navigation solution Drain() hands over, in frame order, the sets of the right-front frames that
// have arrived by the solution's time (and are not older than `kMaxAge`); later frames stay
// queued for the next solution. Each set, stamped with its frame's measurement time, pairs the
// right-front frame n with the other units' newest frames numbered ≤ n. Which frames a control
// step sees is thus fixed by the streams' bytes, not by when guidanced happened to read the
// ports (a frame measured at the solution's own time is still on the wire then: the next one).
// Times are UTC times of day in ns, as guidanced's solution times (GGA); a run does not cross
// midnight. Fixed buffers after start-up.
#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "hil/estimator/drivers/benewake_decoder.h"
#include "hil/estimator/guidance/deviation_corrector.h"

namespace hil::guidanced {

class RangeInputs {
 public:
  static constexpr std::size_t kUnits = 4;  // right front, right rear, left front, left rear
  static constexpr std::size_t kFrameBytes = 9;
  /// Frames older than this before a solution are not handed over (stale: before the first
  /// solution, after a gap in the solutions).
  static constexpr estimator::Nanoseconds kMaxAge{500'000'000};
  /// Decoders and timing without ports (Open() calls it; tests Feed() the bytes themselves).
  /// `start`: the time of day the modules' first period began, if known.
  void Configure(bool tfmini_s, double rate_hz, int baud, std::optional<estimator::GpsTime> start);
  /// Opens the four ports (raw, `baud`) and Configure()s; false (with errno set) when one cannot
  /// be opened.
  bool Open(const std::array<std::string, kUnits>& paths, int baud, bool tfmini_s, double rate_hz,
            std::optional<estimator::GpsTime> start);
  /// Reads what port k holds into its queue (the newest kQueue frames are kept): the ports are
  /// read whenever they have bytes, so that a lockstep harness sees them read.
  void Read(std::size_t k);
  /// Bytes of unit k's stream, in order (Read() passes what it reads).
  void Feed(std::size_t k, std::string_view bytes);
  /// Reads what every port holds and hands `on_set` one RangeSet per queued right-front frame
  /// measured after t − kMaxAge whose last byte arrived by t, oldest first; later frames stay
  /// queued.
  void Drain(estimator::GpsTime t,
             const std::function<void(const estimator::guidance::RangeSet&)>& on_set);
  std::array<int, kUnits> fds() const { return fds_; }
  std::uint64_t bad_bytes() const;
  /// Frames lost from a full queue after the first solution (the ports were not drained for
  /// kQueue periods; before it the oldest frames go by design).
  std::uint64_t overflows() const { return overflows_; }
  /// The device time of frame n (0-based) of a stream; only once the start is known.
  estimator::GpsTime FrameTime(std::int64_t n) const { return *start_ + period_ * (n + 1); }

 private:
  static constexpr std::size_t kQueue = 128;
  struct Frame {
    std::int64_t number = 0;
    estimator::drivers::BenewakeRange range{};
  };
  struct Unit {
    std::array<Frame, kQueue> queue{};
    std::size_t count = 0, first = 0;  // a ring: `count` frames from `first`
    const Frame& front() const { return queue[first]; }
    void Pop() { first = (first + 1) % kQueue, --count; }
    estimator::drivers::BenewakeRange last{};
  };
  void Push(std::size_t k, const estimator::drivers::BenewakeRange& r);
  // the newest of unit k's frames numbered ≤ n becomes its `last`; they leave the queue
  void Advance(std::size_t k, std::int64_t n);
  estimator::guidance::RangeSet MakeSet(estimator::GpsTime t) const;

  std::array<int, kUnits> fds_{-1, -1, -1, -1};
  std::array<Unit, kUnits> units_{};
  std::array<std::unique_ptr<estimator::drivers::BenewakeDecoder>, kUnits> decoders_{};
  estimator::Nanoseconds period_{10'000'000}, transfer_{781'250};  // a frame's 90 bits on the wire
  std::optional<estimator::GpsTime> start_;
  std::uint64_t overflows_ = 0;
  bool drained_ = false;
};

}  // namespace hil::guidanced

#pragma once
/// @file
/// The closed loop's truth track on truth.csv's grid (10 Hz, 40 B a sample: 1.4 MB per emulated
/// hour, 240 MB in a 7-day run) kept on disk (spill_file.h) for the tracking figures at the end,
/// which read it in order as often as they need (TrackPass).

#include <cstdint>
#include <optional>

#include "hil/harness/core/spill_file.h"
#include "hil/harness/eval/path_tracking.h"

namespace hil::harness {

class SpilledTrack {
 public:
  /// Our choice: 4096 samples (160 KiB, 6.8 min) in memory; the rest on disk.
  static constexpr std::size_t kMemorySamples = 4096;
  explicit SpilledTrack(std::size_t memory_samples = kMemorySamples) : file_(memory_samples) {}

  /// Appends a sample (time order). @throws std::runtime_error when the file fails.
  void Add(const TrackSample& s);
  std::size_t size() const { return file_.size(); }
  bool empty() const { return file_.empty(); }
  /// The first and the last sample (not empty).
  const TrackSample& front() const { return *front_; }
  const TrackSample& back() const { return *back_; }
  /// Samples held in memory now (bounded whatever the run's length).
  std::size_t in_memory() const { return file_.in_memory(); }
  /// One pass over the samples in order, each call from the first.
  TrackPass Pass() const;

 private:
  struct Record {
    std::int64_t t_ns = 0;
    double east_m = 0, north_m = 0, yaw_rad = 0, speed_mps = 0;
  };
  SpillFile<Record> file_;
  std::optional<TrackSample> front_, back_;
};

}  // namespace hil::harness

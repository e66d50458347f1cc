#pragma once
/// @file
/// The closed loop's external commands in time order (TruthIntegrator::SetCommand), in memory
/// bounded whatever the run's length (issue 40: every command of the run was kept, 24 B each at the
/// command grid's 100 Hz, so 8.6 MB per emulated hour and integrator). A restart from t = 0 (a late
/// command, a request before the dense output) reads them all again, so none may be forgotten: the
/// oldest go to an anonymous temporary file (spill_bytes.h) once more than `memory_entries` are
/// held, and are read back from it in order. Runs shorter than that (at 100
/// Hz, 41 s with the default) never touch the disk.

#include <cstddef>
#include <deque>
#include <optional>
#include <vector>

#include "hil/truth/spill_bytes.h"

namespace hil::truth {

class CommandSchedule {
 public:
  struct Entry {
    double t_s = 0;  ///< from this time on
    double speed_mps = 0;
    double steer_or_yaw_rate = 0;
  };
  /// Our choice: 4096 entries (96 KiB) in memory; the rest on disk.
  static constexpr std::size_t kMemoryEntries = 4096;

  explicit CommandSchedule(std::size_t memory_entries = kMemoryEntries);

  /// Appends a command (`t_s` not before the last one's). @throws std::runtime_error when the
  /// temporary file cannot be made or written.
  void Add(const Entry& e);
  /// The latest entry at or before `t_s` (none before the first). Reads on from the previous call
  /// when `t_s` does not decrease, else from the first entry (as after Rewind).
  const Entry* At(double t_s);
  /// The next At() reads from the first entry (a restart from t = 0).
  void Rewind();

  std::size_t size() const { return on_disk_ + memory_.size(); }
  bool empty() const { return size() == 0; }
  const Entry& back() const { return memory_.back(); }
  /// Entries held in memory now (at most `memory_entries`).
  std::size_t in_memory() const { return memory_.size(); }

 private:
  Entry Read(std::size_t i);
  void Spill();
  static constexpr std::size_t kReadChunk = 512;  // entries read from the file at once

  std::size_t memory_entries_;
  std::deque<Entry> memory_;  // entries [on_disk_, size())
  SpillBytes file_{sizeof(Entry), "truth commands"};
  std::size_t on_disk_ = 0;  // entries [0, on_disk_) are in file_
  std::size_t next_ = 0;     // At's cursor: the first entry not yet passed
  std::optional<Entry> current_;
  std::optional<double> last_t_s_;
  std::vector<Entry> read_;  // entries [read_first_, read_first_ + read_.size()) of the file
  std::size_t read_first_ = 0;
};

}  // namespace hil::truth

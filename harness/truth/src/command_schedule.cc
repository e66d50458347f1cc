#include "hil/truth/command_schedule.h"

#include <algorithm>
#include <vector>

namespace hil::truth {

CommandSchedule::CommandSchedule(std::size_t memory_entries)
    : memory_entries_(std::max<std::size_t>(memory_entries, 2)) {}

void CommandSchedule::Add(const Entry& e) {
  memory_.push_back(e);
  if (memory_.size() > memory_entries_) Spill();
}

// The older half of memory_ goes to the end of the file.
void CommandSchedule::Spill() {
  const std::size_t n = memory_.size() / 2;
  const std::vector<Entry> chunk(memory_.begin(), memory_.begin() + static_cast<long>(n));
  file_.Write(on_disk_, chunk.data(), n);
  memory_.erase(memory_.begin(), memory_.begin() + static_cast<long>(n));
  on_disk_ += n;
}

CommandSchedule::Entry CommandSchedule::Read(std::size_t i) {
  if (i >= on_disk_) return memory_[i - on_disk_];
  if (i < read_first_ || i >= read_first_ + read_.size()) {
    read_.resize(std::min(kReadChunk, on_disk_ - i));
    file_.Read(i, read_.data(), read_.size());
    read_first_ = i;
  }
  return read_[i - read_first_];
}

void CommandSchedule::Rewind() {
  next_ = 0;
  current_.reset();
  last_t_s_.reset();
}

const CommandSchedule::Entry* CommandSchedule::At(double t_s) {
  if (last_t_s_ && t_s < *last_t_s_) Rewind();
  last_t_s_ = t_s;
  while (next_ < size()) {
    const Entry e = Read(next_);
    if (e.t_s > t_s) break;
    current_ = e;
    ++next_;
  }
  return current_ ? &*current_ : nullptr;
}

}  // namespace hil::truth

#include "hil/truth/command_schedule.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <vector>

namespace hil::truth {
namespace {

[[noreturn]] void Fail(const char* what) {
  throw std::runtime_error(std::string("truth commands' temporary file: ") + what + ": " +
                           std::strerror(errno));
}

}  // namespace

CommandSchedule::CommandSchedule(std::size_t memory_entries)
    : memory_entries_(std::max<std::size_t>(memory_entries, 2)) {}

CommandSchedule::~CommandSchedule() {
  if (file_) std::fclose(file_);
}

void CommandSchedule::Add(const Entry& e) {
  memory_.push_back(e);
  if (memory_.size() > memory_entries_) Spill();
}

// The older half of memory_ goes to the end of the file.
void CommandSchedule::Spill() {
  if (!file_ && !(file_ = std::tmpfile())) Fail("create");
  const std::size_t n = memory_.size() / 2;
  const std::vector<Entry> chunk(memory_.begin(), memory_.begin() + static_cast<long>(n));
  const std::size_t bytes = n * sizeof(Entry);
  const auto offset = static_cast<off_t>(on_disk_ * sizeof(Entry));
  if (pwrite(fileno(file_), chunk.data(), bytes, offset) != static_cast<ssize_t>(bytes))
    Fail("write");
  memory_.erase(memory_.begin(), memory_.begin() + static_cast<long>(n));
  on_disk_ += n;
}

CommandSchedule::Entry CommandSchedule::Read(std::size_t i) {
  if (i >= on_disk_) return memory_[i - on_disk_];
  if (i < read_first_ || i >= read_first_ + read_.size()) {
    read_.resize(std::min(kReadChunk, on_disk_ - i));
    const std::size_t bytes = read_.size() * sizeof(Entry);
    const auto offset = static_cast<off_t>(i * sizeof(Entry));
    if (pread(fileno(file_), read_.data(), bytes, offset) != static_cast<ssize_t>(bytes))
      Fail("read");
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

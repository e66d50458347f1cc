#pragma once
/// @file
/// Items of a run kept on disk rather than in memory (issue 40: what grows with the run's length
/// must not stay in memory): an anonymous temporary file (truth/spill_bytes.h) that
/// items are appended to, or written to at given places, and read back in order as often as a
/// scorer needs. At most `memory_items` appended items wait in memory before they go to the file;
/// a reader holds one chunk. Runs shorter than that never touch the disk.

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <utility>
#include <vector>

#include "hil/truth/spill_bytes.h"

namespace hil::harness {

template <class T>
class SpillFile {
  static_assert(std::is_trivially_copyable_v<T>, "items go to the file as bytes");

 public:
  /// Our choice: 4096 items wait in memory; a reader takes 1024 at once.
  static constexpr std::size_t kMemoryItems = 4096;
  static constexpr std::size_t kReadChunk = 1024;

  explicit SpillFile(std::size_t memory_items = kMemoryItems)
      : memory_items_(memory_items < 1 ? 1 : memory_items), file_(sizeof(T)) {}
  /// A copy has a file of its own (the items are read and appended).
  SpillFile(const SpillFile& other) : SpillFile(other.memory_items_) {
    other.ForEach([this](const T& item) { Add(item); });
  }
  SpillFile& operator=(const SpillFile& other) {
    if (this == &other) return *this;
    Clear();
    memory_items_ = other.memory_items_;
    other.ForEach([this](const T& item) { Add(item); });
    return *this;
  }
  SpillFile(SpillFile&&) noexcept = default;

  /// Forgets every item (the file is written over from its start; its memory is freed).
  void Clear() {
    on_disk_ = 0;
    std::vector<T>().swap(tail_);
  }

  /// Appends an item. @throws std::runtime_error when the file cannot be made or written.
  void Add(const T& item) {
    tail_.push_back(item);
    if (tail_.size() >= memory_items_) Flush();
  }
  /// Writes `n` items at index `first` straight to the file (a file built by place, never
  /// appended to: a partition). The file's size grows to cover them.
  void WriteAt(std::size_t first, const T* items, std::size_t n) {
    file_.Write(first, items, n);
    if (first + n > on_disk_) on_disk_ = first + n;
  }
  std::size_t size() const { return on_disk_ + tail_.size(); }
  bool empty() const { return size() == 0; }
  /// Items held in memory now (at most `memory_items`).
  std::size_t in_memory() const { return tail_.size(); }

  /// Calls `visit` on the items [first, last) in order.
  template <class F>
  void ForEach(std::size_t first, std::size_t last, F&& visit) const {
    if (last > size()) last = size();
    std::vector<T> chunk;
    while (first < last && first < on_disk_) {
      const std::size_t n = std::min({kReadChunk, last - first, on_disk_ - first});
      chunk.resize(n);
      file_.Read(first, chunk.data(), n);
      for (const T& item : chunk) visit(item);
      first += n;
    }
    for (; first < last; ++first) visit(tail_[first - on_disk_]);
  }
  template <class F>
  void ForEach(F&& visit) const {
    ForEach(0, size(), std::forward<F>(visit));
  }

 private:
  void Flush() {
    file_.Write(on_disk_, tail_.data(), tail_.size());
    on_disk_ += tail_.size();
    tail_.clear();
  }

  std::size_t memory_items_;
  truth::SpillBytes file_;
  std::size_t on_disk_ = 0;  // items [0, on_disk_) are in the file
  std::vector<T> tail_;      // items [on_disk_, size())
};

}  // namespace hil::harness

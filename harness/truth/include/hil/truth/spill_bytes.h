#pragma once
/// @file
/// Records of a run kept on disk rather than in memory (issue 40: what grows with the run's length
/// must not stay in memory): an anonymous temporary file (std::tmpfile, unlinked at once, gone with
/// the process), written and read at record indices. The truth's command schedule and the
/// scoring's spill files (harness/core/spill_file.h) keep their oldest records in one.

#include <cstddef>

namespace hil::truth {

class SpillBytes {
 public:
  /// `item_bytes`: a record's size; `owner`: whose file, for the error messages ("scoring").
  explicit SpillBytes(std::size_t item_bytes, const char* owner = "scoring")
      : item_bytes_(item_bytes), owner_(owner) {}
  ~SpillBytes();
  SpillBytes(const SpillBytes&) = delete;
  SpillBytes& operator=(const SpillBytes&) = delete;
  SpillBytes(SpillBytes&& other) noexcept;
  SpillBytes& operator=(SpillBytes&&) = delete;

  /// Writes `n` records at record index `first` (the file made at the first write).
  /// @throws std::runtime_error (create, write).
  void Write(std::size_t first, const void* data, std::size_t n);
  /// Reads `n` records from record index `first` (all of them written before).
  /// @throws std::runtime_error (read).
  void Read(std::size_t first, void* data, std::size_t n) const;

 private:
  [[noreturn]] void Fail(const char* what) const;

  std::size_t item_bytes_;
  const char* owner_;
  int fd_ = -1;
};

}  // namespace hil::truth

#pragma once
/// @file
/// A run output written whole or not at all (issue 40, disk full): the text goes to `PATH.tmp`
/// (opened close-on-exec), is flushed to the disk and renamed over PATH. Until the rename an
/// earlier PATH (a good report of an earlier run into the same folder) stays as it was; a write
/// that fails (ENOSPC, EIO, EFBIG under RLIMIT_FSIZE) removes the temporary file and throws
/// OutputWriteError, which `hil` reports with its own exit code (kExitWriteFailure, README).

#include <stdexcept>
#include <string>
#include <string_view>

namespace hil::harness {

/// A file of the run folder could not be written: the message names it and the system's reason.
class OutputWriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Writes `text` to `path` through `path`.tmp and a rename. @throws OutputWriteError.
void WriteOutputFile(const std::string& path, std::string_view text);

/// A large run output (a CSV of every solution) written as it is made: the text goes out to
/// `path`.tmp in pieces, so a long run's file is never held in memory whole (an 8 h run's
/// truth.csv is 63 MB), and Commit() renames it over `path`. Destroyed uncommitted, the temporary
/// file is removed and `path` left as it was.
class OutputFile {
 public:
  /// @throws OutputWriteError when the temporary file cannot be made.
  explicit OutputFile(std::string path);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  /// The text not yet written: append to it, then call Pass().
  std::string& text() { return text_; }
  /// Writes the text out once it holds kChunkBytes or more. @throws OutputWriteError.
  void Pass();
  /// Writes the rest, syncs and renames. @throws OutputWriteError.
  void Commit();
  static constexpr std::size_t kChunkBytes = 1 << 20;

 private:
  void WriteOut();
  std::string path_, tmp_;
  std::string text_;
  int fd_ = -1;
};

/// "cannot write PATH: REASON" for errno `err`.
std::string WriteFailureText(const std::string& path, int err);

}  // namespace hil::harness

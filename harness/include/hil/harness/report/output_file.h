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

/// "cannot write PATH: REASON" for errno `err`.
std::string WriteFailureText(const std::string& path, int err);

}  // namespace hil::harness

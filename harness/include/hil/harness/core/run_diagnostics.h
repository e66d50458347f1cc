#pragma once
/// @file
/// What a run notes about its own files as it goes, held by the run (RunContext::diagnostics) and
/// handed to the writers it starts: the first file of the run folder that could not be written
/// (a capture, estimate.jsonl; disk full, a file size limit, the folder removed). The writers note
/// from whichever thread writes; the run reads it between events and stops with a message naming
/// the file. One value per run: nothing is kept from one run to the next.

#include <mutex>
#include <optional>
#include <string>

namespace hil::harness {

class RunDiagnostics {
 public:
  /// Records that writing `path` failed (the first one is kept).
  void NoteWriteFailure(const std::string& path);
  /// The first file of the run folder that could not be written, if any.
  std::optional<std::string> FirstWriteFailure() const;

 private:
  mutable std::mutex mu_;
  std::optional<std::string> write_failure_;
};

}  // namespace hil::harness

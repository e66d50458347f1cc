#include "hil/harness/core/run_diagnostics.h"

namespace hil::harness {

void RunDiagnostics::NoteWriteFailure(const std::string& path) {
  const std::lock_guard<std::mutex> lock(mu_);
  if (!write_failure_) write_failure_ = path;
}

std::optional<std::string> RunDiagnostics::FirstWriteFailure() const {
  const std::lock_guard<std::mutex> lock(mu_);
  return write_failure_;
}

}  // namespace hil::harness

#pragma once
// Bytes of a validated stream that belong to no frame: one "framing" finding per run of them.

#include <cstddef>
#include <cstdint>
#include <string>

#include "hil/harness/validate/validate.h"

namespace hil::harness {

class GarbageRun {
 public:
  /// The byte at `pos` belongs to no frame: it starts a run or continues one.
  void Add(std::size_t pos) {
    if (start_ == std::string::npos) start_ = pos;
  }
  /// A frame (or the end of the stream) at `end`: the run before it, if any, becomes a finding in
  /// `rep`. Returns the run's length (0 when there was none).
  std::size_t End(std::size_t end, ValidationReport& rep) {
    if (start_ == std::string::npos) return 0;
    const std::size_t n = end - start_;
    rep.findings.push_back({true, "framing", std::to_string(n) + " byte(s) outside any frame",
                            static_cast<std::int64_t>(start_)});
    start_ = std::string::npos;
    return n;
  }

 private:
  std::size_t start_ = std::string::npos;
};

}  // namespace hil::harness

#pragma once
/// @file
/// Test support: runs the real navd binary ($HIL_BIN_DIR/navd) in GNSS-only mode on a pty, writes
/// a byte stream into the pty's far end and returns navd's JSON lines.

#include <string>
#include <vector>

namespace hil::estimator::testing {

/// navd's answer to one stream.
struct NavdRun {
  std::vector<std::string> json_lines;
  int exit_status = -1;  ///< navd's exit code after SIGTERM (0: clean)
};

/// Starts navd with `[input] gnss_protocol = protocol` on a pty, writes `bytes` in 256-byte pieces,
/// waits until navd's output stops growing, stops it with SIGTERM. Throws std::runtime_error when
/// the pty or navd cannot be started.
NavdRun RunNavdOnPty(const std::string& bytes, const std::string& protocol);

}  // namespace hil::estimator::testing

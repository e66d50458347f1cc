#pragma once
/// @file
/// Which folder a run may write into (issue 40: `--out /` was accepted and overwrote files). A run
/// writes report.json, junit.xml, captures/, navd.conf, ptys... into its folder, replacing files
/// of the same names; so an existing folder is used only when it is empty or holds a previous
/// run (its report.json or its lock file .hil-run.lock, which an interrupted run leaves). The
/// root folder and the home folder ($HOME) are refused even then. A folder that does not exist
/// is created (with its parents).

#include <optional>
#include <string>

namespace hil::harness {

/// Why `out_dir` may not be a run folder, or nothing when it may.
std::optional<std::string> WhyNotARunFolder(const std::string& out_dir);

/// Creates `out_dir` when missing. @throws std::runtime_error (bad input: exit 2) when
/// WhyNotARunFolder() refuses it or it cannot be created or written.
void MakeRunFolder(const std::string& out_dir);

}  // namespace hil::harness

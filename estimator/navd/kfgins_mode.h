#pragma once
/// @file
/// `navd --kfgins CONFIG.yaml [--navd-conf FILE]`: navd's filter offline on a KF-GINS dataset
/// (hil::estimator::datasets), its result in KF-GINS's files, a summary on stderr.

namespace hil::navd {

/// True when the command line asks for the KF-GINS mode.
bool WantsKfginsMode(int argc, char** argv);
/// Runs it; the process's exit code (0, or 2 for bad input or usage).
int KfginsMain(int argc, char** argv);

}  // namespace hil::navd

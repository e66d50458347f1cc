#pragma once
/// @file
/// What hil was built from, for the sign-off header of report.html: the project's version
/// (CMakeLists.txt `project(hil VERSION …)`) and the git commit of the source tree at build time
/// (ci/cmake/HilBuildCommit.cmake; "-dirty" when tracked files differed from it, "unknown" when
/// built outside a git checkout). navd is built from the same tree by the same build.

#include <string_view>

namespace hil::harness {

/// e.g. "0.1.0"
std::string_view HilVersion();
/// e.g. "ddba7f9c1a2b" or "ddba7f9c1a2b-dirty" or "unknown"
std::string_view HilCommit();

}  // namespace hil::harness

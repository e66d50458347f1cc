#include "hil/harness/core/build_info.h"

#include "hil_build_commit.h"  // generated at build time: HIL_GIT_COMMIT

namespace hil::harness {

std::string_view HilVersion() { return HIL_VERSION; }
std::string_view HilCommit() { return HIL_GIT_COMMIT; }

}  // namespace hil::harness

#pragma once
// Internal to the evaluator's path reader: the boustrophedon shape (vectors/paths/README.md).
#include <map>
#include <string>

#include "hil/harness/scenario/path_file_reader.h"

namespace hil::harness {

/// The vertices and segments (rows, headland turns) of a `boustrophedon` statement at `line` of
/// `file` with its `fields`; errors name the file, the line and the field.
PathFileShape BoustrophedonShape(const std::string& file, int line,
                                 const std::map<std::string, std::string>& fields);

}  // namespace hil::harness

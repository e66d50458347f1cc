#pragma once
/// @file
/// Reader of planned-path files (format: vectors/paths/README.md): a `hil-path 1` header, then one
/// shape — `ab_line`, `polyline` with `vertex` lines, `circle`, `rectangle` or `boustrophedon` with
/// headland turns — as `keyword field=value …` lines. Errors throw `PathFileError`, whose message
/// names the file, the line and the field ("file:line: field 'row_spacing_m': …"); the caller exits
/// with status 2.

#include <stdexcept>
#include <string>
#include <string_view>

#include "hil/estimator/guidance/planned_path.h"

namespace hil::estimator::guidance {

class PathFileError : public std::runtime_error {
 public:
  PathFileError(const std::string& file, int line, const std::string& field,
                const std::string& message);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& field() const { return field_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
};

/// Parses the text of a path file; `name` is used in error messages.
PlannedPath ParsePathText(std::string_view text, const std::string& name);
/// Reads and parses a path file (an unreadable file is an error at line 0).
PlannedPath ReadPathFile(const std::string& path);

}  // namespace hil::estimator::guidance

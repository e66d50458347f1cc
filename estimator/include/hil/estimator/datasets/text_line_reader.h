#pragma once
/// @file
/// Line-by-line reading of a numeric text file into a fixed buffer (no allocation per line), and
/// the splitting of a line into numbers (separated by blanks, tabs or commas) with std::from_chars.

#include <cstdio>
#include <string>
#include <string_view>

#include "hil/estimator/datasets/dataset_error.h"

namespace hil::estimator::datasets {

class TextLineReader {
 public:
  /// @throws DatasetError when the file cannot be opened.
  explicit TextLineReader(const std::string& path);
  ~TextLineReader();
  TextLineReader(const TextLineReader&) = delete;
  TextLineReader& operator=(const TextLineReader&) = delete;

  /// The next line that is not blank and not a comment ('#' or '%' first); false at the end.
  /// @throws DatasetError for a line longer than the buffer.
  bool Next(std::string_view& line);
  /// Parses up to `max` numbers of `line` into `out`; returns how many. Every number must be
  /// finite.
  /// @throws DatasetError (naming `field_names[i]` when given) for a field that is not a finite
  /// number.
  int ParseNumbers(std::string_view line, double* out, int max,
                   const char* const* field_names = nullptr) const;
  long line_number() const { return line_; }
  const std::string& path() const { return path_; }
  /// An error at the current line.
  [[noreturn]] void Fail(const std::string& what) const;

 private:
  static constexpr int kBufferSize = 1024;
  std::string path_;
  std::FILE* f_ = nullptr;
  long line_ = 0;
  char buf_[kBufferSize] = {};
};

}  // namespace hil::estimator::datasets

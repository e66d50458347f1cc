#pragma once
/// @file
/// The one error of the dataset readers: a message that names the file, the line (1-based; 0 when
/// the whole file is meant) and the field.

#include <stdexcept>
#include <string>

namespace hil::estimator::datasets {

class DatasetError : public std::runtime_error {
 public:
  DatasetError(const std::string& path, long line, const std::string& what)
      : std::runtime_error(path + (line > 0 ? ":" + std::to_string(line) : std::string()) + ": " +
                           what) {}
};

}  // namespace hil::estimator::datasets

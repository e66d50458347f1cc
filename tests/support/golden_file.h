#pragma once
/// @file
/// Test support: compare generated output with a golden file in the checkout, or rewrite the
/// file when the environment says HIL_REGEN_VECTORS=1 (the one regeneration switch of every
/// golden test). The checkout is $HIL_SOURCE_DIR (set by hil_add_test).

#include <string>

namespace hil::test {

/// The checkout the tests read their vectors from ($HIL_SOURCE_DIR).
std::string SourceDir();
/// True when HIL_REGEN_VECTORS=1: goldens are rewritten instead of compared.
bool RegenerateVectors();
/// The whole file, bytes as stored ("" when it cannot be read).
std::string ReadFile(const std::string& path);

/// How generated text is compared with its golden file.
struct GoldenCompare {
  /// 0: byte for byte. > 0: line by line, comma-separated fields; fields that both parse as
  /// numbers may differ by this much (absolute), all other fields must be equal.
  double numeric_tolerance = 0;
};

/// Compares `content` with the golden file `relative_path` (under SourceDir()), naming the first
/// differing line, or rewrites the file under HIL_REGEN_VECTORS=1. Reports through GoogleTest
/// (a missing golden fails and says how to create it).
void CheckOrWriteGolden(const std::string& relative_path, const std::string& content,
                        const GoldenCompare& how = {});

}  // namespace hil::test

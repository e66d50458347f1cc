#pragma once
/// @file
/// SHA-256 of a file's bytes (Nettle), for report.html's sign-off header: the scenario file a run
/// read, so that a signed report names exactly which file it judged.

#include <optional>
#include <string>

namespace hil::harness {

/// Lower-case hex SHA-256 of the file's bytes; nullopt when it cannot be read.
std::optional<std::string> Sha256OfFile(const std::string& path);

/// Lower-case hex SHA-256 of `bytes`.
std::string Sha256Hex(const std::string& bytes);

}  // namespace hil::harness

#pragma once
/// @file
/// The exception the link layer throws when a system call fails: the action and errno's text.

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>

namespace hil::link {

/// `what: strerror(errno)` as a runtime_error; call right after the failing system call.
inline std::runtime_error SysError(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

}  // namespace hil::link

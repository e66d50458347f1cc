#pragma once
/// @file
/// Test support: text (or bytes) joined from parts, Joined(kBase, "key: 1\n") instead of
/// std::string(kBase) + "key: 1\n".
///
/// Why not operator+: compiled through the test programs' precompiled header (HIL_TEST_PCH), GCC
/// 12 no longer treats libstdc++'s code as a system header's and reports its -Warray-bounds false
/// positive on `std::string&& + ...` (the move out of the sum: char_traits.h __builtin_memcpy
/// "forming offset [32, N] is out of the bounds [0, 32]"), an error with -Werror. Joined builds
/// the text into one string with append and returns it without a move.

#include <cstddef>
#include <initializer_list>
#include <string>
#include <string_view>

namespace hil::test {

/// The parts one after the other (each part's bytes, NULs included where the part is a
/// std::string or std::string_view; a C string ends at its first NUL, as with operator+).
inline std::string JoinedParts(std::initializer_list<std::string_view> parts) {
  std::size_t size = 0;
  for (const std::string_view part : parts) size += part.size();
  std::string out;
  out.reserve(size);
  for (const std::string_view part : parts) out.append(part);
  return out;
}

/// Joined("a", std::string("b"), std::string_view("c")) == "abc".
template <typename... Parts>
std::string Joined(const Parts&... parts) {
  return JoinedParts({std::string_view(parts)...});
}

}  // namespace hil::test

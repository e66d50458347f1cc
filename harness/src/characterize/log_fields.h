#pragma once
// Fields of the text logs hil characterize reads (internal to harness/src/characterize).
#include <string>
#include <string_view>

namespace hil::harness {

/// `text` as a finite double. @throws std::runtime_error "WHERE: field FIELD: 'text' is not a
/// finite number".
double ParseFiniteField(std::string_view text, const std::string& where, const char* field);

}  // namespace hil::harness

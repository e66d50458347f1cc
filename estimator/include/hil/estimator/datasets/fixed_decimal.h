#pragma once
/// @file
/// A number with a fixed count of decimals, as text: the bytes std::to_chars(first, last, v,
/// std::chars_format::fixed, decimals) writes, by an integer conversion where that is certain to
/// give them (profiled: to_chars's fixed form took a third of `navd --kfgins`'s time).

namespace hil::estimator::datasets {

/// Writes v with `decimals` (0…17) digits after the point into [first, last); returns the end of
/// what was written, or `first` when it does not fit (as std::to_chars reports).
char* FormatFixed(char* first, char* last, double v, int decimals);

}  // namespace hil::estimator::datasets

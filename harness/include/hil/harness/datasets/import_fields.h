#pragma once
/// @file
/// Field parsing shared by the real-log readers of `hil dataset import`: every error names the
/// file, the line (or record) and the field, as "FILE:LINE: FIELD: problem".

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace hil::harness {

/// A bad input file: the message names the file, the line and the field.
class ImportInputError : public std::runtime_error {
 public:
  ImportInputError(const std::string& path, long line, const std::string& field,
                   const std::string& problem);
};

/// Splits a line at blanks, tabs and commas (empty fields between two commas are kept as empty).
std::vector<std::string_view> SplitFields(std::string_view line, bool commas);

/// A finite number, or ImportInputError.
double ParseFiniteField(std::string_view text, const std::string& path, long line,
                        const std::string& field);

/// GPS week and seconds of week of a GPST calendar time (no leap seconds: GPST throughout).
struct GpsWeekSow {
  int week = 0;
  double sow = 0;
};
GpsWeekSow GpsFromCalendar(int year, int month, int day, int hour, int minute, double second);
/// Of GPST seconds counted from 1970-01-01 (RTKLIB's gtime_t in GPST).
GpsWeekSow GpsFromGpstEpochSeconds(double t_s);

}  // namespace hil::harness

#pragma once
/// @file
/// One JSON line of the estimator's output (`estimator.output: json_stdout`, navd's lines) as hil
/// reads it, scanned in one pass without building a document: the solution's fields
/// (estimate_reader.h) and the `health` object (fault_report.h). navd writes one such line of
/// about 900 bytes per solution (10 Hz: 18 000 in seed004's 1800 s); a DOM per line cost the run
/// a tenth of its CPU (allocations for some 40 members, their keys and values).
///
/// The scanner gives the same values as nlohmann::json's parse followed by the readers' lookups,
/// or nothing, and then the caller parses the line as before: it answers only a line that is a
/// valid JSON object whose strings are printable ASCII without escapes, whose integers fit in
/// int64, whose nesting is at most kMaxDepth deep, in which no key the readers use occurs
/// twice at the top level and no key occurs twice in `health`. Anything else (invalid JSON too)
/// goes to the DOM, so an unusual line is read exactly as before.

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

namespace hil::harness {

/// What the readers use of one line (the top-level members they look up, by kind).
struct JsonSolutionLine {
  /// `tov_unix_ns` when it is an integer.
  std::optional<std::int64_t> tov_unix_ns;
  /// Members that are numbers (integer or not), as double.
  std::optional<double> tov_utc_s, lat_deg, lon_deg, height_m, yaw_deg;
  /// Members that are arrays of exactly three numbers.
  std::optional<Eigen::Vector3d> vel_enu_mps, pos_std_enu_m;
  /// `health` is an object: its keys in the line's order (shared by the lines with the same
  /// keys), the value of each that is a number, and the strings of its `flags` array.
  bool health = false;
  std::shared_ptr<const std::vector<std::string>> health_keys;
  std::vector<std::optional<double>> health_values;
  std::vector<std::string> health_flags;
};

/// Scans lines one after another (it keeps the last `health` key layout, so that a stream of
/// lines with the same keys shares one).
class JsonSolutionScanner {
 public:
  /// The line's members, or none: not a line the scanner answers (see the file comment).
  std::optional<JsonSolutionLine> Scan(std::string_view text);
  static constexpr int kMaxDepth = 32;
  static constexpr std::size_t kMaxHealthKeys = 128;

 private:
  std::shared_ptr<const std::vector<std::string>> layout_;
};

}  // namespace hil::harness

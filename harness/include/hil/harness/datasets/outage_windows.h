#pragma once
/// @file
/// GNSS outage windows for imported data: given as a list of start times, or one every N
/// seconds, each of a length, in seconds after a reference time (the first IMU epoch the filter
/// uses). A fix at t is dropped when start ≤ t < start + length (the first fix back is at the
/// window's end). Written beside the data as `outages.txt`, one window a line: start and end in
/// GPS seconds of week, which `hil dataset score --windows` reads.

#include <string>
#include <vector>

namespace hil::harness {

struct OutageWindow {
  double start_s = 0, end_s = 0;  ///< GPS seconds of week (or relative, as given)
};

struct OutagePlan {
  std::vector<double> at_s;  ///< starts after the reference time
  double every_s = 0;        ///< > 0: one window every so many seconds …
  double first_s = 0;        ///< … the first this long after the reference time
  double length_s = 10;
};

/// The windows of a plan on [t0, t_end]: each start relative to t0; windows that do not end
/// before t_end are left out. @throws std::invalid_argument for a length ≤ 0, overlapping windows
/// or a period not longer than the length.
std::vector<OutageWindow> PlanOutages(const OutagePlan& p, double t0, double t_end);

bool InOutage(const std::vector<OutageWindow>& w, double t);

void WriteOutageWindows(const std::string& path, const std::vector<OutageWindow>& w);
/// @throws ImportInputError naming the file, line and field for a bad line.
std::vector<OutageWindow> ReadOutageWindows(const std::string& path);

}  // namespace hil::harness

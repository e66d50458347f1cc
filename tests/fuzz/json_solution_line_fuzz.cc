// Fuzz target: the scanner of navd's JSON lines (json_solution_line.h) against the DOM it stands in
// for: a line it answers is valid JSON, and gives the record and the health the DOM gives, bit for
// bit; anything else it leaves to the DOM.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

#include <nlohmann/json.hpp>

#include "hil/harness/core/json_solution_line.h"
#include "hil/harness/dut/estimate_reader.h"
#include "hil/harness/faults/fault_report.h"

namespace {

bool SameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool SameRecord(const std::optional<hil::harness::EstimateRecord>& a,
                const std::optional<hil::harness::EstimateRecord>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  return a->t_validity == b->t_validity && SameBits(a->lat_deg, b->lat_deg) &&
         SameBits(a->lon_deg, b->lon_deg) && SameBits(a->height_m, b->height_m) &&
         a->vel_enu_mps == b->vel_enu_mps && a->pos_std_enu_m == b->pos_std_enu_m &&
         a->yaw_deg.has_value() == b->yaw_deg.has_value() &&
         (!a->yaw_deg || SameBits(*a->yaw_deg, *b->yaw_deg));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string line(reinterpret_cast<const char*>(data), size);
  static hil::harness::JsonSolutionScanner scanner;  // keeps its health layout between inputs
  const auto scan = scanner.Scan(line);
  if (!scan) return 0;
  const nlohmann::json dom = nlohmann::json::parse(line, nullptr, false);
  if (dom.is_discarded()) std::abort();  // answered a line that is no JSON
  const auto reader = hil::harness::MakeEstimateReader(hil::harness::EstimatorOutput::kJsonStdout,
                                                       hil::UnixTimeFromNs(1LL << 60));
  if (!SameRecord(reader->JsonLine(dom, hil::WallTime{}),
                  reader->ScannedLine(*scan, hil::WallTime{})))
    std::abort();
  hil::harness::EstimatorHealth from_dom, from_scan;
  from_dom.AddJson(dom);
  from_scan.AddScanned(*scan);
  if (from_dom.present != from_scan.present || from_dom.counters != from_scan.counters ||
      from_dom.flags_seen != from_scan.flags_seen)
    std::abort();
  return 0;
}

#include "hil/harness/report/link_integrity.h"

#include <algorithm>
#include <cstdio>

#include <nlohmann/json.hpp>

namespace hil::harness {
namespace {

// Whether a fault of `kind` damages the bytes of a link of `role` on purpose.
bool Damages(FaultKind kind, const std::string& role) {
  switch (kind) {
    case FaultKind::kByteCorruption:
    case FaultKind::kFrameDrop:
    case FaultKind::kFrameTruncate:
    case FaultKind::kFrameDuplicate:
    case FaultKind::kBaudMismatch:
      return true;
    case FaultKind::kGnssOverload:
      return role == "gnss";
    case FaultKind::kMcuReset:
      return role == "imu";
    default:
      return false;
  }
}

// The scenario's faults that damage these links' bytes (by kind name, each once).
std::vector<std::string> Excuses(const FaultTimeline& faults, const std::string& role,
                                 const std::vector<std::string>& links) {
  std::vector<std::string> kinds;
  for (const Fault& f : faults.faults) {
    if (!Damages(f.kind, role)) continue;
    // byte faults name their link; mcu_reset and gnss_overload act on their device's link
    const bool on_link = f.link.empty() || f.kind == FaultKind::kMcuReset ||
                         f.kind == FaultKind::kGnssOverload ||
                         std::find(links.begin(), links.end(), f.link) != links.end();
    const std::string name = FaultKindName(f.kind);
    if (on_link && std::find(kinds.begin(), kinds.end(), name) == kinds.end())
      kinds.push_back(name);
  }
  return kinds;
}

std::string Joined(const std::vector<std::string>& v) {
  std::string s;
  for (const std::string& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string Problem(const LinkIntegrity& r) {
  std::string what;
  for (const auto& [name, value] : r.estimator_counters) {
    if (value <= 0 || !r.excused_by.empty()) continue;
    char b[96];
    std::snprintf(b, sizeof b, "%s%s %.0f", what.empty() ? "" : ", ", name.c_str(), value);
    what += b;
  }
  std::string s = "link " + Joined(r.links) + ": ";
  if (r.bytes_dropped > 0)
    s += std::to_string(r.bytes_dropped) +
         " bytes dropped by the run while the estimator had the port open (it did not read them "
         "in time; captured as drop records)";
  if (!what.empty()) {
    if (r.bytes_dropped > 0) s += "; ";
    s += "the estimator counted " + what + " although the run sent " +
         std::to_string(r.bytes_sent) +
         " bytes that no fault damaged: bytes were lost, added or changed between the run and "
         "the estimator";
  }
  return s;
}

// Whether a counter's growth means damaged bytes. An NMEA decoder's garbage bytes and malformed
// sentences also count a receiver's messages of another protocol (UBX enabled by a host's CFG-MSG
// on an NMEA link: hil_run_e2e_test HostBytesReachTheReceiverAtItsBaud), so on the GNSS link they
// are reported but not judged; a byte lost or changed inside a sentence breaks its checksum, which
// is judged. The MCU's binary stream carries one protocol: every IMU counter is judged.
bool JudgesDamage(const std::string& counter) {
  return counter != "gnss_malformed" && counter != "gnss_garbage_bytes";
}

}  // namespace

const std::vector<std::string>& EstimatorLinkCounters(const std::string& role) {
  static const std::vector<std::string> gnss = {"gnss_checksum_errors", "gnss_malformed",
                                                "gnss_garbage_bytes"};
  static const std::vector<std::string> imu = {"imu_crc_errors", "imu_bad_headers",
                                               "imu_garbage_bytes", "imu_sequence_gaps",
                                               "imu_repeated_frames"};
  static const std::vector<std::string> none;
  return role == "gnss" ? gnss : role == "imu" ? imu : none;
}

std::vector<LinkIntegrity> CheckLinkIntegrity(const std::vector<LinkSent>& sent,
                                              const EstimatorHealth& health,
                                              const std::map<std::string, double>& baseline,
                                              const FaultTimeline& faults) {
  std::vector<LinkIntegrity> out;
  for (const LinkSent& s : sent) {
    auto it = std::find_if(out.begin(), out.end(),
                           [&](const LinkIntegrity& r) { return r.role == s.role; });
    if (it == out.end()) {
      out.push_back({});
      it = out.end() - 1;
      it->role = s.role;
    }
    it->links.push_back(s.link);
    it->bytes_sent += s.bytes_sent;
    it->bytes_dropped += s.bytes_dropped;
  }
  for (LinkIntegrity& r : out) {
    r.excused_by = Excuses(faults, r.role, r.links);
    bool counted = false;
    if (health.present) {
      for (const std::string& name : EstimatorLinkCounters(r.role)) {
        const auto c = health.counters.find(name);
        if (c == health.counters.end()) continue;
        const auto b = baseline.find(name);
        const double v = c->second - (b == baseline.end() ? 0.0 : b->second);
        r.estimator_counters[name] = v;
        counted = counted || (v > 0 && JudgesDamage(name));
      }
    }
    r.intact = r.bytes_dropped == 0 && (!counted || !r.excused_by.empty());
    if (!r.intact) r.problem = Problem(r);
  }
  return out;
}

nlohmann::json LinkIntegrityJson(const std::vector<LinkIntegrity>& links) {
  nlohmann::json a = nlohmann::json::array();
  for (const LinkIntegrity& r : links) {
    nlohmann::json counters = nlohmann::json::object();
    for (const auto& [name, value] : r.estimator_counters) counters[name] = value;
    a.push_back({{"role", r.role},
                 {"links", r.links},
                 {"bytes_sent", r.bytes_sent},
                 {"bytes_dropped", r.bytes_dropped},
                 {"estimator_counters", counters},
                 {"excused_by", r.excused_by},
                 {"intact", r.intact}});
  }
  return a;
}

}  // namespace hil::harness

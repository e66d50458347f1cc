// hil validate: the conformance report (JSON and a terminal summary).
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/harness/validate/validate.h"

namespace hil::harness {

void WriteValidationJson(const ValidationReport& r, const std::string& path) {
  nlohmann::json j;
  j["protocol"] = r.protocol;
  j["source"] = r.source;
  j["description"] = r.description;
  j["conforms"] = r.conforms();
  j["errors"] = r.errors();
  j["warnings"] = r.findings.size() - r.errors();
  j["bytes"] = r.bytes;
  j["frames"] = r.frames;
  j["bad_frames"] = r.bad_frames;
  j["garbage_bytes"] = r.garbage_bytes;
  j["epochs"] = r.epochs;
  j["epoch_rate_hz"] = r.epoch_rate_hz ? nlohmann::json(*r.epoch_rate_hz) : nlohmann::json(nullptr);
  j["epoch_first_byte_offset_p50_ms"] = r.epoch_first_byte_offset_p50_ms
                                            ? nlohmann::json(*r.epoch_first_byte_offset_p50_ms)
                                            : nlohmann::json(nullptr);
  j["epoch_first_byte_jitter_ms"] = r.epoch_first_byte_jitter_ms
                                        ? nlohmann::json(*r.epoch_first_byte_jitter_ms)
                                        : nlohmann::json(nullptr);
  j["messages"] = nlohmann::json::object();
  for (const auto& [name, st] : r.messages)
    j["messages"][name] = {{"count", st.count}, {"rate_hz", st.rate_hz}};
  j["findings"] = nlohmann::json::array();
  for (const auto& f : r.findings) {
    j["findings"].push_back({{"severity", f.error ? "error" : "warning"},
                             {"check", f.check},
                             {"message", f.message},
                             {"offset", f.offset}});
  }
  std::ofstream out(path);
  out << j.dump(2) << "\n";
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string ValidationSummary(const ValidationReport& r, std::size_t max_findings) {
  std::string s;
  char buf[256];
  std::snprintf(buf, sizeof buf, "%s: %s (%s)\n", r.source.c_str(), r.protocol.c_str(),
                r.description.c_str());
  s += buf;
  std::snprintf(buf, sizeof buf,
                "  %zu bytes, %zu frames, %zu bad frames, %zu stray bytes, %zu epochs", r.bytes,
                r.frames, r.bad_frames, r.garbage_bytes, r.epochs);
  s += buf;
  if (r.epoch_rate_hz) {
    std::snprintf(buf, sizeof buf, " at %.3f Hz", *r.epoch_rate_hz);
    s += buf;
  }
  s += "\n";
  if (r.epoch_first_byte_jitter_ms) {
    std::snprintf(buf, sizeof buf, "  first byte of an epoch %.1f ms after it (spread %.3f ms)\n",
                  *r.epoch_first_byte_offset_p50_ms, *r.epoch_first_byte_jitter_ms);
    s += buf;
  }
  for (const auto& [name, st] : r.messages) {
    std::snprintf(buf, sizeof buf, "  %-16s %6zu  %.3f Hz\n", name.c_str(), st.count, st.rate_hz);
    s += buf;
  }
  // identical findings are listed once, with their count and first offset
  std::vector<std::pair<const ValidationFinding*, std::size_t>> groups;
  for (const auto& f : r.findings) {
    auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) {
      return g.first->check == f.check && g.first->message == f.message &&
             g.first->error == f.error;
    });
    if (it == groups.end())
      groups.emplace_back(&f, 1);
    else
      ++it->second;
  }
  std::size_t shown = 0;
  for (const auto& [f, count] : groups) {
    if (shown++ == max_findings) {
      s += "  … " + std::to_string(groups.size() - max_findings) +
           " more kinds (see the JSON report)\n";
      break;
    }
    const std::string times =
        count > 1 ? " (x" + std::to_string(count) + ", first @" + std::to_string(f->offset) + ")"
        : f->offset >= 0 ? " (@" + std::to_string(f->offset) + ")"
                         : "";
    std::snprintf(buf, sizeof buf, "  %s [%s] %s%s\n", f->error ? "ERROR" : "warn ",
                  f->check.c_str(), f->message.c_str(), times.c_str());
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "%s: %zu error(s), %zu warning(s)\n",
                r.conforms() ? "CONFORMS" : "DOES NOT CONFORM", r.errors(),
                r.findings.size() - r.errors());
  s += buf;
  return s;
}

}  // namespace hil::harness

#include "hil/harness/scenario/fault_timeline.h"

#include <algorithm>
#include <array>
#include <cstdio>

#include "hil/harness/scenario/yaml_reader.h"

namespace hil::harness {
namespace {

struct ParamSpec {
  const char* key;
  double lo, hi, fallback;
};

struct KindSpec {
  FaultKind kind;
  const char* name;
  bool instantaneous;  // end_s is optional (and defaults to start_s)
  bool takes_link;
  std::vector<ParamSpec> params;
};

const std::vector<KindSpec>& Kinds() {
  static const std::vector<KindSpec> kinds{
      {FaultKind::kGnssOutage, "gnss_outage", false, false, {}},
      {FaultKind::kGnssDataGap, "gnss_data_gap", false, false, {}},
      {FaultKind::kGnssGlitch,
       "gnss_glitch",
       false,
       false,
       {{"north_m", -1e4, 1e4, 0}, {"east_m", -1e4, 1e4, 0}, {"up_m", -1e4, 1e4, 0}}},
      {FaultKind::kByteCorruption,
       "byte_corruption",
       false,
       true,
       {{"probability", 0, 1, 1e-3}, {"bit_error_rate", 0, 0.5, 0}}},
      {FaultKind::kFrameDrop, "frame_drop", false, true, {{"probability", 0, 1, 1}}},
      {FaultKind::kMcuReset, "mcu_reset", true, false, {}},
      {FaultKind::kBaudMismatch, "baud_mismatch", false, true, {{"baud", 300, 921600, 4800}}},
      {FaultKind::kFrameDuplicate, "frame_duplicate", false, true, {{"probability", 0, 1, 1}}},
      {FaultKind::kFrameTruncate, "frame_truncate", false, true, {{"probability", 0, 1, 1}}},
      {FaultKind::kCanReorder, "can_reorder", false, false, {{"probability", 0, 1, 1}}},
      {FaultKind::kGnssOverload, "gnss_overload", false, false, {}},
      {FaultKind::kControllerStop, "controller_stop", true, false, {}},
      {FaultKind::kCommandLinkLoss, "command_link_loss", false, false, {}},
      {FaultKind::kCommandLatency,
       "command_latency",
       false,
       false,
       {{"latency_s", 0, 1, 0.1}, {"jitter_s", 0, 0.5, 0}}},
      {FaultKind::kActuatorSaturation,
       "actuator_saturation",
       false,
       false,
       {{"max_wheel_speed_radps", 0, 500, 4}}},
      {FaultKind::kActuatorStuck, "actuator_stuck", false, false, {}},
  };
  return kinds;
}

}  // namespace

const char* FaultKindName(FaultKind kind) {
  for (const auto& k : Kinds()) {
    if (k.kind == kind) return k.name;
  }
  return "?";
}

double Fault::Param(const std::string& key, double fallback) const {
  const auto it = params.find(key);
  return it == params.end() ? fallback : it->second;
}

std::vector<Fault> FaultTimeline::OfKind(FaultKind kind) const {
  std::vector<Fault> out;
  for (const Fault& f : faults) {
    if (f.kind == kind) out.push_back(f);
  }
  std::stable_sort(out.begin(), out.end(),
                   [](const Fault& a, const Fault& b) { return a.start < b.start; });
  return out;
}

std::optional<Fault> FaultTimeline::ActiveAt(FaultKind kind, Time t,
                                             const std::string& link) const {
  for (const Fault& f : faults) {
    if (f.kind == kind && f.ActiveAt(t) && (f.link.empty() || f.link == link)) return f;
  }
  return std::nullopt;
}

FaultTimeline ReadFaultTimeline(const YamlReader& list, double duration_s) {
  FaultTimeline timeline;
  for (const YamlReader& e : list.Elements()) {
    if (!e.IsMap())
      e.Fail("expected a mapping such as {kind: gnss_outage, start_s: 10, end_s: 20}");
    const std::string kind_name = e.String("kind");
    const KindSpec* spec = nullptr;
    for (const auto& k : Kinds()) {
      if (kind_name == k.name) spec = &k;
    }
    if (!spec) {
      std::string msg = "unknown fault kind '" + kind_name + "' (one of:";
      for (const auto& k : Kinds()) msg += std::string(" ") + k.name;
      e.Fail("kind", msg + ")");
    }
    std::vector<std::string> keys{"kind", "start_s", "end_s"};
    if (spec->takes_link) keys.emplace_back("link");
    for (const auto& p : spec->params) keys.emplace_back(p.key);
    e.CheckKeys(keys);
    Fault f;
    f.kind = spec->kind;
    const double start_s = e.DoubleIn("start_s", 0, 0, duration_s);
    if (!e.Has("start_s")) e.Fail("missing required key 'start_s'");
    double end_s = start_s;
    if (spec->instantaneous) {
      end_s = e.DoubleIn("end_s", start_s, start_s, duration_s);
    } else {
      if (!e.Has("end_s")) e.Fail("missing required key 'end_s'");
      end_s = e.DoubleIn("end_s", 0, 0, duration_s);
      if (end_s <= start_s) {
        char buf[128];
        std::snprintf(buf, sizeof buf, "end_s (%g) must be after start_s (%g)", end_s, start_s);
        e.Fail("end_s", buf);
      }
    }
    f.start = TimeFromSeconds(start_s);
    f.end = TimeFromSeconds(end_s);
    if (spec->takes_link) {
      f.link = e.String("link", "");
      if (f.link.find('/') != std::string::npos)
        e.Fail("link", "must be a link name such as ttyGPS");
    }
    for (const auto& p : spec->params) f.params[p.key] = e.DoubleIn(p.key, p.fallback, p.lo, p.hi);
    timeline.faults.push_back(std::move(f));
  }
  return timeline;
}

}  // namespace hil::harness

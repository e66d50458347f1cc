#include "hil/harness/dut/estimate_reader.h"

#include <cmath>
#include <map>
#include <stdexcept>

#include <nlohmann/json.hpp>

#include "hil/firmware_emu/gnss/gps_time.h"
#include "hil/harness/dut/n2k_bus_reader.h"
#include "hil/harness/dut/nmea_sentence.h"

namespace hil::harness {
namespace {

constexpr double kKnotToMps = 1852.0 / 3600.0;

// A solution's integer time of validity (ns since 1970) to the run's time; none when the
// difference does not fit an int64 (a garbled line).
std::optional<Time> FromUnixNs(std::int64_t unix_ns, UnixTime start_utc) {
  std::int64_t d = 0;
  if (__builtin_sub_overflow(unix_ns, ToNs(start_utc), &d)) return std::nullopt;
  return TimeFromNs(d);
}

// Seconds since 1970 to the run's time, read to the microsecond; none beyond ±9e9 s (about
// 285 years: no solution time, and its nanoseconds would not fit an int64).
std::optional<Time> FromUnixSeconds(double unix_s, UnixTime start_utc) {
  if (!std::isfinite(unix_s) || std::fabs(unix_s) > 9e9) return std::nullopt;
  const auto sec = static_cast<std::int64_t>(std::floor(unix_s));
  const auto ns =
      static_cast<std::int64_t>(std::llround((unix_s - static_cast<double>(sec)) * 1e6)) * 1000;
  return FromUnixNs(sec * 1000000000LL + ns, start_utc);
}

std::optional<Eigen::Vector3d> Vec3(const nlohmann::json& j, const char* key) {
  if (!j.contains(key) || !j[key].is_array() || j[key].size() != 3) return std::nullopt;
  for (const auto& v : j[key]) {
    if (!v.is_number()) return std::nullopt;
  }
  return Eigen::Vector3d(j[key][0].get<double>(), j[key][1].get<double>(), j[key][2].get<double>());
}

// The members of a parsed line that the json_stdout reader uses, as the scanner gives them (the
// health object aside): one reading of the solution whichever way the line was read.
JsonSolutionLine SolutionFieldsOf(const nlohmann::json& j) {
  JsonSolutionLine l;
  const auto number = [&j](const char* key) -> std::optional<double> {
    if (j.contains(key) && j[key].is_number()) return j[key].get<double>();
    return std::nullopt;
  };
  if (j.contains("tov_unix_ns") && j["tov_unix_ns"].is_number_integer())
    l.tov_unix_ns = j["tov_unix_ns"].get<std::int64_t>();
  l.tov_utc_s = number("tov_utc_s");
  l.lat_deg = number("lat_deg");
  l.lon_deg = number("lon_deg");
  l.height_m = number("height_m");
  l.yaw_deg = number("yaw_deg");
  l.vel_enu_mps = Vec3(j, "vel_enu_mps");
  l.pos_std_enu_m = Vec3(j, "pos_std_enu_m");
  return l;
}

// Why a json_stdout line is no solution: the first field it lacks or gives wrongly.
std::string WhyNotAJsonSolution(const std::string& text, UnixTime start_utc) {
  const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
  if (j.is_discarded()) return "not JSON";
  if (!j.is_object()) return "not a JSON object";
  for (const char* key : {"lat_deg", "lon_deg"}) {
    if (!j.contains(key)) return std::string("no \"") + key + "\"";
    if (!j[key].is_number()) return std::string("\"") + key + "\" is not a number";
  }
  if (j.contains("tov_unix_ns")) {
    if (!j["tov_unix_ns"].is_number_integer())
      return "\"tov_unix_ns\" is not an integer (UTC nanoseconds)";
    if (!FromUnixNs(j["tov_unix_ns"].get<std::int64_t>(), start_utc))
      return "\"tov_unix_ns\" is out of range";
    return "a solution field is malformed";
  }
  if (!j.contains("tov_utc_s")) return "neither \"tov_unix_ns\" nor \"tov_utc_s\"";
  if (!j["tov_utc_s"].is_number()) return "\"tov_utc_s\" is not a number";
  if (!FromUnixSeconds(j["tov_utc_s"].get<double>(), start_utc))
    return "\"tov_utc_s\" is out of range";
  return "a solution field is malformed";
}

class JsonLinesReader final : public EstimateReader {
 public:
  explicit JsonLinesReader(UnixTime start) : start_(start) {}
  std::optional<EstimateRecord> Line(const std::string& text, WallTime wall) override {
    return JsonLine(nlohmann::json::parse(text, nullptr, false), wall);
  }
  bool reads_json() const override { return true; }
  std::optional<EstimateRecord> JsonLine(const nlohmann::json& j, WallTime wall) override {
    if (j.is_discarded() || !j.is_object()) return std::nullopt;
    return ScannedLine(SolutionFieldsOf(j), wall);
  }
  bool reads_scanned_lines() const override { return true; }
  std::string WhyNotASolution(const std::string& text) const override {
    return WhyNotAJsonSolution(text, start_);
  }
  std::optional<EstimateRecord> ScannedLine(const JsonSolutionLine& l, WallTime wall) override {
    if (!l.lat_deg || !l.lon_deg) return std::nullopt;
    EstimateRecord r;
    // navd's integer time of validity; other estimators may give only seconds (`tov_utc_s`)
    std::optional<Time> t;
    if (l.tov_unix_ns)
      t = FromUnixNs(*l.tov_unix_ns, start_);
    else if (l.tov_utc_s)
      t = FromUnixSeconds(*l.tov_utc_s, start_);
    if (!t) return std::nullopt;
    r.t_validity = *t;
    r.lat_deg = *l.lat_deg;
    r.lon_deg = *l.lon_deg;
    if (l.height_m) r.height_m = *l.height_m;
    r.vel_enu_mps = l.vel_enu_mps;
    r.pos_std_enu_m = l.pos_std_enu_m;
    r.yaw_deg = l.yaw_deg;
    r.wall_rx = wall;
    return r;
  }

 private:
  UnixTime start_;
};

class GpsdJsonReader final : public EstimateReader {
 public:
  explicit GpsdJsonReader(UnixTime start) : start_(start) {}
  std::optional<EstimateRecord> Line(const std::string& text, WallTime wall) override {
    return JsonLine(nlohmann::json::parse(text, nullptr, false), wall);
  }
  bool reads_json() const override { return true; }
  std::optional<EstimateRecord> JsonLine(const nlohmann::json& j, WallTime wall) override {
    if (j.is_discarded() || !j.is_object() || j.value("class", "") != "TPV") return std::nullopt;
    if (!j.contains("time") || !j["time"].is_string() || !j.contains("lat") || !j.contains("lon"))
      return std::nullopt;
    if (j.value("mode", 0) < 2) return std::nullopt;
    EstimateRecord r;
    try {
      r.t_validity = Time{} + (gnss::ParseIsoUtc(j["time"].get<std::string>()) - start_);
    } catch (const std::invalid_argument&) {
      return std::nullopt;
    }
    r.lat_deg = j["lat"].get<double>();
    r.lon_deg = j["lon"].get<double>();
    if (j.contains("altHAE") && j["altHAE"].is_number())
      r.height_m = j["altHAE"].get<double>();
    else if (j.contains("alt") && j["alt"].is_number())
      r.height_m = j["alt"].get<double>();
    if (j.contains("track") && j["track"].is_number()) {
      r.yaw_deg = j["track"].get<double>();
      if (j.contains("speed") && j["speed"].is_number()) {
        const double v = j["speed"].get<double>(), psi = *r.yaw_deg * M_PI / 180.0;
        const double climb =
            j.contains("climb") && j["climb"].is_number() ? j["climb"].get<double>() : 0.0;
        r.vel_enu_mps = Eigen::Vector3d(v * std::sin(psi), v * std::cos(psi), climb);
      }
    }
    if (j.contains("epx") && j.contains("epy") && j.contains("epv") && j["epx"].is_number() &&
        j["epy"].is_number() && j["epv"].is_number()) {
      // gpsd's epx/epy/epv are 95 % confidence half-widths; 1-sigma ≈ value / 1.96
      r.pos_std_enu_m =
          Eigen::Vector3d(j["epx"].get<double>(), j["epy"].get<double>(), j["epv"].get<double>()) /
          1.96;
    }
    r.wall_rx = wall;
    return r;
  }

 private:
  UnixTime start_;
};

class NmeaReader final : public EstimateReader {
 public:
  explicit NmeaReader(UnixTime start) : start_(start) {}
  std::optional<EstimateRecord> Line(const std::string& text, WallTime wall) override {
    const NmeaParse p = ParseNmeaSentence(text);
    if (!p.sentence) return std::nullopt;
    const NmeaSentence& s = *p.sentence;
    const auto& f = s.fields;
    if (s.type() == "RMC" && f.size() >= 8 && f[1] == "A") {
      last_rmc_tod_ = NmeaTimeOfDay(f[0]);
      char* end = nullptr;
      const double kn = std::strtod(f[6].c_str(), &end);
      rmc_speed_mps_ = end != f[6].c_str() ? std::optional<double>(kn * kKnotToMps) : std::nullopt;
      const double course = std::strtod(f[7].c_str(), &end);
      rmc_course_deg_ = end != f[7].c_str() ? std::optional<double>(course) : std::nullopt;
      return std::nullopt;
    }
    if (s.type() != "GGA" || f.size() < 11 || f[5].empty() || f[5] == "0") return std::nullopt;
    const auto tod = NmeaTimeOfDay(f[0]);
    const auto lat = NmeaDegrees(f[1], f[2]);
    const auto lon = NmeaDegrees(f[3], f[4]);
    if (!tod || !lat || !lon) return std::nullopt;
    EstimateRecord r;
    // the day: the one that puts this time of day closest to the scenario start
    const std::int64_t start_ns = ToNs(start_);
    const std::int64_t day0 = start_ns - ((start_ns % kDayNs) + kDayNs) % kDayNs;
    std::int64_t t_ns = day0 + static_cast<std::int64_t>(std::llround(*tod * 1e9));
    if (t_ns < start_ns - kDayNs / 2) t_ns += kDayNs;
    r.t_validity = TimeFromNs(t_ns - start_ns);
    r.lat_deg = *lat;
    r.lon_deg = *lon;
    const double msl = std::atof(f[8].c_str());
    const double sep = f.size() > 10 ? std::atof(f[10].c_str()) : 0.0;
    r.height_m = msl + sep;
    if (last_rmc_tod_ && std::abs(*last_rmc_tod_ - *tod) < 1e-3 && rmc_speed_mps_ &&
        rmc_course_deg_) {
      const double psi = *rmc_course_deg_ * M_PI / 180.0;
      r.vel_enu_mps =
          Eigen::Vector3d(*rmc_speed_mps_ * std::sin(psi), *rmc_speed_mps_ * std::cos(psi), 0.0);
      r.yaw_deg = *rmc_course_deg_;
    }
    r.wall_rx = wall;
    return r;
  }
  bool OtherRecordOfTheStream(const std::string& text) const override {
    return ParseNmeaSentence(text).sentence.has_value();
  }

 private:
  UnixTime start_;
  std::optional<double> last_rmc_tod_, rmc_speed_mps_, rmc_course_deg_;
};

// NMEA 2000 from candump -l/-L lines on stdout, decoded frame by frame (n2k_bus_reader.h).
class N2kCandumpReader final : public EstimateReader {
 public:
  explicit N2kCandumpReader(UnixTime start) : bus_(start) {}
  std::optional<EstimateRecord> Line(const std::string& text, WallTime wall) override {
    const std::size_t hash = text.find('#');
    const std::size_t sp = text.rfind(' ', hash);
    if (hash == std::string::npos || sp == std::string::npos || hash - sp - 1 != 8)
      return std::nullopt;
    std::uint32_t id = 0;
    std::string data;
    try {
      id = static_cast<std::uint32_t>(std::stoul(text.substr(sp + 1, 8), nullptr, 16));
      const std::string hex = text.substr(hash + 1);
      if (hex.size() % 2 != 0 || hex.empty()) return std::nullopt;
      for (std::size_t i = 0; i < hex.size(); i += 2)
        data += static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16));
    } catch (const std::exception&) {
      return std::nullopt;
    }
    return bus_.Frame(id, data, wall);
  }

 private:
  N2kBusReader bus_;
};

// n2k_socketcan: the solutions come from the bus (EstimateCollector::AttachBus); stdout lines
// (navd's JSON with its health object) are diagnostics only.
class NoLinesReader final : public EstimateReader {
 public:
  std::optional<EstimateRecord> Line(const std::string&, WallTime) override { return std::nullopt; }
  bool SolutionsInLines() const override { return false; }
};

}  // namespace

std::string EstimateReader::WhyNotASolution(const std::string& /*text*/) const {
  return "not a solution in the scenario's estimator.output format";
}

const char* RawEstimateFileName(EstimatorOutput output) {
  const bool nmea = output == EstimatorOutput::kNmeaStdout || output == EstimatorOutput::kNmeaPty;
  return nmea ? "estimate.nmea" : "estimate.jsonl";
}

std::unique_ptr<EstimateReader> MakeEstimateReader(EstimatorOutput output, UnixTime start_utc) {
  switch (output) {
    case EstimatorOutput::kJsonStdout:
      return std::make_unique<JsonLinesReader>(start_utc);
    case EstimatorOutput::kGpsdJson:
      return std::make_unique<GpsdJsonReader>(start_utc);
    case EstimatorOutput::kNmeaStdout:
    case EstimatorOutput::kNmeaPty:
      return std::make_unique<NmeaReader>(start_utc);
    case EstimatorOutput::kN2kCandump:
      return std::make_unique<N2kCandumpReader>(start_utc);
    case EstimatorOutput::kN2kSocketcan:
      return std::make_unique<NoLinesReader>();
  }
  throw std::invalid_argument("unknown estimator output format");
}

}  // namespace hil::harness

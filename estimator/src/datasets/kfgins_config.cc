#include "hil/estimator/datasets/kfgins_config.h"

#include <charconv>
#include <cmath>
#include <fstream>
#include <map>
#include <vector>

#include <sys/stat.h>

namespace hil::estimator::datasets {
namespace {

struct YamlValue {
  std::string text;
  long line = 0;
};

std::string Trim(const std::string& s) {
  const std::size_t b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const std::size_t e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

// strips a '#' comment that is not inside quotes
std::string StripComment(const std::string& s) {
  char quote = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (quote) {
      if (s[i] == quote) quote = 0;
    } else if (s[i] == '"' || s[i] == '\'') {
      quote = s[i];
    } else if (s[i] == '#' && (i == 0 || s[i - 1] == ' ' || s[i - 1] == '\t')) {
      return s.substr(0, i);
    }
  }
  return s;
}

// "key: value" lines, nested keys joined with '.', e.g. "imunoise.arw"
std::map<std::string, YamlValue> ReadFlatYaml(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw DatasetError(path, 0, "cannot open the configuration");
  std::map<std::string, YamlValue> keys;
  std::string raw, parent;
  long line_no = 0;
  while (std::getline(in, raw)) {
    ++line_no;
    const std::string line = StripComment(raw);
    if (Trim(line).empty() || Trim(line) == "---") continue;
    const std::size_t indent = line.find_first_not_of(" ");
    const std::string body = Trim(line);
    const std::size_t colon = body.find(':');
    if (colon == std::string::npos) throw DatasetError(path, line_no, "expected 'key: value'");
    const std::string key = Trim(body.substr(0, colon));
    const std::string value = Trim(body.substr(colon + 1));
    if (indent == 0) parent.clear();
    if (indent > 0 && parent.empty())
      throw DatasetError(path, line_no, key + ": indented key without a parent");
    const std::string full = indent > 0 ? parent + "." + key : key;
    if (value.empty()) {
      if (indent == 0) parent = key;
      continue;
    }
    if (keys.count(full)) throw DatasetError(path, line_no, full + ": given twice");
    keys[full] = {value, line_no};
  }
  return keys;
}

std::string Unquote(const std::string& s) {
  if (s.size() >= 2 && (s.front() == '"' || s.front() == '\'') && s.back() == s.front())
    return s.substr(1, s.size() - 2);
  return s;
}

class Keys {
 public:
  Keys(std::string path, std::map<std::string, YamlValue> keys)
      : path_(std::move(path)), keys_(std::move(keys)) {}

  const YamlValue& Required(const std::string& key) const {
    const auto it = keys_.find(key);
    if (it == keys_.end()) throw DatasetError(path_, 0, key + ": missing");
    return it->second;
  }
  bool Has(const std::string& key) const { return keys_.count(key) > 0; }
  std::string String(const std::string& key) const { return Unquote(Required(key).text); }
  double Number(const std::string& key) const { return ParseNumber(key, Required(key).text); }
  double NumberOr(const std::string& key, double fallback) const {
    return Has(key) ? Number(key) : fallback;
  }
  Eigen::Vector3d Vector(const std::string& key) const {
    const YamlValue& v = Required(key);
    if (v.text.size() < 2 || v.text.front() != '[' || v.text.back() != ']')
      throw DatasetError(path_, v.line, key + ": expected a list [x, y, z]");
    std::vector<std::string> items;
    std::string cur;
    for (char c : v.text.substr(1, v.text.size() - 2)) {
      if (c == ',') {
        items.push_back(cur);
        cur.clear();
      } else {
        cur += c;
      }
    }
    items.push_back(cur);
    if (items.size() != 3)
      throw DatasetError(path_, v.line,
                         key + ": expected 3 values, got " + std::to_string(items.size()));
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i) out[i] = ParseNumber(key, items[static_cast<std::size_t>(i)]);
    return out;
  }
  /// KF-GINS's per-axis noise lists ([x, y, z]) or one number for the three axes; navd's noise
  /// is isotropic, so it takes the largest of the three
  double AxesNumber(const std::string& key) const {
    const std::string t = Trim(Required(key).text);
    return !t.empty() && t.front() == '[' ? Vector(key).maxCoeff() : Number(key);
  }
  double AxesNumberOr(const std::string& key, double fallback) const {
    return Has(key) ? AxesNumber(key) : fallback;
  }
  std::optional<Eigen::Vector3d> OptionalVector(const std::string& key) const {
    if (!Has(key)) return std::nullopt;
    return Vector(key);
  }

 private:
  double ParseNumber(const std::string& key, const std::string& raw) const {
    const std::string t = Trim(raw);
    double v = 0;
    const char* b = t.data() + (t.size() > 0 && t[0] == '+' ? 1 : 0);
    const auto [ptr, ec] = std::from_chars(b, t.data() + t.size(), v);
    if (t.empty() || ec != std::errc() || ptr != t.data() + t.size() || !std::isfinite(v))
      throw DatasetError(path_, Required(key).line, key + ": not a finite number: '" + t + "'");
    return v;
  }

  std::string path_;
  std::map<std::string, YamlValue> keys_;
};

bool FileExists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace

std::string KfginsConfig::Resolve(const std::string& p) const {
  if (p.empty() || p[0] == '/' || FileExists(p)) return p;
  const std::size_t slash = config_path.rfind('/');
  if (slash == std::string::npos) return p;
  const std::string alt = config_path.substr(0, slash + 1) + p;
  return FileExists(alt) || FileExists(alt.substr(0, alt.rfind('/'))) ? alt : p;
}

KfginsConfig LoadKfginsConfig(const std::string& path) {
  const Keys k(path, ReadFlatYaml(path));
  KfginsConfig c;
  c.config_path = path;
  c.imupath = k.String("imupath");
  c.gnsspath = k.String("gnsspath");
  c.outputpath = k.String("outputpath");
  c.imudatalen = static_cast<int>(k.NumberOr("imudatalen", 7));
  if (c.imudatalen < 7 || c.imudatalen > 8)
    throw DatasetError(path, k.Required("imudatalen").line, "imudatalen: must be 7 or 8");
  c.imudatarate_hz = k.Number("imudatarate");
  if (!(c.imudatarate_hz > 0))
    throw DatasetError(path, k.Required("imudatarate").line, "imudatarate: must be positive");
  c.starttime_s = k.Number("starttime");
  c.endtime_s = k.NumberOr("endtime", -1);
  c.initpos_deg_deg_m = k.Vector("initpos");
  c.initvel_ned_mps = k.Vector("initvel");
  c.initatt_rpy_deg = k.Vector("initatt");
  c.initposstd_ned_m = k.Vector("initposstd");
  c.initvelstd_ned_mps = k.Vector("initvelstd");
  c.initattstd_deg = k.Vector("initattstd");
  c.initgyrbias_deg_hr = k.OptionalVector("initgyrbias");
  c.initaccbias_mgal = k.OptionalVector("initaccbias");
  c.initbgstd_deg_hr = k.OptionalVector("initbgstd");
  c.initbastd_mgal = k.OptionalVector("initbastd");
  c.initgyrscale_ppm = k.OptionalVector("initgyrscale");
  c.initsgstd_ppm = k.OptionalVector("initsgstd");
  c.imunoise.arw_deg_rthr = k.AxesNumber("imunoise.arw");
  c.imunoise.vrw_mps_rthr = k.AxesNumber("imunoise.vrw");
  c.imunoise.gbstd_deg_hr = k.AxesNumber("imunoise.gbstd");
  c.imunoise.abstd_mgal = k.AxesNumber("imunoise.abstd");
  c.imunoise.gsstd_ppm = k.AxesNumberOr("imunoise.gsstd", 0);
  c.imunoise.asstd_ppm = k.AxesNumberOr("imunoise.asstd", 0);
  c.imunoise.corrtime_hr = k.Number("imunoise.corrtime");
  if (!(c.imunoise.corrtime_hr > 0))
    throw DatasetError(path, k.Required("imunoise.corrtime").line,
                       "imunoise.corrtime: must be positive");
  c.antlever_frd_m = k.Vector("antlever");
  return c;
}

}  // namespace hil::estimator::datasets

#include "hil/estimator/drivers/nmea_decoder.h"

#include <charconv>
#include <vector>

namespace hil::estimator::drivers {
namespace {

std::vector<std::string_view> SplitFields(std::string_view body) {
  std::vector<std::string_view> out;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= body.size(); ++i) {
    if (i == body.size() || body[i] == ',') {
      out.push_back(body.substr(start, i - start));
      start = i + 1;
    }
  }
  return out;
}

std::optional<double> ToDouble(std::string_view s) {
  if (s.empty()) return std::nullopt;
  double v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

std::optional<int> ToInt(std::string_view s) {
  if (s.empty()) return std::nullopt;
  int v = 0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size()) return std::nullopt;
  return v;
}

// The step of a decimal field as written: 10^-(digits after the point), 1 without a point.
double DecimalStep(std::string_view s) {
  const std::size_t dot = s.find('.');
  double step = 1.0;
  if (dot == std::string_view::npos) return step;
  for (std::size_t i = dot + 1; i < s.size(); ++i) step *= 0.1;
  return step;
}

int HexDigit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// ddmm.mmmm + hemisphere → signed degrees
std::optional<double> ParseAngle(std::string_view value, std::string_view hemi, int deg_digits) {
  if (value.size() < static_cast<std::size_t>(deg_digits) + 2 || hemi.size() != 1)
    return std::nullopt;
  const auto deg = ToInt(value.substr(0, deg_digits));
  const auto min = ToDouble(value.substr(deg_digits));
  if (!deg || !min || *min >= 60.0 || *min < 0) return std::nullopt;
  double d = *deg + *min / 60.0;
  if (d > (deg_digits == 2 ? 90.0 : 180.0)) return std::nullopt;  // ddd = 999: not a place on Earth
  const char h = hemi[0];
  if (h == 'S' || h == 'W')
    d = -d;
  else if (h != 'N' && h != 'E')
    return std::nullopt;
  return d;
}

std::optional<std::int64_t> ParseTimeOfDay(std::string_view s) {
  if (s.size() < 6) return std::nullopt;
  const auto hh = ToInt(s.substr(0, 2)), mm = ToInt(s.substr(2, 2));
  const auto ss = ToDouble(s.substr(4));
  if (!hh || !mm || !ss || *hh > 23 || *mm > 59 || *ss >= 61.0 || *ss < 0) return std::nullopt;
  return (static_cast<std::int64_t>(*hh) * 3600 + *mm * 60) * 1000000000LL +
         static_cast<std::int64_t>(*ss * 1e9 + 0.5);
}

}  // namespace

std::optional<NmeaFix> NmeaDecoder::ParseSentence(std::string_view s, NmeaDecoderStats* stats) {
  while (!s.empty() && (s.back() == '\r' || s.back() == '\n')) s.remove_suffix(1);
  const std::size_t star = s.rfind('*');
  if (s.empty() || s[0] != '$' || star == std::string_view::npos || star + 3 != s.size()) {
    ++stats->malformed;
    return std::nullopt;
  }
  const std::string_view body = s.substr(1, star - 1);
  std::uint8_t sum = 0;
  for (char c : body) sum ^= static_cast<std::uint8_t>(c);
  const int hi = HexDigit(s[star + 1]), lo = HexDigit(s[star + 2]);
  if (hi < 0 || lo < 0 || sum != static_cast<std::uint8_t>(hi * 16 + lo)) {
    ++stats->bad_checksum;
    return std::nullopt;
  }
  const auto f = SplitFields(body);
  if (f[0].size() != 5) {
    ++stats->unsupported;
    return std::nullopt;
  }
  const std::string_view type = f[0].substr(2);
  NmeaFix fix;
  if (type == "GGA" && f.size() >= 15) {
    fix.kind = NmeaFix::Kind::kGga;
    fix.utc_time_of_day_ns = ParseTimeOfDay(f[1]);
    fix.lat_deg = ParseAngle(f[2], f[3], 2);
    fix.lon_deg = ParseAngle(f[4], f[5], 3);
    fix.quality = ToInt(f[6]).value_or(0);
    fix.num_sv = ToInt(f[7]).value_or(0);
    fix.hdop = ToDouble(f[8]);
    fix.msl_altitude_m = ToDouble(f[9]);
    if (fix.msl_altitude_m) fix.altitude_step_m = DecimalStep(f[9]);
    fix.geoid_separation_m = ToDouble(f[11]);
    if (fix.geoid_separation_m) fix.geoid_step_m = DecimalStep(f[11]);
    fix.valid = fix.quality > 0 && fix.lat_deg && fix.lon_deg;
  } else if (type == "RMC" && f.size() >= 10) {
    fix.kind = NmeaFix::Kind::kRmc;
    fix.utc_time_of_day_ns = ParseTimeOfDay(f[1]);
    fix.lat_deg = ParseAngle(f[3], f[4], 2);
    fix.lon_deg = ParseAngle(f[5], f[6], 3);
    if (const auto kn = ToDouble(f[7])) fix.speed_mps = *kn * 1852.0 / 3600.0;
    fix.course_deg = ToDouble(f[8]);
    if (f[9].size() == 6) {
      fix.day = ToInt(f[9].substr(0, 2));
      fix.month = ToInt(f[9].substr(2, 2));
      if (const auto yy = ToInt(f[9].substr(4, 2))) fix.year = 2000 + *yy;
    }
    fix.valid = f[2] == "A" && fix.lat_deg && fix.lon_deg;
  } else if (type == "GSA" && f.size() >= 18) {
    // $xxGSA,mode,fix type,12 × satellite,PDOP,HDOP,VDOP[,system id]
    fix.kind = NmeaFix::Kind::kGsa;
    const auto vdop = ToDouble(f[17]);
    if (ToInt(f[2]).value_or(0) == 3 && vdop && *vdop > 0 && *vdop < 99.0) {
      fix.vdop = vdop;
      fix.hdop = ToDouble(f[16]);
    }
  } else {
    ++stats->unsupported;
    return std::nullopt;
  }
  ++stats->sentences_ok;
  return fix;
}

void NmeaDecoder::Feed(std::string_view bytes) {
  for (char c : bytes) {
    if (c == '$') {
      if (in_sentence_) ++stats_.malformed;  // a sentence cut short by the next one
      line_.assign(1, c);
      in_sentence_ = true;
      continue;
    }
    if (!in_sentence_) {
      if (c != '\r' && c != '\n') ++stats_.garbage_bytes;
      continue;
    }
    if (c == '\n' || c == '\r') {
      if (line_.size() > 1) {
        if (auto fix = ParseSentence(line_, &stats_)) handler_(*fix);
      }
      in_sentence_ = false;
      line_.clear();
      continue;
    }
    if (static_cast<unsigned char>(c) < 0x20 || static_cast<unsigned char>(c) > 0x7E ||
        line_.size() >= kMaxSentence) {
      // binary data or a runaway line: the sentence is lost
      if (line_.size() >= kMaxSentence)
        ++stats_.overlong;
      else
        ++stats_.malformed;
      in_sentence_ = false;
      line_.clear();
      continue;
    }
    line_ += c;
  }
}

}  // namespace hil::estimator::drivers

// hil validate: framing and protocol checks of NMEA 0183 / UBX byte streams.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/little_endian.h"
#include "hil/harness/dut/nmea_sentence.h"
#include "hil/harness/eval/evaluator.h"
#include "hil/harness/validate/validate.h"

#include "garbage_run.h"

namespace hil::harness {
namespace {

constexpr std::size_t kNmeaMaxChars = 82;  // '$' to LF inclusive (NMEA 0183)
constexpr std::size_t kUbxMaxPayload = 4096;
constexpr double kNeo5mMaxRateHz = 4.0;

// ---------------------------------------------------------------- framing
struct Frame {
  enum class Kind { kNmea, kUbx, kComment } kind = Kind::kNmea;
  std::size_t offset = 0, length = 0;
  std::int64_t t_ns = -1;
  std::optional<NmeaSentence> nmea;  // valid sentence
  std::uint8_t cls = 0, id = 0;
  std::string payload;
  bool crlf = false;
};

struct Framed {
  std::vector<Frame> frames;
  std::size_t bad = 0, garbage = 0;
};

std::int64_t TimeAt(const ByteStream& s, std::size_t i) {
  return i < s.t_ns.size() ? s.t_ns[i] : -1;
}

// After one frame: go on at the new position, or stop (the stream ends inside the frame).
enum class FrameStep { kNext, kStop };

// The UBX frame whose sync pair is at `pos`: appended to `out` with `pos` past it, or a finding
// with `pos` past the sync pair (to resynchronise).
FrameStep FrameUbx(const ByteStream& s, std::size_t& pos, Framed& out, ValidationReport& rep) {
  using gnss::ubx::FrameAtStatus;
  const gnss::ubx::FrameAt u =
      gnss::ubx::ParseFrameAt(std::string_view(s.bytes).substr(pos), kUbxMaxPayload);
  const std::size_t len = u.payload_length;
  if (u.status == FrameAtStatus::kHeaderCut) {
    rep.findings.push_back({false, "truncated", "UBX header cut off at the end of the stream",
                            static_cast<std::int64_t>(pos)});
    return FrameStep::kStop;
  }
  if (u.status == FrameAtStatus::kTooLong) {
    rep.findings.push_back({true, "ubx_length",
                            "implausible UBX payload length " + std::to_string(len),
                            static_cast<std::int64_t>(pos)});
    ++out.bad;
    pos += 2;
    return FrameStep::kNext;
  }
  if (u.status == FrameAtStatus::kCut) {
    rep.findings.push_back({false, "truncated", "UBX frame cut off at the end of the stream",
                            static_cast<std::int64_t>(pos)});
    return FrameStep::kStop;
  }
  if (u.status == FrameAtStatus::kBadChecksum) {
    char msg[96];
    std::snprintf(msg, sizeof msg,
                  "UBX checksum mismatch (class 0x%02X id 0x%02X, %zu payload bytes)", u.cls, u.id,
                  len);
    rep.findings.push_back({true, "checksum", msg, static_cast<std::int64_t>(pos)});
    ++out.bad;
    pos += 2;  // resynchronise on the next sync pair
    return FrameStep::kNext;
  }
  Frame f;
  f.kind = Frame::Kind::kUbx;
  f.offset = pos;
  f.length = u.frame_size();
  f.t_ns = TimeAt(s, pos);
  f.cls = u.cls;
  f.id = u.id;
  f.payload = std::string(u.payload);
  out.frames.push_back(std::move(f));
  pos += u.frame_size();
  return FrameStep::kNext;
}

// The NMEA sentence whose '$' is at `pos`: appended to `out` (or a finding), `pos` past its line.
FrameStep FrameNmea(const ByteStream& s, std::size_t& pos, Framed& out, ValidationReport& rep) {
  const std::string& b = s.bytes;
  std::size_t end = pos + 1;
  while (end < b.size() && b[end] != '\n' && b[end] != '$' && end - pos < 4 * kNmeaMaxChars &&
         !(static_cast<unsigned char>(b[end]) == 0xB5 && end + 1 < b.size() &&
           static_cast<unsigned char>(b[end + 1]) == 0x62)) {
    ++end;
  }
  if (end >= b.size()) {
    rep.findings.push_back({false, "truncated", "NMEA sentence cut off at the end of the stream",
                            static_cast<std::int64_t>(pos)});
    return FrameStep::kStop;
  }
  if (b[end] != '\n') {
    rep.findings.push_back(
        {true, "framing", "NMEA sentence without line end", static_cast<std::int64_t>(pos)});
    ++out.bad;
    pos = end;
    return FrameStep::kNext;
  }
  std::string line = b.substr(pos, end - pos);
  const bool crlf = !line.empty() && line.back() == '\r';
  if (crlf) line.pop_back();
  const std::size_t total = end + 1 - pos;
  NmeaParse p = ParseNmeaSentence(line);
  if (!p.sentence) {
    rep.findings.push_back(
        {true, p.error.find("checksum") != std::string::npos ? "checksum" : "framing",
         "'" + line.substr(0, 24) + (line.size() > 24 ? "…" : "") + "': " + p.error,
         static_cast<std::int64_t>(pos)});
    ++out.bad;
  } else {
    if (total > kNmeaMaxChars + (crlf ? 0 : 1)) {
      rep.findings.push_back({true, "length",
                              p.sentence->address + " is " + std::to_string(line.size() + 2) +
                                  " characters with CR LF (NMEA allows 82)",
                              static_cast<std::int64_t>(pos)});
    }
    Frame f;
    f.kind = Frame::Kind::kNmea;
    f.offset = pos;
    f.length = total;
    f.t_ns = TimeAt(s, pos);
    f.nmea = std::move(p.sentence);
    f.crlf = crlf;
    out.frames.push_back(std::move(f));
  }
  pos = end + 1;
  return FrameStep::kNext;
}

Framed FrameStream(const ByteStream& s, bool want_nmea, bool want_ubx, ValidationReport& rep) {
  Framed out;
  const std::string& b = s.bytes;
  std::size_t pos = 0;
  GarbageRun garbage;
  const auto flush_garbage = [&](std::size_t end) { out.garbage += garbage.End(end, rep); };
  while (pos < b.size()) {
    const auto c = static_cast<unsigned char>(b[pos]);
    const bool line_start = pos == 0 || b[pos - 1] == '\n';
    if (want_ubx && c == 0xB5 && pos + 1 < b.size() &&
        static_cast<unsigned char>(b[pos + 1]) == 0x62) {
      flush_garbage(pos);
      if (FrameUbx(s, pos, out, rep) == FrameStep::kStop) break;
      continue;
    }
    if (want_nmea && c == '#' &&
        line_start) {  // a comment line of a log (gpsd format): a segment break
      flush_garbage(pos);
      const std::size_t nl = b.find('\n', pos);
      Frame f;
      f.kind = Frame::Kind::kComment;
      f.offset = pos;
      f.length = (nl == std::string::npos ? b.size() : nl + 1) - pos;
      out.frames.push_back(f);
      pos += f.length;
      continue;
    }
    if (want_nmea && c == '$') {
      flush_garbage(pos);
      if (FrameNmea(s, pos, out, rep) == FrameStep::kStop) break;
      continue;
    }
    if (c == '\r' || c == '\n') {
      flush_garbage(pos);
      ++pos;
      continue;
    }
    garbage.Add(pos);
    ++pos;
  }
  flush_garbage(pos < b.size() ? pos : b.size());
  return out;
}

// ---------------------------------------------------------------- NMEA sentence layouts
bool IsNumber(const std::string& s, bool allow_empty = false) {
  if (s.empty()) return allow_empty;
  char* end = nullptr;
  std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}
bool OneOf(const std::string& s, std::initializer_list<const char*> v, bool allow_empty = false) {
  if (s.empty()) return allow_empty;
  for (const char* x : v) {
    if (s == x) return true;
  }
  return false;
}

/// The time-of-day field of a sentence type (index into fields), or -1 when it carries none.
int TimeField(const std::string& type) {
  if (type == "GGA" || type == "RMC" || type == "ZDA" || type == "GST" || type == "GBS" ||
      type == "GRS")
    return 0;
  if (type == "GLL") return 4;
  return -1;
}

/// Checks one sentence's layout; returns an empty string when it conforms.
std::string CheckLayout(const NmeaSentence& s, bool& known) {
  const std::string t = s.type();
  const auto& f = s.fields;
  const std::size_t n = f.size();
  known = true;
  const auto pos_ok = [&](std::size_t i) {
    if (f[i].empty() && f[i + 1].empty() && f[i + 2].empty() && f[i + 3].empty()) return true;
    return NmeaDegrees(f[i], f[i + 1]).has_value() && NmeaDegrees(f[i + 2], f[i + 3]).has_value();
  };
  const auto time_ok = [&](std::size_t i) {
    return f[i].empty() || NmeaTimeOfDay(f[i]).has_value();
  };
  if (t == "GGA") {
    if (n != 14) return "GGA has " + std::to_string(n) + " fields (14 expected)";
    if (!time_ok(0)) return "GGA time '" + f[0] + "' is not hhmmss.ss";
    if (!pos_ok(1)) return "GGA position is malformed";
    if (!OneOf(f[5], {"0", "1", "2", "3", "4", "5", "6", "7", "8"}))
      return "GGA quality '" + f[5] + "' is not 0-8";
    if (!IsNumber(f[6], true) || !IsNumber(f[7], true) || !IsNumber(f[8], true))
      return "GGA satellites/HDOP/altitude not numeric";
    return "";
  }
  if (t == "RMC") {
    if (n < 11 || n > 13) return "RMC has " + std::to_string(n) + " fields (11-13 expected)";
    if (!time_ok(0)) return "RMC time '" + f[0] + "' is not hhmmss.ss";
    if (!OneOf(f[1], {"A", "V"})) return "RMC status '" + f[1] + "' is not A or V";
    if (!pos_ok(2)) return "RMC position is malformed";
    if (!IsNumber(f[6], true) || !IsNumber(f[7], true)) return "RMC speed/course not numeric";
    if (!f[8].empty() && (f[8].size() != 6 || !IsNumber(f[8])))
      return "RMC date '" + f[8] + "' is not ddmmyy";
    if (n >= 12 && !OneOf(f[11], {"A", "D", "E", "N", "M", "S", "F", "R", "P"}))
      return "RMC mode '" + f[11] + "' unknown";
    return "";
  }
  if (t == "VTG") {
    if (n != 8 && n != 9) return "VTG has " + std::to_string(n) + " fields (8 or 9 expected)";
    if (!IsNumber(f[0], true) || !IsNumber(f[4], true) || !IsNumber(f[6], true))
      return "VTG course/speed not numeric";
    return "";
  }
  if (t == "GSA") {
    if (n < 17 || n > 18) return "GSA has " + std::to_string(n) + " fields (17 expected)";
    if (!OneOf(f[0], {"A", "M"})) return "GSA mode '" + f[0] + "' is not A or M";
    if (!OneOf(f[1], {"1", "2", "3"})) return "GSA fix type '" + f[1] + "' is not 1-3";
    return "";
  }
  if (t == "GSV") {
    if (n < 3 || ((n - 3) % 4 != 0 && (n - 3) % 4 != 1) || n > 20)
      return "GSV has " + std::to_string(n) + " fields";
    if (!IsNumber(f[0]) || !IsNumber(f[1]) || !IsNumber(f[2])) return "GSV counts not numeric";
    return "";
  }
  if (t == "GLL") {
    if (n != 6 && n != 7) return "GLL has " + std::to_string(n) + " fields (6 or 7 expected)";
    if (!pos_ok(0)) return "GLL position is malformed";
    if (!time_ok(4)) return "GLL time '" + f[4] + "' is not hhmmss.ss";
    if (!OneOf(f[5], {"A", "V"})) return "GLL status '" + f[5] + "' is not A or V";
    return "";
  }
  if (t == "TXT") return n == 4 ? "" : "TXT has " + std::to_string(n) + " fields (4 expected)";
  if (t == "ZDA") return n == 6 && time_ok(0) ? "" : "ZDA malformed";
  if (t == "GST")
    return n == 8 && time_ok(0) ? "" : "GST has " + std::to_string(n) + " fields (8 expected)";
  if (t == "GBS") return (n == 8 || n == 10) && time_ok(0) ? "" : "GBS malformed";
  if (t == "GRS") return n >= 14 && time_ok(0) ? "" : "GRS malformed";
  known = false;
  return "";
}

int Neo5mRank(const std::string& type) {
  static const char* kOrder[] = {"RMC", "VTG", "GGA", "GSA", "GSV", "GLL"};
  for (int i = 0; i < 6; ++i) {
    if (type == kOrder[i]) return i;
  }
  return -1;
}

struct Epoch {
  std::optional<double> tod_s;
  std::vector<const Frame*> frames;  // NMEA sentences in order
  std::size_t bytes = 0;
  std::int64_t t_first_ns = -1;
  bool after_break = false;  // a comment or the stream start precedes it
  bool before_break = false;
};

// The valid sentences grouped into epochs (by time of day, and at every break of the log), with
// the per-sentence checks: layout, the message set, the talker, the line end.
std::vector<Epoch> GroupEpochs(const Framed& fr, bool neo5m, ValidationReport& rep) {
  std::vector<Epoch> epochs;
  bool pending_break = true;
  std::size_t lf_only = 0;
  for (const Frame& f : fr.frames) {
    if (f.kind == Frame::Kind::kComment) {
      if (!epochs.empty()) epochs.back().before_break = true;
      pending_break = true;
      continue;
    }
    if (f.kind != Frame::Kind::kNmea) continue;
    const NmeaSentence& s = *f.nmea;
    const std::string type = s.type();
    rep.messages[s.address].count++;
    if (!f.crlf) ++lf_only;
    bool known = false;
    if (const std::string e = CheckLayout(s, known); !e.empty()) {
      rep.findings.push_back({true, "layout", e, static_cast<std::int64_t>(f.offset)});
    }
    if (s.address != "PUBX" && !known) {
      rep.findings.push_back(
          {neo5m, neo5m ? "message_set" : "unknown_sentence",
           s.address + " is not " +
               (neo5m ? "a sentence a u-blox 5 sends" : "a sentence this validator knows"),
           static_cast<std::int64_t>(f.offset)});
    }
    if (neo5m && s.address != "PUBX" && s.talker() != "GP") {
      rep.findings.push_back({true, "talker", s.address + ": a u-blox 5 uses the GP talker",
                              static_cast<std::int64_t>(f.offset)});
    }
    if (type == "TXT") continue;  // banner lines sit between epochs
    const int tf = TimeField(type);
    std::optional<double> tod;
    if (tf >= 0 && static_cast<std::size_t>(tf) < s.fields.size())
      tod = NmeaTimeOfDay(s.fields[static_cast<std::size_t>(tf)]);
    const bool new_epoch =
        epochs.empty() || pending_break ||
        (tod && epochs.back().tod_s && std::abs(*tod - *epochs.back().tod_s) > 1e-6);
    if (new_epoch) {
      if (!epochs.empty() && pending_break) epochs.back().before_break = true;
      epochs.push_back({});
      epochs.back().after_break = pending_break;
      epochs.back().t_first_ns = f.t_ns;
      pending_break = false;
    }
    Epoch& e = epochs.back();
    if (tod && !e.tod_s) e.tod_s = tod;
    e.frames.push_back(&f);
    e.bytes += f.length;
  }
  if (!epochs.empty()) epochs.back().before_break = true;
  if (lf_only > 0) {
    rep.findings.push_back(
        {false, "line_end",
         std::to_string(lf_only) + " sentence(s) end in LF only (CR LF expected)", -1});
  }
  return epochs;
}

// Epoch times: monotonic, the rate (and a NEO-5M's maximum), the gaps; the median period (0 when
// there are fewer than two timed epochs).
double CheckEpochTimes(std::vector<Epoch>& epochs, bool neo5m, ValidationReport& rep) {
  std::vector<double> dt;
  for (std::size_t i = 1; i < epochs.size(); ++i) {
    if (epochs[i].after_break || !epochs[i].tod_s || !epochs[i - 1].tod_s) continue;
    double d = *epochs[i].tod_s - *epochs[i - 1].tod_s;
    if (d < -43200) d += 86400;  // midnight
    if (d <= 0) {
      char msg[96];
      std::snprintf(msg, sizeof msg, "epoch time went backwards (%.2f s to %.2f s of day)",
                    *epochs[i - 1].tod_s, *epochs[i].tod_s);
      rep.findings.push_back(
          {true, "time_monotonic", msg, static_cast<std::int64_t>(epochs[i].frames[0]->offset)});
      continue;
    }
    dt.push_back(d);
  }
  rep.epochs = epochs.size();
  double period = 0;
  if (!dt.empty()) {
    period = Percentile(dt, 50);
    rep.epoch_rate_hz = 1.0 / period;
    std::size_t gaps = 0;
    for (std::size_t i = 1; i < epochs.size(); ++i) {
      if (epochs[i].after_break || !epochs[i].tod_s || !epochs[i - 1].tod_s) continue;
      const double d = *epochs[i].tod_s - *epochs[i - 1].tod_s;
      if (d > 1.5 * period) {
        ++gaps;
        epochs[i - 1].before_break = epochs[i].after_break = true;
        char msg[96];
        std::snprintf(msg, sizeof msg, "sequence gap: %.0f epoch(s) missing before %.2f s of day",
                      std::round(d / period) - 1, *epochs[i].tod_s);
        rep.findings.push_back(
            {false, "sequence_gap", msg, static_cast<std::int64_t>(epochs[i].frames[0]->offset)});
      }
    }
    double span = 0;
    for (const double d : dt) span += d;
    for (auto& [name, st] : rep.messages)
      st.rate_hz = static_cast<double>(st.count) / (span + period);
  }
  if (neo5m && rep.epoch_rate_hz && *rep.epoch_rate_hz > kNeo5mMaxRateHz + 1e-6) {
    char msg[96];
    std::snprintf(msg, sizeof msg, "epoch rate %.2f Hz above the u-blox 5 maximum of %.0f Hz",
                  *rep.epoch_rate_hz, kNeo5mMaxRateHz);
    rep.findings.push_back({true, "rate", msg, -1});
  }
  return period;
}

// GSV numbering within an epoch (an incomplete epoch may start inside a set).
void CheckGsvSequence(const Epoch& e, bool complete, std::int64_t offset, ValidationReport& rep) {
  int gsv_total = -1, gsv_next = 1;
  for (const Frame* f : e.frames) {
    const NmeaSentence& s = *f->nmea;
    if (s.type() != "GSV" || s.fields.size() < 3) continue;
    const int total = std::atoi(s.fields[0].c_str()), num = std::atoi(s.fields[1].c_str());
    if (gsv_total < 0) gsv_total = total;
    if ((total != gsv_total || num != gsv_next) && (complete || num != 1)) {
      rep.findings.push_back({complete, "gsv_sequence",
                              "GSV " + s.fields[1] + " of " + s.fields[0] +
                                  " out of sequence (expected " + std::to_string(gsv_next) +
                                  " of " + std::to_string(gsv_total) + ")",
                              static_cast<std::int64_t>(f->offset)});
    }
    gsv_total = total;
    gsv_next = num + 1;
  }
  if (complete && gsv_total > 0 && gsv_next != gsv_total + 1) {
    rep.findings.push_back({true, "gsv_sequence", "GSV set incomplete in an epoch", offset});
  }
}

// A u-blox 5 epoch: its sentences in order, none twice, none missing from a complete epoch.
void CheckNeo5mEpoch(const Epoch& e, bool complete, std::int64_t offset, ValidationReport& rep) {
  int last_rank = -1;
  std::string last_type;
  std::set<std::string> seen;
  for (const Frame* f : e.frames) {
    const std::string type = f->nmea->type();
    const int rank = Neo5mRank(type);
    if (rank < 0) continue;
    if (rank < last_rank) {
      rep.findings.push_back({true, "epoch_order",
                              type + " after " + last_type +
                                  ": a u-blox 5 sends RMC, VTG, GGA, GSA, GSV, GLL in that order",
                              static_cast<std::int64_t>(f->offset)});
    }
    if (type != "GSV" && seen.count(type)) {
      rep.findings.push_back({true, "epoch_duplicate", type + " twice in one epoch",
                              static_cast<std::int64_t>(f->offset)});
    }
    last_rank = std::max(last_rank, rank);
    last_type = type;
    seen.insert(type);
  }
  if (complete) {
    for (const char* need : {"RMC", "VTG", "GGA", "GSA", "GSV", "GLL"}) {
      if (!seen.count(need)) {
        rep.findings.push_back(
            {false, "epoch_incomplete", std::string(need) + " missing from an epoch", offset});
      }
    }
  }
}

void CheckNmea(const Framed& fr, bool neo5m, int baud, ValidationReport& rep) {
  std::vector<Epoch> epochs = GroupEpochs(fr, neo5m, rep);
  const double period = CheckEpochTimes(epochs, neo5m, rep);

  // per-epoch content (complete epochs only: not next to a break or the stream ends)
  std::vector<double> first_byte_offset_s;
  for (std::size_t k = 0; k < epochs.size(); ++k) {
    const Epoch& e = epochs[k];
    const bool complete = !e.after_break && !e.before_break;
    const auto offset = static_cast<std::int64_t>(e.frames.front()->offset);
    CheckGsvSequence(e, complete, offset, rep);
    if (!neo5m) continue;
    CheckNeo5mEpoch(e, complete, offset, rep);
    if (baud > 0 && period > 0 && static_cast<double>(e.bytes) * 10.0 / baud > period) {
      char msg[128];
      std::snprintf(msg, sizeof msg,
                    "epoch of %zu bytes needs %.2f s at %d baud, longer than the %.2f s epoch",
                    e.bytes, static_cast<double>(e.bytes) * 10.0 / baud, baud, period);
      rep.findings.push_back({false, "line_budget", msg, offset});
    }
    if (e.t_first_ns >= 0 && e.tod_s && period > 0) {
      const double t = static_cast<double>(e.t_first_ns) * 1e-9;
      double o = std::fmod(t - *e.tod_s, period);
      if (o < 0) o += period;
      first_byte_offset_s.push_back(o);
    }
  }
  if (!first_byte_offset_s.empty()) {
    const double med = Percentile(first_byte_offset_s, 50);
    std::vector<double> dev;
    for (const double o : first_byte_offset_s) dev.push_back(std::abs(o - med));
    rep.epoch_first_byte_offset_p50_ms = med * 1e3;
    rep.epoch_first_byte_jitter_ms = Percentile(dev, 100) * 1e3;
  }
}

// ---------------------------------------------------------------- UBX
struct UbxSpec {
  std::uint8_t cls, id;
  const char* name;
  int fixed_len;           // -1: variable
  int base = 0, step = 0;  // variable: base + k·step
  bool has_itow = false;
  bool on_ublox5 = true;
};

const std::vector<UbxSpec>& UbxTable() {
  static const std::vector<UbxSpec> t{
      {0x01, 0x01, "NAV-POSECEF", 20, 0, 0, true},
      {0x01, 0x02, "NAV-POSLLH", 28, 0, 0, true},
      {0x01, 0x03, "NAV-STATUS", 16, 0, 0, true},
      {0x01, 0x04, "NAV-DOP", 18, 0, 0, true},
      {0x01, 0x06, "NAV-SOL", 52, 0, 0, true},
      {0x01, 0x11, "NAV-VELECEF", 20, 0, 0, true},
      {0x01, 0x12, "NAV-VELNED", 36, 0, 0, true},
      {0x01, 0x20, "NAV-TIMEGPS", 16, 0, 0, true},
      {0x01, 0x21, "NAV-TIMEUTC", 20, 0, 0, true},
      {0x01, 0x22, "NAV-CLOCK", 20, 0, 0, true},
      {0x01, 0x30, "NAV-SVINFO", -1, 8, 12, true},
      {0x01, 0x31, "NAV-DGPS", -1, 16, 12, true},
      {0x01, 0x32, "NAV-SBAS", -1, 12, 12, true},
      {0x01, 0x60, "NAV-AOPSTATUS", 20, 0, 0, true},
      {0x01, 0x07, "NAV-PVT", 92, 0, 0, true, false},
      {0x01, 0x35, "NAV-SAT", -1, 8, 12, true, false},
      {0x01, 0x14, "NAV-HPPOSLLH", 36, 0, 0, true, false},
      {0x01, 0x61, "NAV-EOE", 4, 0, 0, true, false},
      {0x01, 0x43, "NAV-SIG", -1, 8, 16, true, false},
      {0x02, 0x10, "RXM-RAW", -1, 8, 24},
      {0x02, 0x11, "RXM-SFRB", 42},
      {0x02, 0x20, "RXM-SVSI", -1, 8, 6},
      {0x02, 0x41, "RXM-PMREQ", 8},
      {0x04, 0x00, "INF-ERROR", -1, 0, 1},
      {0x04, 0x01, "INF-WARNING", -1, 0, 1},
      {0x04, 0x02, "INF-NOTICE", -1, 0, 1},
      {0x04, 0x03, "INF-TEST", -1, 0, 1},
      {0x04, 0x04, "INF-DEBUG", -1, 0, 1},
      {0x05, 0x01, "ACK-ACK", 2},
      {0x05, 0x00, "ACK-NAK", 2},
      {0x0A, 0x04, "MON-VER", -1, 40, 30},
      {0x0A, 0x09, "MON-HW", -1, 60, 8},
      {0x0A, 0x02, "MON-IO", -1, 0, 20},
      {0x0A, 0x06, "MON-MSGPP", 120},
      {0x0A, 0x07, "MON-RXBUF", 24},
      {0x0A, 0x08, "MON-TXBUF", 28},
      {0x0A, 0x0B, "MON-HW2", 28},
      {0x0A, 0x38, "MON-RF", -1, 4, 24, false, false},
      {0x0D, 0x01, "TIM-TP", 16},
      {0x0D, 0x03, "TIM-TM2", 28},
      {0x0D, 0x04, "TIM-SVIN", 28},
  };
  return t;
}

void CheckUbx(const Framed& fr, bool neo5m, ValidationReport& rep) {
  std::vector<std::uint32_t> itows;  // distinct epochs in stream order
  for (const Frame& f : fr.frames) {
    if (f.kind != Frame::Kind::kUbx) continue;
    const UbxSpec* spec = nullptr;
    for (const auto& s : UbxTable()) {
      if (s.cls == f.cls && s.id == f.id) spec = &s;
    }
    char name[32];
    if (spec)
      std::snprintf(name, sizeof name, "UBX-%s", spec->name);
    else
      std::snprintf(name, sizeof name, "UBX-0x%02X-0x%02X", f.cls, f.id);
    rep.messages[name].count++;
    const auto off = static_cast<std::int64_t>(f.offset);
    if (f.cls == 0x06) continue;  // CFG: input or poll answers of many lengths
    if (!spec) {
      rep.findings.push_back(
          {neo5m, "message_set", std::string(name) + " is not a known UBX message", off});
      continue;
    }
    if (neo5m && !spec->on_ublox5) {
      rep.findings.push_back(
          {true, "message_set", std::string(name) + " does not exist on u-blox 5", off});
    }
    const int len = static_cast<int>(f.payload.size());
    const bool len_ok =
        spec->fixed_len >= 0
            ? len == spec->fixed_len
            : len >= spec->base && (spec->step == 0 || (len - spec->base) % spec->step == 0);
    if (!len_ok) {
      rep.findings.push_back({true, "payload_length",
                              std::string(name) + " payload of " + std::to_string(len) + " bytes",
                              off});
      continue;
    }
    if (spec->has_itow && len >= 4) {
      const std::uint32_t itow = LeRead<std::uint32_t>(f.payload, 0);
      if (itows.empty() || itows.back() != itow) {
        if (!itows.empty() && itow < itows.back() && itows.back() - itow < 302400000u) {
          rep.findings.push_back({true, "time_monotonic",
                                  "iTOW went backwards (" + std::to_string(itows.back()) + " to " +
                                      std::to_string(itow) + " ms)",
                                  off});
        }
        itows.push_back(itow);
      }
    }
  }
  if (itows.size() < 2) {
    rep.epochs = std::max(rep.epochs, itows.size());
    return;
  }
  std::vector<double> dt;
  for (std::size_t i = 1; i < itows.size(); ++i) {
    if (itows[i] > itows[i - 1]) dt.push_back((itows[i] - itows[i - 1]) * 1e-3);
  }
  rep.epochs = std::max(rep.epochs, itows.size());
  if (dt.empty()) return;
  const double period = Percentile(dt, 50);
  if (!rep.epoch_rate_hz) rep.epoch_rate_hz = 1.0 / period;
  double span = 0;
  for (const double d : dt) {
    span += d;
    if (d > 1.5 * period) {
      char msg[96];
      std::snprintf(msg, sizeof msg, "sequence gap: %.0f UBX epoch(s) missing",
                    std::round(d / period) - 1);
      rep.findings.push_back({false, "sequence_gap", msg, -1});
    }
  }
  for (auto& [name, st] : rep.messages) {
    if (name.rfind("UBX-", 0) == 0) st.rate_hz = static_cast<double>(st.count) / (span + period);
  }
  if (neo5m && 1.0 / period > kNeo5mMaxRateHz + 1e-6) {
    rep.findings.push_back({true, "rate", "UBX epoch rate above the u-blox 5 maximum", -1});
  }
}

}  // namespace

std::size_t ValidationReport::errors() const {
  std::size_t n = 0;
  for (const auto& f : findings) n += f.error ? 1 : 0;
  return n;
}

ValidationReport ValidateStream(ValidateProtocol protocol, const ByteStream& stream, int baud) {
  ValidationReport rep;
  rep.protocol = protocol == ValidateProtocol::kNmea  ? "nmea"
                 : protocol == ValidateProtocol::kUbx ? "ubx"
                                                      : "neo5m";
  rep.description = stream.description;
  rep.bytes = stream.bytes.size();
  const bool want_nmea = protocol != ValidateProtocol::kUbx,
             want_ubx = protocol != ValidateProtocol::kNmea;
  const Framed fr = FrameStream(stream, want_nmea, want_ubx, rep);
  for (const auto& f : fr.frames) rep.frames += f.kind == Frame::Kind::kComment ? 0 : 1;
  rep.bad_frames = fr.bad;
  rep.garbage_bytes = fr.garbage;
  const bool neo5m = protocol == ValidateProtocol::kNeo5m;
  if (want_nmea) CheckNmea(fr, neo5m, neo5m ? baud : 0, rep);
  if (want_ubx) CheckUbx(fr, neo5m, rep);
  CheckLineRate(stream, rep);
  if (rep.frames == 0) rep.findings.push_back({true, "empty", "no valid frame in the stream", -1});
  return rep;
}

}  // namespace hil::harness

// hil validate --protocol can: candump -l logs, NMEA 2000 fast-packet continuity.
#include <cctype>
#include <cmath>
#include <cstdio>
#include <map>
#include <set>
#include <sstream>

#include "hil/harness/eval/evaluator.h"
#include "hil/harness/validate/validate.h"

namespace hil::harness {
namespace {

bool AllHex(const std::string& s) {
  for (char c : s) {
    if (!std::isxdigit(static_cast<unsigned char>(c))) return false;
  }
  return true;
}

std::uint32_t PgnOf(std::uint32_t id) {
  const std::uint32_t dp = (id >> 24) & 0x3, pf = (id >> 16) & 0xFF, ps = (id >> 8) & 0xFF;
  return pf < 240 ? (dp << 16) | (pf << 8) : (dp << 16) | (pf << 8) | ps;
}

// NMEA 2000 PGNs sent as fast packets (the ones a navigation stack emits or reads)
const std::set<std::uint32_t> kFastPacketPgns{126464, 126996, 127233, 127237, 127489,
                                              128275, 129029, 129038, 129039, 129284,
                                              129285, 129540, 129542, 129794};

struct FastPacketState {
  int seq = -1;
  int next_frame = 0;
  int frames_left = 0;
};

// NMEA 2000 fast-packet continuity of one frame of a fast-packet PGN; true when it starts a
// packet (frame 0).
bool CheckFastPacket(std::uint32_t id, const std::string& data, std::int64_t line_no,
                     std::map<std::pair<std::uint32_t, std::uint32_t>, FastPacketState>& fast,
                     ValidationReport& rep) {
  const std::uint32_t pgn = PgnOf(id);
  const int b0 = std::stoi(data.substr(0, 2), nullptr, 16);
  const int seq = b0 >> 5, frame_no = b0 & 0x1F;
  FastPacketState& st = fast[{id & 0xFF, pgn}];
  if (frame_no == 0) {
    if (st.frames_left > 0) {
      rep.findings.push_back(
          {true, "fast_packet",
           "PGN " + std::to_string(pgn) + ": new packet before the previous one ended", line_no});
    }
    const int len = std::stoi(data.substr(2, 2), nullptr, 16);
    st.seq = seq;
    st.next_frame = 1;
    st.frames_left = len <= 6 ? 0 : (len - 6 + 6) / 7;
    return true;
  }
  if (st.frames_left == 0 || seq != st.seq || frame_no != st.next_frame) {
    rep.findings.push_back({true, "fast_packet",
                            "PGN " + std::to_string(pgn) + ": frame " + std::to_string(frame_no) +
                                " of sequence " + std::to_string(seq) + " out of order",
                            line_no});
    st.frames_left = 0;
  } else {
    ++st.next_frame;
    --st.frames_left;
  }
  return false;
}

// The rate of each identifier and its gaps longer than 2.5 median periods (fast packets are
// timed by their first frames).
void CheckRates(const std::map<std::string, std::vector<double>>& times, ValidationReport& rep) {
  for (const auto& [id, ts] : times) {
    if (ts.size() < 2) continue;
    const double span = ts.back() - ts.front();
    std::vector<double> dt;
    for (std::size_t i = 1; i < ts.size(); ++i) dt.push_back(ts[i] - ts[i - 1]);
    const double med = Percentile(dt, 50);
    if (span > 0) rep.messages[id].rate_hz = static_cast<double>(ts.size() - 1) / span;
    std::size_t gaps = 0;
    for (const double d : dt) gaps += med > 0 && d > 2.5 * med ? 1 : 0;
    if (gaps > 0)
      rep.findings.push_back({false, "sequence_gap",
                              id + ": " + std::to_string(gaps) + " gap(s) longer than 2.5 periods",
                              -1});
  }
}

}  // namespace

ValidationReport ValidateCanLog(const std::string& text) {
  ValidationReport rep;
  rep.protocol = "can";
  rep.description = "candump -l log";
  rep.bytes = text.size();
  std::istringstream in(text);
  std::string line;
  std::int64_t line_no = 0;
  double last_t = -1;
  std::map<std::string, std::vector<double>> times;                         // per identifier
  std::map<std::pair<std::uint32_t, std::uint32_t>, FastPacketState> fast;  // (source, pgn)
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.empty()) continue;
    std::istringstream ls(line);
    std::string ts, iface, frame;
    if (!(ls >> ts >> iface >> frame) || ts.size() < 4 || ts.front() != '(' || ts.back() != ')') {
      rep.findings.push_back(
          {true, "format", "not a candump -l line: '" + line.substr(0, 40) + "'", line_no});
      ++rep.bad_frames;
      continue;
    }
    const std::string tnum = ts.substr(1, ts.size() - 2);
    const std::size_t dot = tnum.find('.');
    if (dot == std::string::npos || tnum.size() - dot - 1 != 6) {
      rep.findings.push_back({true, "format", "timestamp must be (seconds.microseconds)", line_no});
      ++rep.bad_frames;
      continue;
    }
    const double t = std::atof(tnum.c_str());
    const std::size_t hash = frame.find('#');
    if (hash == std::string::npos) {
      rep.findings.push_back({true, "format", "frame without '#': " + frame, line_no});
      ++rep.bad_frames;
      continue;
    }
    const std::string id_hex = frame.substr(0, hash);
    std::string data = frame.substr(hash + 1);
    const bool fd = !data.empty() && data[0] == '#';
    if (fd) data = data.size() >= 2 ? data.substr(2) : "";  // "##<flags><data>"
    if ((id_hex.size() != 3 && id_hex.size() != 8) || !AllHex(id_hex)) {
      rep.findings.push_back(
          {true, "identifier",
           "identifier '" + id_hex + "' must be 3 (standard) or 8 (extended) hex digits", line_no});
      ++rep.bad_frames;
      continue;
    }
    const auto id = static_cast<std::uint32_t>(std::stoul(id_hex, nullptr, 16));
    if ((id_hex.size() == 3 && id > 0x7FF) || id > 0x1FFFFFFF) {
      rep.findings.push_back(
          {true, "identifier", "identifier " + id_hex + " out of range", line_no});
      ++rep.bad_frames;
      continue;
    }
    const bool remote = data == "R" || (data.size() == 2 && data[0] == 'R');
    if (!remote && (data.size() % 2 != 0 || !AllHex(data) || data.size() > (fd ? 128u : 16u))) {
      rep.findings.push_back(
          {true, "data", "data '" + data + "' is not whole bytes of hex within the frame length",
           line_no});
      ++rep.bad_frames;
      continue;
    }
    ++rep.frames;
    if (last_t >= 0 && t < last_t) {
      rep.findings.push_back({true, "time_monotonic", "timestamp went backwards", line_no});
    }
    last_t = std::max(last_t, t);
    rep.messages[id_hex].count++;
    // a fast packet's frames leave back to back: its period is that of its first frames
    const bool fast_packet =
        id_hex.size() == 8 && !remote && data.size() >= 4 && kFastPacketPgns.count(PgnOf(id));
    if (!fast_packet || CheckFastPacket(id, data, line_no, fast, rep)) times[id_hex].push_back(t);
  }
  CheckRates(times, rep);
  rep.epochs = 0;
  if (rep.frames == 0) rep.findings.push_back({true, "empty", "no valid frame in the log", -1});
  return rep;
}

}  // namespace hil::harness

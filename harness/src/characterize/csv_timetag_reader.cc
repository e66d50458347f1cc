// IMU CSV lines timed by their sensor tick and put on GPST by an RTKLIB TIMETAG file (layout in
// imu_log_readers.h).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "hil/harness/characterize/imu_log_readers.h"
#include "hil/harness/datasets/import_fields.h"
#include "hil/harness/datasets/rtklib_timetag.h"

#include "log_fields.h"

namespace hil::harness {
namespace {

constexpr const char* kCsvFields[] = {"ax", "ay", "az", "gx", "gy", "gz", "tick"};

std::string ReadAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error(path + ": cannot open");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct TagRecord {
  double t_s;          // GPST (time_t form) of the write
  std::uint64_t fpos;  // file position after the write
};

// the tag's records read with `fpos_bytes`-byte positions (the datasets' reader), or empty when
// that layout does not fit or the positions pass the end of the data file
std::vector<TagRecord> TagRecords(const std::string& tag_path, int fpos_bytes,
                                  std::size_t data_size) {
  RtklibTimeTag tag;
  try {
    tag = ReadRtklibTimeTag(tag_path, fpos_bytes);
  } catch (const ImportInputError& e) {
    const std::string what = e.what();
    // the header's problems are the same in both layouts: say them at once
    if (what.find("header") != std::string::npos || what.find("cannot open") != std::string::npos)
      throw std::runtime_error(what);
    return {};
  }
  std::vector<TagRecord> out;
  for (const RtklibTimeTagRecord& r : tag.records) {
    if (r.file_pos > data_size) return {};
    out.push_back({tag.open_gpst_s + r.tick_ms * 1e-3, r.file_pos});
  }
  return out;
}

std::vector<TagRecord> ReadTag(const std::string& tag_path, std::size_t data_size) {
  std::vector<TagRecord> r = TagRecords(tag_path, 4, data_size);
  if (r.empty()) r = TagRecords(tag_path, 8, data_size);
  if (r.empty())
    throw std::runtime_error(tag_path +
                             ": records: neither 8- nor 12-byte records with file "
                             "positions that grow and stay within the data file");
  return r;
}

struct CsvSample {
  double v[7];
  std::size_t end;  // file position after the line
  std::size_t line;
};

// the line's seven fields, or false for a fragment (wrong field count or an unparsable field)
bool ParseCsvLine(std::string_view text, const std::string& where, double (&v)[7]) {
  std::size_t count = 0, b = 0;
  for (std::size_t i = 0; i <= text.size(); ++i) {
    if (i < text.size() && text[i] != ',') continue;
    if (count == 7) return false;
    std::string_view f = text.substr(b, i - b);
    while (!f.empty() && (f.back() == '\r' || f.back() == ' ')) f.remove_suffix(1);
    v[count] = ParseFiniteField(f, where, kCsvFields[count]);
    ++count;
    b = i + 1;
  }
  return count == 7;
}

std::vector<CsvSample> ReadCsv(const std::string& path, const std::string& data,
                               std::vector<std::string>& notes) {
  std::vector<CsvSample> out;
  std::size_t at = 0;
  for (std::size_t n = 1; at < data.size(); ++n) {
    const std::size_t nl = data.find('\n', at);
    const bool terminated = nl != std::string::npos;
    const std::size_t end = terminated ? nl + 1 : data.size();
    const std::string_view text(data.data() + at, (terminated ? nl : data.size()) - at);
    const std::string where = path + ":" + std::to_string(n);
    CsvSample s{{}, end, n};
    bool ok = false;
    try {
      ok = ParseCsvLine(text, where, s.v);
    } catch (const std::runtime_error&) {
      if (n != 1 && terminated) throw;
    }
    if (!ok && (n == 1 || !terminated)) {
      notes.push_back(where + ": " + (n == 1 ? "first" : "unterminated last") +
                      " line is a fragment, skipped");
    } else if (!ok) {
      throw std::runtime_error(where +
                               ": expected 7 comma-separated fields (ax,ay,az [g], "
                               "gx,gy,gz [deg/s], tick [ms])");
    } else {
      if (s.v[6] < 0 || s.v[6] != std::floor(s.v[6]))
        throw std::runtime_error(where + ": field tick: not a whole number of milliseconds");
      if (!out.empty() && !(s.v[6] > out.back().v[6]))
        throw std::runtime_error(where + ": field tick: does not increase");
      out.push_back(s);
    }
    at = end;
  }
  return out;
}

double Median(std::vector<double> v) {
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

ImuSeries ReadCsvTimetag(const std::string& csv_path, const std::string& tag_path) {
  const std::string data = ReadAll(csv_path);
  // a log written with CRLF line ends and copied with LF ones: the tag's positions count one more
  // byte per line than the file now holds
  const bool lf_only = data.find('\r') == std::string::npos;
  const auto newlines = static_cast<std::size_t>(std::count(data.begin(), data.end(), '\n'));
  const std::vector<TagRecord> tag = ReadTag(tag_path, data.size() + (lf_only ? newlines : 0));
  const bool crlf = lf_only && tag.back().fpos > data.size();
  ImuSeries s;
  s.format = "csv-timetag";
  std::vector<CsvSample> rows = ReadCsv(csv_path, data, s.notes);
  if (crlf) {
    for (CsvSample& r : rows) r.end += r.line;  // every line up to this one lost its CR
    s.notes.push_back(tag_path + ": file positions count CRLF line ends; " + csv_path +
                      " has LF ones (the tag's last position is " +
                      std::to_string(tag.back().fpos) + ", the file holds " +
                      std::to_string(data.size()) + " bytes in " + std::to_string(newlines) +
                      " lines)");
  }
  if (rows.size() < 3) throw std::runtime_error(csv_path + ": fewer than 3 IMU lines");
  // each line: the first write whose file position holds its end
  std::vector<double> offsets;
  for (const CsvSample& r : rows) {
    const auto it = std::lower_bound(tag.begin(), tag.end(), r.end,
                                     [](const TagRecord& t, std::size_t e) { return t.fpos < e; });
    if (it != tag.end()) offsets.push_back(it->t_s - r.v[6] * 1e-3);
  }
  if (offsets.empty())
    throw std::runtime_error(tag_path + ": records: no write covers any line of " + csv_path);
  const double offset = Median(offsets);
  std::vector<double> lag(offsets.size());
  for (std::size_t k = 0; k < lag.size(); ++k) lag[k] = offsets[k] - offset;
  std::sort(lag.begin(), lag.end());
  constexpr double kDeg = std::numbers::pi / 180.0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const double* v = rows[k].v;
    s.t_s.push_back(v[6] * 1e-3 + offset);
    if (k + 1 == rows.size()) break;  // the last sample has no interval to hold
    s.accel_mps2.emplace_back(v[0] * kCsvG_mps2, v[1] * kCsvG_mps2, v[2] * kCsvG_mps2);
    s.gyro_radps.emplace_back(v[3] * kDeg, v[4] * kDeg, v[5] * kDeg);
  }
  char note[200];
  std::snprintf(note, sizeof note,
                "IMU CSV + TIMETAG: sensor tick + %.3f s = GPST (median over %zu lines; write "
                "time minus tick spans %.3f..%.3f s about it, 5th..95th percentile); sensor axes",
                offset, offsets.size(), lag[lag.size() / 20], lag[lag.size() * 19 / 20]);
  s.notes.push_back(note);
  return s;
}

}  // namespace hil::harness

#include "hil/harness/datasets/rtklib_timetag.h"

#include <algorithm>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "hil/firmware_emu/little_endian.h"
#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {
namespace {

constexpr std::size_t kTagHeaderBytes = 64, kTagTimeBytes = 4 + 8;

double TagLeDouble(const unsigned char* p) {
  const std::uint64_t bits = LeRead<std::uint64_t>(p);
  double d = 0;
  std::memcpy(&d, &bits, sizeof d);
  return d;
}

}  // namespace

RtklibTimeTag ReadRtklibTimeTag(const std::string& path, int fpos_bytes) {
  if (fpos_bytes != 4 && fpos_bytes != 8)
    throw ImportInputError(path, 0, "file position size", "must be 4 or 8 bytes");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  const std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
  if (b.size() < kTagHeaderBytes + kTagTimeBytes)
    throw ImportInputError(path, 0, "header", "shorter than RTKLIB's 76-byte time-tag header");
  RtklibTimeTag t;
  t.header.assign(b.begin(), b.begin() + kTagHeaderBytes - 4);
  t.header.resize(std::strlen(t.header.c_str()));
  if (t.header.rfind("TIMETAG RTKLIB", 0) != 0)
    throw ImportInputError(path, 0, "header", "does not start with 'TIMETAG RTKLIB'");
  t.open_tick_ms = LeRead<std::uint32_t>(&b[kTagHeaderBytes - 4]);
  const double frac = TagLeDouble(&b[kTagHeaderBytes + 4]);
  if (!(frac >= 0 && frac < 1))
    throw ImportInputError(path, 0, "opening time", "fraction of second outside [0, 1)");
  t.open_gpst_s = LeRead<std::uint32_t>(&b[kTagHeaderBytes]) + frac;
  const std::size_t rec = 4 + static_cast<std::size_t>(fpos_bytes);
  const std::size_t body = b.size() - kTagHeaderBytes - kTagTimeBytes;
  if (body % rec != 0)
    throw ImportInputError(path, static_cast<long>(body / rec) + 1, "record",
                           "partial record (" + std::to_string(body % rec) + " bytes) at the end");
  for (std::size_t i = 0; i < body / rec; ++i) {
    const unsigned char* p = &b[kTagHeaderBytes + kTagTimeBytes + i * rec];
    RtklibTimeTagRecord r;
    r.tick_ms = LeRead<std::uint32_t>(p);
    r.file_pos = fpos_bytes == 4 ? LeRead<std::uint32_t>(p + 4) : LeRead<std::uint64_t>(p + 4);
    if (!t.records.empty() && r.tick_ms < t.records.back().tick_ms)
      throw ImportInputError(path, static_cast<long>(i) + 1, "tick", "goes backwards");
    if (!t.records.empty() && r.file_pos < t.records.back().file_pos)
      throw ImportInputError(path, static_cast<long>(i) + 1, "file position", "goes backwards");
    t.records.push_back(r);
  }
  if (t.records.empty()) throw ImportInputError(path, 0, "", "no records");
  return t;
}

double RtklibTimeTagTimeOf(const RtklibTimeTag& tag, std::uint64_t end_pos) {
  const auto it = std::lower_bound(
      tag.records.begin(), tag.records.end(), end_pos,
      [](const RtklibTimeTagRecord& r, std::uint64_t pos) { return r.file_pos < pos; });
  if (it == tag.records.end()) throw std::out_of_range("past the time tag's last record");
  return tag.open_gpst_s + it->tick_ms * 1e-3;
}

}  // namespace hil::harness

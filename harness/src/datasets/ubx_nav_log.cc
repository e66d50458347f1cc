#include "hil/harness/datasets/ubx_nav_log.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>

#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/little_endian.h"
#include "hil/harness/datasets/import_fields.h"

namespace hil::harness {
namespace {

void CheckUbxLength(std::size_t len, std::size_t need, const char* name, const std::string& path,
                    std::size_t offset) {
  if (len != need)
    throw ImportInputError(path, 0, name,
                           "payload of " + std::to_string(len) + " bytes at byte offset " +
                               std::to_string(offset) + " (expected " + std::to_string(need) + ")");
}

// NAV-PVT: u-blox 8 / M8 / F9 / X20 interface description, 92 bytes
void OnNavPvt(const unsigned char* p, UbxNavLog& log) {
  ++log.nav_pvt;
  const std::uint8_t fix_type = p[20], flags = p[21];
  if (!(flags & 1) || (fix_type != 3 && fix_type != 4)) {
    ++log.not_fixed;
    return;
  }
  UbxNavFix f;
  f.sow = LeRead<std::uint32_t>(p) * 1e-3;  // nano (p + 16) belongs to the UTC fields, not iTOW
  f.lon_deg = LeRead<std::int32_t>(p + 24) * 1e-7;
  f.lat_deg = LeRead<std::int32_t>(p + 28) * 1e-7;
  f.height_m = LeRead<std::int32_t>(p + 32) * 1e-3;
  f.height_msl_m = LeRead<std::int32_t>(p + 36) * 1e-3;
  const double h_acc = LeRead<std::uint32_t>(p + 40) * 1e-3,
               v_acc = LeRead<std::uint32_t>(p + 44) * 1e-3;
  f.std_ned_m = {h_acc / std::sqrt(2.0), h_acc / std::sqrt(2.0), v_acc};
  f.has_velocity = true;
  f.v_ned_mps = Eigen::Vector3d(LeRead<std::int32_t>(p + 48), LeRead<std::int32_t>(p + 52),
                                LeRead<std::int32_t>(p + 56)) *
                1e-3;
  f.v_std_ned_mps.setConstant(LeRead<std::uint32_t>(p + 68) * 1e-3);
  f.carrier_solution = (flags >> 6) & 3;
  log.fixes.push_back(f);
}

struct UbxPosVelParts {
  std::map<std::uint32_t, UbxNavFix> by_itow;
  std::map<std::uint32_t, bool> has_pos;
};

void OnPosLlh(const unsigned char* p, UbxPosVelParts& parts, UbxNavLog& log) {
  ++log.posllh;
  const std::uint32_t itow = LeRead<std::uint32_t>(p);
  UbxNavFix& f = parts.by_itow[itow];
  f.sow = itow * 1e-3;
  f.lon_deg = LeRead<std::int32_t>(p + 4) * 1e-7;
  f.lat_deg = LeRead<std::int32_t>(p + 8) * 1e-7;
  f.height_m = LeRead<std::int32_t>(p + 12) * 1e-3;
  f.height_msl_m = LeRead<std::int32_t>(p + 16) * 1e-3;
  const double h_acc = LeRead<std::uint32_t>(p + 20) * 1e-3,
               v_acc = LeRead<std::uint32_t>(p + 24) * 1e-3;
  f.std_ned_m = {h_acc / std::sqrt(2.0), h_acc / std::sqrt(2.0), v_acc};
  parts.has_pos[itow] = true;
}

void OnVelNed(const unsigned char* p, UbxPosVelParts& parts, UbxNavLog& log) {
  ++log.velned;
  UbxNavFix& f = parts.by_itow[LeRead<std::uint32_t>(p)];
  f.has_velocity = true;
  f.v_ned_mps = Eigen::Vector3d(LeRead<std::int32_t>(p + 4), LeRead<std::int32_t>(p + 8),
                                LeRead<std::int32_t>(p + 12)) *
                1e-2;
  f.v_std_ned_mps.setConstant(LeRead<std::uint32_t>(p + 28) * 1e-2);
}

}  // namespace

UbxNavLog ReadUbxNavLog(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ImportInputError(path, 0, "", "cannot open");
  const std::vector<unsigned char> b((std::istreambuf_iterator<char>(in)),
                                     std::istreambuf_iterator<char>());
  UbxNavLog log;
  UbxPosVelParts parts;
  std::size_t i = 0;
  while (i + 1 < b.size()) {
    if (b[i] != 0xB5 || b[i + 1] != 0x62) {
      ++i;
      continue;
    }
    const gnss::ubx::FrameAt u = gnss::ubx::ParseFrameAt(
        std::string_view(reinterpret_cast<const char*>(&b[i]), b.size() - i));
    if (u.status == gnss::ubx::FrameAtStatus::kBadChecksum) {
      ++log.bad_checksum;
      ++i;
      continue;
    }
    if (u.status != gnss::ubx::FrameAtStatus::kFrame) {  // cut (no limit below 0xFFFF is set)
      ++log.cut_frames;
      break;
    }
    ++log.frames;
    const std::size_t len = u.payload_length;
    const unsigned char* p = &b[i + 6];
    const int cls = u.cls, id = u.id;
    if (cls == 0x01 && id == 0x07) {
      CheckUbxLength(len, 92, "NAV-PVT", path, i);
      OnNavPvt(p, log);
    } else if (cls == 0x01 && id == 0x02) {
      CheckUbxLength(len, 28, "NAV-POSLLH", path, i);
      OnPosLlh(p, parts, log);
    } else if (cls == 0x01 && id == 0x12) {
      CheckUbxLength(len, 36, "NAV-VELNED", path, i);
      OnVelNed(p, parts, log);
    }
    i += 8 + len;
  }
  if (log.nav_pvt == 0)
    for (const auto& [itow, f] : parts.by_itow)
      if (parts.has_pos.count(itow)) log.fixes.push_back(f);
  std::stable_sort(log.fixes.begin(), log.fixes.end(),
                   [](const UbxNavFix& a, const UbxNavFix& c) { return a.sow < c.sow; });
  const auto same = [](const UbxNavFix& a, const UbxNavFix& c) { return a.sow == c.sow; };
  const auto last = std::unique(log.fixes.begin(), log.fixes.end(), same);
  log.duplicates = static_cast<std::uint64_t>(log.fixes.end() - last);
  log.fixes.erase(last, log.fixes.end());
  if (log.fixes.empty()) throw ImportInputError(path, 0, "", "no NAV-PVT or NAV-POSLLH fix");
  return log;
}

}  // namespace hil::harness

#include "hil/firmware_emu/uwb/linktrack_setting_frame0.h"

#include <cmath>

#include "hil/firmware_emu/little_endian.h"
#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"

namespace hil::linktrack {
namespace {

void PutInt24(std::string& b, std::size_t at, std::int32_t v) {
  const auto u = static_cast<std::uint32_t>(v) & 0xFFFFFFu;
  LePut(b, at, u, 3);
}

std::int32_t Millimetres(double v_m) {
  const double mm = std::round(v_m * 1000.0);
  if (!std::isfinite(mm)) return kSettingNotAvailable;
  return mm < -8388607.0 ? -8388607 : mm > 8388607.0 ? 8388607 : static_cast<std::int32_t>(mm);
}

}  // namespace

std::string EncodeSettingFrame0(const SettingFrame0& f) {
  using namespace setting_frame0;
  std::string b(kSettingFrame0Size, '\0');
  b[0] = static_cast<char>(kSettingFrame0Header);
  b[1] = static_cast<char>(kSettingFrame0Mark);
  b[kMix] = static_cast<char>(f.mix);
  b[kRole] = static_cast<char>(f.role);
  b[kId] = static_cast<char>(f.id);
  b[kGroup] = static_cast<char>(f.group);
  for (std::size_t slot = 0; slot < kSettingAnchorSlots; ++slot) {
    const std::size_t at = kSettingAnchorOffset + 9 * slot;
    for (int k = 0; k < 3; ++k) {
      const std::int32_t v =
          slot < f.p_anchor_m.size() ? Millimetres(f.p_anchor_m[slot][k]) : kSettingNotAvailable;
      PutInt24(b, at + 3 * static_cast<std::size_t>(k), v);
    }
  }
  b[kCheck] = static_cast<char>(NlinkSum8(b.data(), kCheck));
  return b;
}

std::string EncodeSettingReadRequest() {
  std::string b(kSettingFrame0Size, '\0');
  b[0] = static_cast<char>(kSettingFrame0Header);
  b[1] = static_cast<char>(kSettingFrame0Mark);
  b[setting_frame0::kMix] = static_cast<char>(setting_frame0::kMixReadRequest);
  b[setting_frame0::kCheck] = static_cast<char>(NlinkSum8(b.data(), setting_frame0::kCheck));
  return b;
}

bool IsSettingReadRequest(std::string_view frame) {
  if (frame.size() != kSettingFrame0Size) return false;
  const auto u = [&](std::size_t i) { return static_cast<unsigned char>(frame[i]); };
  return u(0) == kSettingFrame0Header && u(1) == kSettingFrame0Mark &&
         u(setting_frame0::kMix) == setting_frame0::kMixReadRequest &&
         u(setting_frame0::kCheck) == NlinkSum8(frame.data(), setting_frame0::kCheck);
}

}  // namespace hil::linktrack

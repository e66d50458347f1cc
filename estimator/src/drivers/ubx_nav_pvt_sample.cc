// A UBX NAV-PVT message as a GnssSample (ubx_nav_pvt_sample.h).
#include "hil/estimator/drivers/ubx_nav_pvt_sample.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <numbers>

namespace hil::estimator::drivers {
namespace {

constexpr std::uint8_t kValidDate = 0x01, kValidTime = 0x02;
constexpr std::int64_t kNsPerWeek = kSecondsPerGpsWeek * kNsPerSecond;

// GPS time of the message's iTOW, in the week its UTC date and time (+ leap seconds) fall in (the
// week either side when iTOW and the UTC time straddle a week boundary).
std::optional<GpsTime> NavPvtTime(const UbxMessage& m, int leap_s) {
  if ((m.utc_valid & (kValidDate | kValidTime)) != (kValidDate | kValidTime)) return std::nullopt;
  using namespace std::chrono;
  const year_month_day ymd{year{m.year}, month{static_cast<unsigned>(m.month)},
                           day{static_cast<unsigned>(m.day)}};
  if (!ymd.ok()) return std::nullopt;
  const std::int64_t unix_s = sys_days{ymd}.time_since_epoch().count() * 86400LL + m.hour * 3600LL +
                              m.minute * 60LL + m.second;
  const std::int64_t utc_ns =
      ToNs(GpsTimeFromUnixNs(unix_s * kNsPerSecond + m.utc_nano_ns, leap_s));
  const std::int64_t week = utc_ns / kNsPerWeek;
  const std::int64_t tow_ns = static_cast<std::int64_t>(m.itow_ms) * 1'000'000LL;
  std::int64_t best = week;
  for (std::int64_t w = week - 1; w <= week + 1; ++w) {
    if (std::llabs(w * kNsPerWeek + tow_ns - utc_ns) <
        std::llabs(best * kNsPerWeek + tow_ns - utc_ns))
      best = w;
  }
  return GpsTimeFromWeek(best, tow_ns);
}

}  // namespace

int NavPvtFixQuality(const UbxMessage& m) {
  switch (PvtCarrSoln(m)) {
    case 2:
      return 4;
    case 1:
      return 5;
    default:
      return PvtDiffSoln(m) ? 2 : 1;
  }
}

std::optional<GnssSample> NavPvtToGnssSample(const UbxMessage& m, int leap_s,
                                             const UbxPvtAccuracy& acc) {
  const bool fix_type_ok = m.gps_fix == 2 || m.gps_fix == 3 || m.gps_fix == 4;
  if (m.cls != 0x01 || m.id != 0x07 || !PvtGnssFixOk(m) || !fix_type_ok || (m.flags3 & 0x01))
    return std::nullopt;
  const std::optional<GpsTime> t = NavPvtTime(m, leap_s);
  if (!t) return std::nullopt;
  GnssSample g;
  g.t = *t;
  g.position = {m.lat_deg, m.lon_deg, m.height_m};
  g.geoid_separation_m = m.height_m - m.h_msl_m;
  const double h = std::max(acc.scale * m.h_acc_m / std::numbers::sqrt2, acc.pos_floor_m);
  double up = std::max(acc.scale * m.v_acc_m, acc.pos_floor_m);
  if (NavPvtFixQuality(m) == 5)
    up = std::max(std::min(up, acc.float_up_max_std_m), acc.pos_floor_m);
  g.receiver_h_std_m = m.h_acc_m / std::numbers::sqrt2;
  g.fix_dim = m.gps_fix == 2 ? 2 : 3;
  g.pos_std_enu_m = {h, h, g.fix_dim == 2 ? UbxEpochAssembler::kHeldHeightStd_m : up};
  g.has_velocity = true;
  g.vel_enu_mps = {m.vel_e_mps, m.vel_n_mps, -m.vel_d_mps};
  const double s = std::max(acc.scale * m.s_acc_mps, acc.vel_floor_mps);
  g.vel_std_enu_mps = {s, s, s};
  g.ground_speed_mps = m.g_speed_mps;
  g.num_sv = m.num_sv;
  g.fix_quality = NavPvtFixQuality(m);
  return g;
}

}  // namespace hil::estimator::drivers

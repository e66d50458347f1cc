#include "hil/estimator/drivers/ubx_decoder.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "hil/estimator/geodesy.h"

namespace hil::estimator::drivers {
namespace {

std::uint8_t U1(const char* p) { return static_cast<std::uint8_t>(*p); }
std::uint16_t U2(const char* p) { return static_cast<std::uint16_t>(U1(p) | (U1(p + 1) << 8)); }
std::uint32_t U4(const char* p) {
  return static_cast<std::uint32_t>(U1(p)) | (static_cast<std::uint32_t>(U1(p + 1)) << 8) |
         (static_cast<std::uint32_t>(U1(p + 2)) << 16) |
         (static_cast<std::uint32_t>(U1(p + 3)) << 24);
}
std::int32_t I4(const char* p) { return static_cast<std::int32_t>(U4(p)); }

void Fletcher(const char* p, std::size_t n, std::uint8_t& a, std::uint8_t& b) {
  a = b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    a = static_cast<std::uint8_t>(a + U1(p + i));
    b = static_cast<std::uint8_t>(b + a);
  }
}

/// Decoder table: class, id, payload length, field decoder.
struct Entry {
  std::uint8_t cls, id;
  std::size_t len;
  void (*decode)(const char* p, UbxMessage& m);
};

constexpr Entry kTable[] = {
    {0x01, 0x02, 28,
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.lon_deg = I4(p + 4) * 1e-7;
       m.lat_deg = I4(p + 8) * 1e-7;
       m.height_m = I4(p + 12) * 1e-3;
       m.h_msl_m = I4(p + 16) * 1e-3;
       m.h_acc_m = U4(p + 20) * 1e-3;
       m.v_acc_m = U4(p + 24) * 1e-3;
     }},
    {0x01, 0x06, 52,
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.ftow_ns = I4(p + 4);
       m.week = static_cast<std::int16_t>(U2(p + 8));
       m.gps_fix = U1(p + 10);
       m.flags = U1(p + 11);
       for (int i = 0; i < 3; ++i) {
         m.p_E_m[i] = I4(p + 12 + 4 * i) * 0.01;
         m.v_E_mps[i] = I4(p + 28 + 4 * i) * 0.01;
       }
       m.p_acc_m = U4(p + 24) * 0.01;
       m.sol_s_acc_mps = U4(p + 40) * 0.01;
       m.pdop = U2(p + 44) * 0.01;
       m.num_sv = U1(p + 47);
     }},
    {0x01, 0x04, 18,
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.pdop = U2(p + 6) * 0.01;
       m.vdop = U2(p + 10) * 0.01;
       m.hdop = U2(p + 12) * 0.01;
     }},
    {0x01, 0x12, 36,
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.vel_n_mps = I4(p + 4) * 0.01;
       m.vel_e_mps = I4(p + 8) * 0.01;
       m.vel_d_mps = I4(p + 12) * 0.01;
       m.s_acc_mps = U4(p + 28) * 0.01;
     }},
    {0x01, 0x20, 16,
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.ftow_ns = I4(p + 4);
       m.week = static_cast<std::int16_t>(U2(p + 8));
       m.leap_s = static_cast<std::int8_t>(U1(p + 10));
       m.flags = U1(p + 11);
     }},
    {0x01, 0x07, 92,  // NAV-PVT (protocol 27+): offsets of the u-blox 9 interface description
     [](const char* p, UbxMessage& m) {
       m.itow_ms = U4(p);
       m.year = U2(p + 4), m.month = U1(p + 6), m.day = U1(p + 7);
       m.hour = U1(p + 8), m.minute = U1(p + 9), m.second = U1(p + 10);
       m.utc_valid = U1(p + 11);
       m.utc_nano_ns = I4(p + 16);
       m.gps_fix = U1(p + 20);
       m.flags = U1(p + 21);
       m.num_sv = U1(p + 23);
       m.lon_deg = I4(p + 24) * 1e-7;
       m.lat_deg = I4(p + 28) * 1e-7;
       m.height_m = I4(p + 32) * 1e-3;
       m.h_msl_m = I4(p + 36) * 1e-3;
       m.h_acc_m = U4(p + 40) * 1e-3;
       m.v_acc_m = U4(p + 44) * 1e-3;
       m.vel_n_mps = I4(p + 48) * 1e-3;
       m.vel_e_mps = I4(p + 52) * 1e-3;
       m.vel_d_mps = I4(p + 56) * 1e-3;
       m.g_speed_mps = I4(p + 60) * 1e-3;
       m.head_mot_deg = I4(p + 64) * 1e-5;
       m.s_acc_mps = U4(p + 68) * 1e-3;
       m.pdop = U2(p + 76) * 0.01;
       m.flags3 = U2(p + 78);
     }},
    {0x01, 0x21, 20, [](const char* p, UbxMessage& m) { m.itow_ms = U4(p); }},
    {0x05, 0x01, 2, [](const char* p, UbxMessage& m) { m.ack_cls = U1(p), m.ack_id = U1(p + 1); }},
    {0x05, 0x00, 2, [](const char* p, UbxMessage& m) { m.ack_cls = U1(p), m.ack_id = U1(p + 1); }},
};

}  // namespace

std::size_t UbxDecoder::Encode(std::uint8_t cls, std::uint8_t id, std::string_view payload,
                               char* out, std::size_t cap) {
  const std::size_t n = payload.size() + 8;
  if (n > cap || payload.size() > 0xFFFF) return 0;
  out[0] = static_cast<char>(0xB5);
  out[1] = 0x62;
  out[2] = static_cast<char>(cls);
  out[3] = static_cast<char>(id);
  out[4] = static_cast<char>(payload.size() & 0xFF);
  out[5] = static_cast<char>(payload.size() >> 8);
  std::memcpy(out + 6, payload.data(), payload.size());
  std::uint8_t a, b;
  Fletcher(out + 2, payload.size() + 4, a, b);
  out[n - 2] = static_cast<char>(a);
  out[n - 1] = static_cast<char>(b);
  return n;
}

void UbxDecoder::Feed(std::string_view bytes) {
  while (!bytes.empty()) {
    if (len_ == 0 && other_) {  // outside a frame: the run up to the next sync byte is not UBX
      const std::size_t run = std::min(bytes.find('\xB5'), bytes.size());
      if (run > 0) {
        other_(bytes.substr(0, run));
        bytes.remove_prefix(run);
        continue;
      }
    }
    buf_[len_++] = bytes.front();
    bytes.remove_prefix(1);
    Scan();
  }
}

void UbxDecoder::Skip(std::size_t n, bool garbage) {
  if (other_) {
    other_(std::string_view(buf_.data(), n));
  } else if (garbage) {
    stats_.garbage_bytes += n;
  }
  std::memmove(buf_.data(), buf_.data() + n, len_ - n);
  len_ -= n;
}

void UbxDecoder::Scan() {
  for (;;) {
    std::size_t i = 0;
    while (i < len_ && !(U1(&buf_[i]) == 0xB5 && (i + 1 == len_ || U1(&buf_[i + 1]) == 0x62))) ++i;
    if (i > 0) Skip(i);
    if (len_ < 6) return;
    const std::size_t n = U2(&buf_[4]);
    if (n > kMaxPayload) {
      ++stats_.overlong;
      Skip(1, false);
      continue;
    }
    if (len_ < n + 8) return;
    std::uint8_t a, b;
    Fletcher(&buf_[2], n + 4, a, b);
    if (a != U1(&buf_[n + 6]) || b != U1(&buf_[n + 7])) {
      ++stats_.bad_checksum;
      Skip(1, false);
      continue;
    }
    Dispatch(buf_.data(), n);
    std::memmove(buf_.data(), buf_.data() + n + 8, len_ - n - 8);
    len_ -= n + 8;
  }
}

void UbxDecoder::Dispatch(const char* f, std::size_t n) {
  ++stats_.frames_ok;
  UbxMessage m;
  m.cls = U1(f + 2);
  m.id = U1(f + 3);
  for (const Entry& e : kTable) {
    if (e.cls != m.cls || e.id != m.id) continue;
    if (n < e.len) {
      ++stats_.unsupported;
      return;
    }
    e.decode(f + 6, m);
    if (m.cls == 0x05) ++(m.id == 0x01 ? stats_.acks : stats_.naks);
    if (handler_) handler_(m);
    return;
  }
  ++stats_.unsupported;
}

UbxEpochs UbxEpochAssembler::Add(const UbxMessage& m) {
  UbxEpochs out;
  const auto keep = [&out](std::optional<GnssSample> g) {
    if (g) out.samples[out.count++] = *g;
  };
  if (m.cls != 0x01) return out;
  if (m.id == 0x20) {
    if (m.flags & 0x02) week_ = m.week;
    if (m.flags & 0x04) {
      leap_s_ = m.leap_s;
      leap_reported_ = true;
    }
    return out;
  }
  const std::uint8_t kind = m.id == 0x02 ? kPos : m.id == 0x12 ? kVel : m.id == 0x06 ? kSol : 0;
  if (kind == 0) return out;
  if (have_ != 0 && m.itow_ms != itow_) {
    expected_ |= have_;  // what this receiver sends per epoch, learned from the epochs it sent
    keep(Flush());
  }
  itow_ = m.itow_ms;
  have_ |= kind;
  if (kind == kPos) pos_ = m;
  if (kind == kVel) vel_ = m;
  if (kind == kSol) {
    sol_ = m;
    if (m.flags & 0x04) week_ = m.week;
  }
  if (Complete()) keep(Flush());
  return out;
}

bool UbxEpochAssembler::Complete() const {
  constexpr std::uint8_t kAll = kPos | kVel | kSol;
  if ((have_ & kAll) == kAll) return true;
  return expected_ != 0 && (have_ & expected_) == expected_;
}

void UbxEpochAssembler::FillPosition(GnssSample& g) const {
  if (have_ & kPos) {  // NAV-POSLLH: 1e-7 deg, mm
    g.position = {pos_.lat_deg, pos_.lon_deg, pos_.height_m};
    g.geoid_separation_m = pos_.height_m - pos_.h_msl_m;
    const double h = std::max(pos_.h_acc_m, 0.01) / std::sqrt(2.0);
    g.pos_std_enu_m = {h, h, std::max(pos_.v_acc_m, 0.01)};
    return;
  }
  // NAV-SOL: ECEF in cm with a 3-D accuracy, shared equally by the three axes
  g.position = LlaFromEcef(Eigen::Vector3d(sol_.p_E_m[0], sol_.p_E_m[1], sol_.p_E_m[2]));
  const double s = std::max(sol_.p_acc_m, 0.01) / std::sqrt(3.0);
  g.pos_std_enu_m = {s, s, s};
}

void UbxEpochAssembler::FillVelocity(GnssSample& g) const {
  if (have_ & kVel) {  // NAV-VELNED: NED in cm/s
    g.has_velocity = true;
    g.vel_enu_mps = {vel_.vel_e_mps, vel_.vel_n_mps, -vel_.vel_d_mps};
    const double s = std::max(vel_.s_acc_mps, 0.01);
    g.vel_std_enu_mps = {s, s, s};
  } else if (have_ & kSol) {  // NAV-SOL: ECEF in cm/s, rotated into ENU at the fix
    const LocalTangentFrame at_fix(g.position);
    const Eigen::Vector3d v_E(sol_.v_E_mps[0], sol_.v_E_mps[1], sol_.v_E_mps[2]);
    g.has_velocity = true;
    g.vel_enu_mps = at_fix.R_EN().transpose() * v_E;
    const double s = std::max(sol_.sol_s_acc_mps, 0.01);
    g.vel_std_enu_mps = {s, s, s};
  }
  if (g.has_velocity) g.ground_speed_mps = g.vel_enu_mps.head<2>().norm();
}

std::optional<GnssSample> UbxEpochAssembler::Flush() {
  std::optional<GnssSample> out;
  const bool have_sol = (have_ & kSol) != 0;
  const bool fix_ok =
      !have_sol || ((sol_.flags & 0x01) && (sol_.gps_fix == 2 || sol_.gps_fix == 3));
  if ((have_ & (kPos | kSol)) && week_ >= 0 && fix_ok) {
    GnssSample g;
    g.t = GpsTimeFromWeek(
        week_, static_cast<std::int64_t>(itow_) * 1'000'000LL + (have_sol ? sol_.ftow_ns : 0));
    FillPosition(g);
    FillVelocity(g);
    g.fix_dim = have_sol && sol_.gps_fix == 2 ? 2 : 3;
    if (g.fix_dim == 2) g.pos_std_enu_m.z() = kHeldHeightStd_m;
    g.num_sv = have_sol ? sol_.num_sv : 0;
    g.fix_quality = have_sol && (sol_.flags & 0x02) ? 2 : 1;
    out = g;
  }
  have_ = 0;
  return out;
}

}  // namespace hil::estimator::drivers

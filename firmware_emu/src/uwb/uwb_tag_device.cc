#include "hil/firmware_emu/uwb/uwb_tag_device.h"

#include <cmath>
#include <stdexcept>

#include <Eigen/LU>

#include "hil/firmware_emu/uwb/linktrack_setting_frame0.h"
#include "hil/firmware_emu/uwb/linktrack_tag_frame0.h"
#include "hil/firmware_emu/uwb/uwb_tdoa_frame.h"

namespace hil::uwb {
namespace {

double Range_m(const Eigen::Vector2d& p, double h_tag, const Eigen::Vector2d& a, double h_anchor) {
  const double dz = h_tag - h_anchor;
  return std::sqrt((p - a).squaredNorm() + dz * dz);
}

}  // namespace

UwbTagDevice::UwbTagDevice(const UwbTagConfig& config, std::uint64_t seed)
    : config_(config), errors_(config.errors, seed) {
  if (!(config_.rate_hz >= 1.0 && config_.rate_hz <= 50.0))
    throw std::invalid_argument("UWB: rate_hz must be within 1–50 Hz (paper 003)");
  const auto& a = config_.p_W_anchor_m;
  const Eigen::Vector2d e2 = a[1] - a[0], e3 = a[2] - a[0];
  if (std::fabs(e2.x() * e3.y() - e2.y() * e3.x()) < 1e-3)
    throw std::invalid_argument("UWB: BS1, BS2, BS3 are collinear");
  next_fix_ = Time{} + PeriodFromHz(config_.rate_hz);
}

// First-order response of a TDOA position to an extra range b on anchor j: the differences move
// by δd_i = b·([i = j] − [j = BS1]); δp = (GᵀG)⁻¹Gᵀ δd with G's rows ∂r_i1/∂p = u_i − u_1.
Eigen::Vector2d UwbTagDevice::NlosShift(const Eigen::Vector2d& p_W_m, const NlosState& nlos) const {
  if (nlos.anchor < 0) return Eigen::Vector2d::Zero();
  const auto& a = config_.p_W_anchor_m;
  std::array<Eigen::Vector2d, 4> u;
  for (std::size_t i = 0; i < 4; ++i) {
    const Eigen::Vector2d d = p_W_m - a[i];
    const double n = d.norm();
    u[i] = n > 1e-6 ? Eigen::Vector2d(d / n) : Eigen::Vector2d::Zero();
  }
  Eigen::Matrix<double, 3, 2> g;
  Eigen::Vector3d dd;
  for (std::size_t i = 1; i < 4; ++i) {
    g.row(static_cast<Eigen::Index>(i - 1)) = (u[i] - u[0]).transpose();
    const double own = static_cast<int>(i) == nlos.anchor ? 1.0 : 0.0;
    dd[static_cast<Eigen::Index>(i - 1)] = nlos.bias_m * (own - (nlos.anchor == 0 ? 1.0 : 0.0));
  }
  const Eigen::Matrix2d gtg = g.transpose() * g;
  if (std::fabs(gtg.determinant()) < 1e-9) return Eigen::Vector2d::Zero();
  return gtg.inverse() * (g.transpose() * dd);
}

void UwbTagDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const Time t = truth.t;
  fix_ = {};
  fix_.p_W_true_m = truth.p_NB_N_m.head<2>();
  const Eigen::Vector2d m = errors_.Measure(fix_.p_W_true_m);
  fix_.nlos = errors_.StepNlos(t, fix_.p_W_true_m, 4);
  fix_.p_W_measured_m = m + NlosShift(m, fix_.nlos);
  for (std::size_t i = 0; i < 4; ++i) {
    fix_.range_m[i] =
        Range_m(m, config_.tag_height_m, config_.p_W_anchor_m[i], config_.anchor_height_m) +
        (fix_.nlos.anchor == static_cast<int>(i) ? fix_.nlos.bias_m : 0.0);
  }
  for (std::size_t i = 0; i < 3; ++i) fix_.r_i1_m[i] = fix_.range_m[i + 1] - fix_.range_m[0];
  ++stats_.fixes;
  if (fix_.nlos.anchor >= 0) ++stats_.nlos_fixes;
  Emit(t, out);
  next_fix_ = t + PeriodFromHz(config_.rate_hz);
}

void UwbTagDevice::Emit(Time t, DeviceOutput& out) {
  const Time ready = t + config_.output_lag;
  const auto ms = static_cast<std::uint32_t>(ToNs(t) / 1000000);
  if (config_.output != UwbOutput::kTdoa) {
    linktrack::TagFrame0 f;
    f.id = config_.tag_id;
    f.p_m = {fix_.p_W_measured_m.x(), fix_.p_W_measured_m.y(), config_.tag_height_m};
    if (have_last_) {
      const Eigen::Vector2d v = (fix_.p_W_measured_m - last_p_m_) * config_.rate_hz;
      f.v_mps = {v.x(), v.y(), 0};
    }
    for (std::size_t i = 0; i < 4; ++i) f.dis_m[i] = fix_.range_m[i];
    f.local_time_ms = f.system_time_ms = ms;
    const Eigen::Vector2d& s = config_.errors.white_sigma_m;
    f.eop_m = {s.x(), s.y(), 0};
    f.voltage_v = config_.voltage_v;
    out.serial.push_back({ready, 0, linktrack::EncodeTagFrame0(f), "NLINK-TAG-FRAME0"});
  }
  if (config_.output != UwbOutput::kTagFrame0) {
    TdoaFrame f;
    f.id = config_.tag_id;
    f.system_time_ms = ms;
    for (std::size_t i = 0; i < 3; ++i) f.t_i1_ps[i] = TdoaPicoseconds(fix_.r_i1_m[i]);
    out.serial.push_back({ready, 0, EncodeTdoaFrame(f), "HIL-UWB-TDOA0"});
  }
  last_p_m_ = fix_.p_W_measured_m;
  have_last_ = true;
}

void UwbTagDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  (void)port;
  host_buf_.append(bytes);
  std::size_t i = 0;
  while (i < host_buf_.size()) {
    const auto u = [&](std::size_t k) { return static_cast<unsigned char>(host_buf_[i + k]); };
    const std::size_t n = host_buf_.size() - i;
    if (u(0) != linktrack::kSettingFrame0Header ||
        (n >= 2 && u(1) != linktrack::kSettingFrame0Mark)) {
      ++stats_.host_garbage_bytes;
      ++i;
      continue;
    }
    if (n < linktrack::kSettingFrame0Size) break;
    const std::string_view frame(host_buf_.data() + i, linktrack::kSettingFrame0Size);
    if (!linktrack::IsSettingReadRequest(frame)) {  // a bad sum or another setting: skip a byte
      ++stats_.host_garbage_bytes;
      ++i;
      continue;
    }
    linktrack::SettingFrame0 reply;
    reply.id = config_.tag_id;
    for (const Eigen::Vector2d& a : config_.p_W_anchor_m)
      reply.p_anchor_m.emplace_back(a.x(), a.y(), config_.anchor_height_m);
    out.serial.push_back({t + config_.reply_latency, 0, linktrack::EncodeSettingFrame0(reply),
                          "NLINK-SETTING-FRAME0"});
    ++stats_.setting_replies;
    i += linktrack::kSettingFrame0Size;
  }
  host_buf_.erase(0, i);
}

}  // namespace hil::uwb

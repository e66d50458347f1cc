#include "hil/truth/truth_integrator.h"

#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include <GeographicLib/NormalGravity.hpp>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace hil::truth {
namespace {

constexpr double kEarthRate_radps = 7.2921150e-5;
constexpr double kDeg = std::numbers::pi / 180.0;
enum StateIndex { kE = 0, kN = 1, kYaw = 2, kV = 3, kStateSize = 4 };

}  // namespace

struct TruthIntegrator::Impl {
  SUNContext ctx = nullptr;
  N_Vector y = nullptr;
  N_Vector dky = nullptr;
  void* cvode = nullptr;
  SUNNonlinearSolver nls = nullptr;
  const TruthConfig* config = nullptr;

  static int Rhs(sunrealtype /*t*/, N_Vector y, N_Vector ydot, void* user) {
    const auto* self = static_cast<const Impl*>(user);
    const double* s = N_VGetArrayPointer(y);
    double* d = N_VGetArrayPointer(ydot);
    const double L = self->config->wheelbase_m;
    d[kE] = s[kV] * std::cos(s[kYaw]);
    d[kN] = s[kV] * std::sin(s[kYaw]);
    d[kYaw] = s[kV] * std::tan(self->config->steer_deg * kDeg) / L;
    d[kV] = (self->config->speed_mps - s[kV]) / self->config->speed_lag_s;
    return 0;
  }

  void Check(int flag, const char* what) const {
    if (flag < 0) throw std::runtime_error(std::string("CVODE ") + what + " failed with flag " + std::to_string(flag));
  }

  void Init() {
    Free();
    Check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    y = N_VNew_Serial(kStateSize, ctx);
    dky = N_VNew_Serial(kStateSize, ctx);
    double* s = N_VGetArrayPointer(y);
    s[kE] = config->start_p_N_m.x();
    s[kN] = config->start_p_N_m.y();
    s[kYaw] = (90.0 - config->heading_deg) * kDeg;
    s[kV] = config->start_at_speed ? config->speed_mps : 0.0;
    cvode = CVodeCreate(CV_ADAMS, ctx);
    Check(CVodeInit(cvode, Rhs, 0.0, y), "CVodeInit");
    Check(CVodeSetUserData(cvode, this), "CVodeSetUserData");
    nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    Check(CVodeSetNonlinearSolver(cvode, nls), "CVodeSetNonlinearSolver");
    Check(CVodeSStolerances(cvode, config->rtol, config->atol_m), "CVodeSStolerances");
    Check(CVodeSetMaxStep(cvode, 0.5), "CVodeSetMaxStep");
    Check(CVodeSetMaxNumSteps(cvode, 100000), "CVodeSetMaxNumSteps");
  }

  void Free() {
    if (cvode) CVodeFree(&cvode);
    if (nls) SUNNonlinSolFree(nls);
    if (y) N_VDestroy(y);
    if (dky) N_VDestroy(dky);
    if (ctx) SUNContext_Free(&ctx);
    cvode = nullptr;
    nls = nullptr;
    y = dky = nullptr;
    ctx = nullptr;
  }
};

TruthIntegrator::TruthIntegrator(const TruthConfig& config)
    : config_(config), frame_(config.origin), impl_(std::make_unique<Impl>()) {
  impl_->config = &config_;
  impl_->Init();
}

TruthIntegrator::~TruthIntegrator() { impl_->Free(); }

long TruthIntegrator::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cvode, &n);
  return n;
}

TruthSample TruthIntegrator::Sample(Time t) {
  const double ts = ToSeconds(t);
  if (ts < 0) throw std::runtime_error("truth requested before t = 0");
  double t_cur = 0;
  CVodeGetCurrentTime(impl_->cvode, &t_cur);
  if (t_cur > 0) {
    // dense output is valid over the last step only: an earlier request restarts from t = 0
    double h_last = 0;
    CVodeGetLastStep(impl_->cvode, &h_last);
    if (ts < t_cur - h_last) {
      impl_->Init();
      t_cur = 0;
    }
  }
  while (t_cur < ts) {
    double t_ret = 0;
    impl_->Check(CVode(impl_->cvode, ts + 1.0, impl_->y, &t_ret, CV_ONE_STEP), "CVode");
    CVodeGetCurrentTime(impl_->cvode, &t_cur);
  }
  double s[kStateSize], d[kStateSize];
  if (t_cur == 0.0) {
    const double* y0 = N_VGetArrayPointer(impl_->y);
    for (int i = 0; i < kStateSize; ++i) s[i] = y0[i];
    Impl::Rhs(0.0, impl_->y, impl_->dky, impl_.get());
    for (int i = 0; i < kStateSize; ++i) d[i] = N_VGetArrayPointer(impl_->dky)[i];
  } else {
    impl_->Check(CVodeGetDky(impl_->cvode, ts, 0, impl_->dky), "CVodeGetDky(0)");
    for (int i = 0; i < kStateSize; ++i) s[i] = N_VGetArrayPointer(impl_->dky)[i];
    impl_->Check(CVodeGetDky(impl_->cvode, ts, 1, impl_->dky), "CVodeGetDky(1)");
    for (int i = 0; i < kStateSize; ++i) d[i] = N_VGetArrayPointer(impl_->dky)[i];
  }

  TruthSample out;
  out.t = t;
  const double yaw = s[kYaw], v = s[kV], yaw_rate = d[kYaw], v_dot = d[kV];
  out.p_NB_N_m = Eigen::Vector3d(s[kE], s[kN], 0.0);
  const Geodetic g = frame_.ToGeodetic(out.p_NB_N_m);
  out.lat_deg = g.lat_deg;
  out.lon_deg = g.lon_deg;
  out.height_m = g.height_m;
  out.p_EB_E_m = frame_.ToEcef(out.p_NB_N_m);
  const Eigen::Vector2d fwd(std::cos(yaw), std::sin(yaw));
  const Eigen::Vector2d left(-std::sin(yaw), std::cos(yaw));
  out.v_NB_N_mps << v * fwd, 0.0;
  out.a_NB_N_mps2 << v_dot * fwd + v * yaw_rate * left, 0.0;
  out.q_NB = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  out.w_NB_B_radps = Eigen::Vector3d(0, 0, yaw_rate);
  const double g_mag = GeographicLib::NormalGravity::WGS84().SurfaceGravity(g.lat_deg);
  out.gravity_N_mps2 = Eigen::Vector3d(0, 0, -g_mag);
  const Eigen::Matrix3d R_BN = out.q_NB.toRotationMatrix().transpose();
  out.f_B_mps2 = R_BN * (out.a_NB_N_mps2 - out.gravity_N_mps2);
  const double lat = g.lat_deg * kDeg;
  const Eigen::Vector3d w_IE_N(0, kEarthRate_radps * std::cos(lat), kEarthRate_radps * std::sin(lat));
  out.w_IB_B_radps = out.w_NB_B_radps + (config_.earth_rotation ? Eigen::Vector3d(R_BN * w_IE_N) : Eigen::Vector3d::Zero());
  out.speed_mps = v;
  out.steer_rad = config_.steer_deg * kDeg;
  out.wheel_speed_left_mps = v;
  out.wheel_speed_right_mps = v;
  return out;
}

}  // namespace hil::truth

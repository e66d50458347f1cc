#include "hil/truth/truth_integrator.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/NormalGravity.hpp>
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "hil/firmware_emu/angles.h"
#include "hil/truth/actuator_lag.h"
#include "hil/truth/body_motion.h"
#include "hil/truth/command_schedule.h"

namespace hil::truth {
namespace {

constexpr double kEarthRate_radps = 7.2921150e-5;
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kFreeRunHorizon_s = 1e4;  // tout for CVODE when no event is scheduled
enum StateIndex { kE = 0, kN = 1, kYaw = 2, kV = 3, kU = 4, kStateSize = 5 };

double WrapPi(double a) { return std::remainder(a, 2 * std::numbers::pi); }

/// Commands held between guidance updates.
struct Inputs {
  double v_cmd = 0;  ///< forward speed command (m/s)
  double u_cmd = 0;  ///< steering angle (rad, bicycle) or yaw rate (rad/s, diff drive)
  bool operator==(const Inputs&) const = default;
};

/// The discrete state of the path follower.
struct Mode {
  enum class Phase { kOpenLoop, kFollow, kStopped, kTurnInPlace, kDone, kExternal };
  Phase phase = Phase::kOpenLoop;
  std::size_t segment = 0;  ///< active path segment
  double resume_t = kInf;   ///< end of a stop
  bool operator==(const Mode&) const = default;
};

}  // namespace

namespace {
/// Geodetic coordinates of an ECEF point and the normal gravity there, expressed in N.
Eigen::Vector3d GeodeticAndGravity(const LocalFrame& frame, const Eigen::Vector3d& p_E,
                                   Geodetic& g) {
  GeographicLib::Geocentric::WGS84().Reverse(p_E.x(), p_E.y(), p_E.z(), g.lat_deg, g.lon_deg,
                                             g.height_m);
  Eigen::Vector3d g_E;
  GeographicLib::NormalGravity::WGS84().U(p_E.x(), p_E.y(), p_E.z(), g_E.x(), g_E.y(), g_E.z());
  return frame.R_EN().transpose() * g_E;
}
}  // namespace

Eigen::Vector3d GravityAt(const LocalFrame& frame, const Eigen::Vector3d& p_N_m) {
  Geodetic g;
  return GeodeticAndGravity(frame, frame.ToEcef(p_N_m), g);
}

Eigen::Vector3d EarthRateIn(const LocalFrame& frame) {
  return frame.R_EN().transpose() * Eigen::Vector3d(0, 0, kEarthRate_radps);
}

struct TruthIntegrator::Impl {
  const TruthConfig* c = nullptr;
  const Terrain* terrain = nullptr;
  const LocalFrame* frame = nullptr;
  bool diff_drive = false;  // commanded by a yaw rate (diff_drive, skid_steer)
  bool skid_steer = false;  // the reference point slips sideways in a turn
  mutable std::optional<SpeedVariation> speed_variation;  // grows its grid as time advances
  std::vector<bool> stop_vertex;          // vehicle stops at (or turns in place at) this vertex
  std::vector<std::size_t> next_stop;     // first stop vertex after segment i's start
  std::vector<Eigen::Vector2d> switch_n;  // normal of segment i's switching line through vertex i+1
  double tick_s = kInf;                   // guidance period
  Eigen::Vector3d w_IE_N = Eigen::Vector3d::Zero();

  // CVODE
  SUNContext ctx = nullptr;
  N_Vector y = nullptr, work = nullptr, atol = nullptr;
  void* cvode = nullptr;
  SUNNonlinearSolver nls = nullptr;
  long steps_before = 0, reinits = 0, roots = 0;

  // the integration's own view of time
  Inputs in;
  Mode mode;
  double t_cur = 0;      // integrated up to here (a root/stop time or the last step's end)
  double t_lo = 0;       // dense output valid from here
  double t_init = 0;     // time of the last (re)initialisation
  bool fresh = true;     // no step since the last (re)initialisation: y holds the state at t_cur
  bool pending = false;  // an event at t_cur has not been handled
  bool pending_root = false;
  std::int64_t next_tick = 1;  // index of the next guidance update
  double last_request = 0;

  // closed loop: external commands, from each one's grid instant on (sorted by time); read in
  // time order by Guide (a cursor, rewound by Init), so mutable
  mutable CommandSchedule schedule;
  bool restart_needed = false;
  long late_restarts = 0;

  // The lags of v and u in closed form from (lag_t0, lag_v0, lag_u0) under the held inputs;
  // CVODE integrates e, n, ψ only (kOdeSize components of y). Their right-hand side stays
  // continuous when the inputs change (v and u do not jump), so a new input needs no restart:
  // CVODE's error control takes the kink in v̇ and u̇; a mode change or a root restarts it.
  static constexpr int kOdeSize = kYaw + 1;
  double lag_t0 = 0, lag_v0 = 0, lag_u0 = 0;

  /// Closed loop with a first-order hold: v and u ramp to each command (command_hold_s).
  bool Held() const { return c->external_commands && c->command_hold_s > 0; }

  /// The full state at t from CVODE's components `ode` (e, n, ψ) and the lags' closed forms.
  void FullState(double t, const double* ode, double* s) const {
    std::copy(ode, ode + kOdeSize, s);
    const VehicleParams& p = c->vehicle;
    const double dt = t - lag_t0;
    if (Held()) {
      s[kV] = LinearHoldAt(lag_v0, in.v_cmd, c->command_hold_s, dt);
      s[kU] = LinearHoldAt(lag_u0, in.u_cmd, c->command_hold_s, dt);
      return;
    }
    s[kV] = FirstOrderLagAt(lag_v0, in.v_cmd, p.speed_lag_s, dt);
    s[kU] = diff_drive ? FirstOrderLagAt(lag_u0, in.u_cmd, p.yaw_rate_lag_s, dt)
                       : RateLimitedLagAt(lag_u0, in.u_cmd, p.steer_lag_s,
                                          p.max_steer_rate_dps * kDeg, dt);
  }

  /// The external command in force at t (zero before the first).
  Inputs Scheduled(double t) const {
    const CommandSchedule::Entry* e = schedule.At(t);
    return e ? Inputs{e->speed_mps, e->steer_or_yaw_rate} : Inputs{};
  }

  // ---- model -------------------------------------------------------------------------------

  double NominalSpeed(double t) const {
    double v = c->speed_mps;
    for (const SpeedStep& s : c->speed_profile) {
      if (s.t_s <= t) v = s.speed_mps;
    }
    return v;
  }

  double SegmentSpeed(std::size_t seg, double t) const {
    const auto& sv = c->path->vertices()[seg].speed_mps;
    return sv ? *sv : NominalSpeed(t);
  }

  /// ψ̇ of the state.
  double YawRate(const double* s) const {
    if (diff_drive) return s[kU];
    return s[kV] * std::tan(s[kU]) / c->vehicle.wheelbase_m;
  }

  /// Slip angle of the velocity.
  double Slip(const double* s) const {
    return -c->vehicle.slip_gain_rad_per_mps2 * s[kV] * YawRate(s);
  }

  void Derivs(const double* s, const Inputs& u, double* d) const {
    const VehicleParams& p = c->vehicle;
    const double chi = s[kYaw] + Slip(s);
    d[kE] = s[kV] * std::cos(chi);
    d[kN] = s[kV] * std::sin(chi);
    if (skid_steer) {  // the lateral speed v_y = −x_v·ψ̇ of the ICRs' offset
      const double v_y = p.lateral_speed_mps(YawRate(s));
      d[kE] -= v_y * std::sin(chi);
      d[kN] += v_y * std::cos(chi);
    }
    d[kYaw] = YawRate(s);
    if (Held()) {
      // the hold's ramp: its slope until the input reaches the command, then none
      d[kV] = s[kV] == u.v_cmd ? 0.0 : (u.v_cmd - lag_v0) / c->command_hold_s;
      d[kU] = s[kU] == u.u_cmd ? 0.0 : (u.u_cmd - lag_u0) / c->command_hold_s;
      return;
    }
    d[kV] = (u.v_cmd - s[kV]) / p.speed_lag_s;
    if (diff_drive) {
      d[kU] = (u.u_cmd - s[kU]) / p.yaw_rate_lag_s;
    } else {
      // first-order lag with a smooth rate limit
      const double r = p.max_steer_rate_dps * kDeg;
      d[kU] = r * std::tanh((u.u_cmd - s[kU]) / (p.steer_lag_s * r));
    }
  }

  /// The horizontal trajectory's jets (value, first and second derivative) from y and ẏ.
  HorizontalJets Jets(const double* s, const double* d) const {
    const double k = c->vehicle.slip_gain_rad_per_mps2;
    const double v = s[kV], v_dot = d[kV];
    const double psi_dot = d[kYaw];
    double psi_ddot = 0;
    if (diff_drive) {
      psi_ddot = d[kU];
    } else {
      const double L = c->vehicle.wheelbase_m, tan_d = std::tan(s[kU]);
      psi_ddot = (v_dot * tan_d + v * (1 + tan_d * tan_d) * d[kU]) / L;
    }
    const double beta_dot = -k * (v_dot * psi_dot + v * psi_ddot);
    const double chi = s[kYaw] + Slip(s), chi_dot = psi_dot + beta_dot;
    const double cc = std::cos(chi), sc = std::sin(chi);
    double e_ddot = v_dot * cc - v * sc * chi_dot, n_ddot = v_dot * sc + v * cc * chi_dot;
    if (skid_steer) {  // the lateral speed v_y = −x_v·ψ̇ and its rate
      const double v_y = c->vehicle.lateral_speed_mps(psi_dot);
      const double v_y_dot = c->vehicle.lateral_speed_mps(psi_ddot);
      e_ddot -= v_y_dot * sc + v_y * cc * chi_dot;
      n_ddot += v_y_dot * cc - v_y * sc * chi_dot;
    }
    HorizontalJets h;
    h.e_m = Jet2(s[kE], d[kE], e_ddot);
    h.n_m = Jet2(s[kN], d[kN], n_ddot);
    h.yaw_rad = Jet2(s[kYaw], psi_dot, psi_ddot);
    return h;
  }

  static int Rhs(sunrealtype t, N_Vector y, N_Vector ydot, void* user) {
    const auto* self = static_cast<const Impl*>(user);
    double s[kStateSize], d[kStateSize];
    self->FullState(t, N_VGetArrayPointer(y), s);
    self->Derivs(s, self->in, d);
    std::copy(d, d + kOdeSize, N_VGetArrayPointer(ydot));
    return 0;
  }

  /// Root function: crossing the switching line at the end of the active segment.
  double SwitchFunction(const double* s) const {
    if (mode.phase != Mode::Phase::kFollow) return 1.0;
    const std::size_t k = mode.segment;
    const Eigen::Vector2d r = Eigen::Vector2d(s[kE], s[kN]) - c->path->vertices()[k + 1].p_N_m;
    return r.dot(switch_n[k]);
  }

  static int Roots(sunrealtype t, N_Vector y, sunrealtype* g, void* user) {
    const auto* self = static_cast<const Impl*>(user);
    double s[kStateSize];
    self->FullState(t, N_VGetArrayPointer(y), s);
    g[0] = self->SwitchFunction(s);
    return 0;
  }

  // ---- guidance ----------------------------------------------------------------------------

  Inputs Guide(double t, const double* s, const Inputs& last) const {
    const VehicleParams& p = c->vehicle;
    Inputs out;
    switch (mode.phase) {
      case Mode::Phase::kExternal:
        return Scheduled(t + 1e-9);  // a command exactly at a grid instant acts there
      case Mode::Phase::kOpenLoop:
        out.v_cmd = NominalSpeed(t) * speed_variation->Factor(t);
        out.u_cmd = diff_drive ? c->yaw_rate_dps * kDeg : c->steer_deg * kDeg;
        return out;
      case Mode::Phase::kDone:
        return {0, diff_drive ? 0 : last.u_cmd};
      case Mode::Phase::kStopped:
        return {0, diff_drive ? 0 : last.u_cmd};
      case Mode::Phase::kTurnInPlace: {
        const Eigen::Vector2d& u = c->path->direction(mode.segment);
        const double err = WrapPi(std::atan2(u.y(), u.x()) - s[kYaw]);
        const double w_max = p.max_yaw_rate_dps * kDeg;
        return {0, std::clamp(c->guidance.turn_heading_gain_per_s * err, -w_max, w_max)};
      }
      case Mode::Phase::kFollow:
        break;
    }
    const Path& path = *c->path;
    const std::size_t k = mode.segment;
    const Eigen::Vector2d pos(s[kE], s[kN]);
    const double s_now = path.AlongOnSegment(k, pos);
    const double s_la = s_now + c->guidance.lookahead_m;
    // the look-ahead point, not beyond the next stop (past it: on the stop's incoming line)
    const std::size_t j = next_stop[k];
    const double s_stop = path.s_at_vertex(j);
    const Eigen::Vector2d target =
        s_la <= s_stop
            ? path.PointAt(s_la)
            : Eigen::Vector2d(path.vertices()[j].p_N_m + (s_la - s_stop) * path.direction(j - 1));
    const double c_yaw = std::cos(s[kYaw]), s_yaw = std::sin(s[kYaw]);
    const Eigen::Vector2d r = target - pos;
    const double dx = c_yaw * r.x() + s_yaw * r.y(), dy = -s_yaw * r.x() + c_yaw * r.y();
    const double curvature = 2 * dy / std::max(dx * dx + dy * dy, 1e-6);
    // speed: the segment's, limited to stop at the next stop vertex
    // distance to the stop, less what the speed lag will still cover
    const double to_stop = s_stop - s_now - s[kV] * p.speed_lag_s;
    out.v_cmd =
        std::min(SegmentSpeed(k, t) * speed_variation->Factor(t),
                 std::max(c->guidance.creep_speed_mps,
                          std::sqrt(2 * c->guidance.stop_decel_mps2 * std::max(to_stop, 0.0))));
    if (diff_drive) {
      const double w_max = p.max_yaw_rate_dps * kDeg;
      out.u_cmd = std::clamp(out.v_cmd * curvature, -w_max, w_max);
    } else {
      const double d_max = p.max_steer_deg * kDeg;
      out.u_cmd = std::clamp(std::atan(p.wheelbase_m * curvature), -d_max, d_max);
    }
    return out;
  }

  /// Mode transitions due at t (a root at the active switching line, or a time event).
  void Transition(double t, const double* s, bool root) {
    const Path* path = c->path ? &*c->path : nullptr;
    if (root && mode.phase == Mode::Phase::kFollow) {
      ++roots;
      const std::size_t v = mode.segment + 1;
      if (v + 1 >= path->vertices().size()) {
        mode.phase = Mode::Phase::kDone;
      } else {
        mode.segment = v;
        const double stop_s = path->vertices()[v].stop_s;
        if (stop_s > 0) {
          mode.phase = Mode::Phase::kStopped;
          mode.resume_t = t + stop_s;
        } else if (stop_vertex[v]) {
          mode.phase = Mode::Phase::kTurnInPlace;
        }
      }
    }
    // a vertex whose switching line is already behind (a short segment cut by the follower)
    // would never give a root: pass it now
    while (root && mode.phase == Mode::Phase::kFollow && SwitchFunction(s) >= 0)
      Transition(t, s, true);
    if (mode.phase == Mode::Phase::kStopped && t >= mode.resume_t) {
      mode.resume_t = kInf;
      mode.phase = stop_vertex[mode.segment] && diff_drive &&
                           TurnAngle(mode.segment) > c->guidance.turn_in_place_deg * kDeg
                       ? Mode::Phase::kTurnInPlace
                       : Mode::Phase::kFollow;
    }
    if (mode.phase == Mode::Phase::kTurnInPlace) {
      const Eigen::Vector2d& u = path->direction(mode.segment);
      const double err = WrapPi(std::atan2(u.y(), u.x()) - s[kYaw]);
      if (std::abs(err) < c->guidance.turn_in_place_done_deg * kDeg)
        mode.phase = Mode::Phase::kFollow;
    }
  }

  /// Turn of the path at vertex v (rad, unsigned).
  double TurnAngle(std::size_t v) const {
    const Path& path = *c->path;
    if (v == 0 || v + 1 >= path.vertices().size()) return 0;
    const Eigen::Vector2d& a = path.direction(v - 1);
    const Eigen::Vector2d& b = path.direction(v);
    return std::abs(std::atan2(a.x() * b.y() - a.y() * b.x(), a.dot(b)));
  }

  double NextTimeEvent() const {
    double t = tick_s * static_cast<double>(next_tick);
    if (mode.resume_t < t) t = mode.resume_t;
    for (const SpeedStep& s : c->speed_profile) {
      if (s.t_s > t_cur && s.t_s < t) t = s.t_s;
    }
    return t;
  }

  // ---- integration -------------------------------------------------------------------------

  void Check(int flag, const char* what) const {
    if (flag < 0)
      throw std::runtime_error(std::string("CVODE ") + what + " failed with flag " +
                               std::to_string(flag) + " (" + CVodeGetReturnFlagName(flag) + ")");
  }

  void Setup() {
    const VehicleParams& p = c->vehicle;
    diff_drive = p.yaw_rate_commanded();
    skid_steer = p.model == VehicleParams::Model::kSkidSteer;
    speed_variation.emplace(p.speed_variation_std, p.speed_variation_tau_s, p.speed_variation_seed);
    if (p.speed_variation_std > 0)
      tick_s = 1.0 / c->guidance.rate_hz;  // open loop too: the speed varies
    w_IE_N = c->earth_rotation ? EarthRateIn(*frame) : Eigen::Vector3d::Zero();
    if (c->external_commands) tick_s = c->command_period_s;
    if (c->path && !c->external_commands) {
      const Path& path = *c->path;
      const std::size_t nv = path.vertices().size();
      tick_s = 1.0 / c->guidance.rate_hz;
      stop_vertex.assign(nv, false);
      stop_vertex[nv - 1] = true;
      for (std::size_t v = 1; v + 1 < nv; ++v) {
        stop_vertex[v] = path.vertices()[v].stop_s > 0 ||
                         (diff_drive && TurnAngle(v) > c->guidance.turn_in_place_deg * kDeg);
      }
      next_stop.assign(nv - 1, nv - 1);
      for (std::size_t i = nv - 1; i-- > 0;) {
        if (stop_vertex[i + 1] || i + 2 >= nv)
          next_stop[i] = i + 1;
        else
          next_stop[i] = next_stop[i + 1];
      }
      switch_n.resize(nv - 1);
      for (std::size_t i = 0; i + 1 < nv; ++i) {
        const Eigen::Vector2d& u = path.direction(i);
        Eigen::Vector2d n = u;
        if (!stop_vertex[i + 1] && i + 2 < nv) {
          const Eigen::Vector2d b = u + path.direction(i + 1);
          if (b.norm() > 1e-6) n = b.normalized();
        }
        switch_n[i] = n;
      }
    }
  }

  void Init() {
    Free();
    schedule.Rewind();
    Check(SUNContext_Create(nullptr, &ctx), "SUNContext_Create");
    y = N_VNew_Serial(kOdeSize, ctx);
    work = N_VNew_Serial(kOdeSize, ctx);
    atol = N_VNew_Serial(kOdeSize, ctx);
    double s[kStateSize];
    const Path* path = c->path ? &*c->path : nullptr;
    const Eigen::Vector2d start =
        c->start_p_N_m.value_or(path ? path->vertices().front().p_N_m : Eigen::Vector2d::Zero());
    const Eigen::Vector2d u0 = path ? path->direction(0) : Eigen::Vector2d(0, 1);
    const double yaw0 =
        c->heading_deg ? (90.0 - *c->heading_deg) * kDeg : std::atan2(u0.y(), u0.x());
    mode = Mode{};
    mode.phase = c->external_commands ? Mode::Phase::kExternal
                 : path               ? Mode::Phase::kFollow
                                      : Mode::Phase::kOpenLoop;
    s[kE] = start.x();
    s[kN] = start.y();
    s[kYaw] = yaw0;
    s[kV] = 0;
    s[kU] = 0;
    in = Guide(0.0, s, Inputs{});
    if (c->start_at_speed) {
      s[kV] = in.v_cmd;
      s[kU] = in.u_cmd;
      in = Guide(0.0, s, in);
    }
    std::copy(s, s + kOdeSize, N_VGetArrayPointer(y));
    lag_t0 = 0;
    lag_v0 = s[kV];
    lag_u0 = s[kU];
    double* a = N_VGetArrayPointer(atol);
    a[kE] = a[kN] = c->atol_m;
    a[kYaw] = c->atol_m * 0.1;
    cvode = CVodeCreate(CV_ADAMS, ctx);
    Check(CVodeInit(cvode, Rhs, 0.0, y), "CVodeInit");
    Check(CVodeSetUserData(cvode, this), "CVodeSetUserData");
    nls = SUNNonlinSol_FixedPoint(y, 0, ctx);
    Check(CVodeSetNonlinearSolver(cvode, nls), "CVodeSetNonlinearSolver");
    Check(CVodeSVtolerances(cvode, c->rtol, atol), "CVodeSVtolerances");
    Check(CVodeSetMaxStep(cvode, c->max_step_s), "CVodeSetMaxStep");
    Check(CVodeSetMaxNumSteps(cvode, 1000000), "CVodeSetMaxNumSteps");
    if (path && !c->external_commands) {
      Check(CVodeRootInit(cvode, 1, Roots), "CVodeRootInit");
      int dir = 1;
      Check(CVodeSetRootDirection(cvode, &dir), "CVodeSetRootDirection");
      Check(CVodeSetNoInactiveRootWarn(cvode), "CVodeSetNoInactiveRootWarn");
    }
    t_cur = t_lo = t_init = 0;
    fresh = true;
    pending = pending_root = false;
    next_tick = 1;
    steps_before = 0;
    reinits = roots = 0;
    last_request = 0;
    restart_needed = false;
    Check(CVodeSetStopTime(cvode, NextTimeEvent()), "CVodeSetStopTime");
  }

  /// Handles the event at t_cur: mode transitions, new commands, and a restart if they changed.
  void HandleEvent() {
    // the state at t_cur: fresh y, or the value CVODE returned at the root/stop time
    double s[kStateSize];
    FullState(t_cur, N_VGetArrayPointer(y), s);
    const Mode old_mode = mode;
    while (tick_s * static_cast<double>(next_tick) <= t_cur) ++next_tick;
    Transition(t_cur, s, pending_root);
    const Inputs next = Guide(t_cur, s, in);
    const bool restart = !(mode == old_mode) || pending_root;
    const bool changed = !(next == in);
    if (changed || restart) {
      in = next;
      lag_t0 = t_cur;  // the lags go on from their values at t_cur under the new inputs
      lag_v0 = s[kV];
      lag_u0 = s[kU];
      t_lo = t_cur;  // dense output before t_cur would take the new inputs' lags
    }
    if (restart) {
      long n = 0;
      CVodeGetNumSteps(cvode, &n);
      steps_before += n;
      Check(CVodeReInit(cvode, t_cur, y), "CVodeReInit");
      t_init = t_cur;
      ++reinits;
      fresh = true;
    }
    pending = pending_root = false;
    const double t_next = NextTimeEvent();
    if (t_next < kInf) Check(CVodeSetStopTime(cvode, t_next), "CVodeSetStopTime");
  }

  void AdvanceTo(double ts) {
    for (;;) {
      if (pending && ts >= t_cur) HandleEvent();
      if (ts <= t_cur) return;
      double t_ret = 0;
      // tout only bounds CVODE's first step after a (re)initialisation; it must not depend on the
      // request, or the step sequence (and so the samples) would depend on the sensor schedule
      const double t_event = NextTimeEvent();
      const int flag = CVode(cvode, t_event < kInf ? t_event : t_init + kFreeRunHorizon_s, y,
                             &t_ret, CV_ONE_STEP);
      Check(flag, "CVode");
      fresh = false;
      double hu = 0;
      CVodeGetLastStep(cvode, &hu);
      double tn = 0;
      CVodeGetCurrentTime(cvode, &tn);
      t_lo = std::max(t_lo, tn - hu);
      t_cur = t_ret;
      if (flag == CV_ROOT_RETURN) {
        pending = pending_root = true;
      } else if (flag == CV_TSTOP_RETURN) {
        pending = true;
      }
    }
  }

  void Free() {
    if (cvode) CVodeFree(&cvode);
    if (nls) SUNNonlinSolFree(nls);
    if (y) N_VDestroy(y);
    if (work) N_VDestroy(work);
    if (atol) N_VDestroy(atol);
    if (ctx) SUNContext_Free(&ctx);
    cvode = nullptr;
    nls = nullptr;
    y = work = atol = nullptr;
    ctx = nullptr;
  }
};

TruthIntegrator::TruthIntegrator(const TruthConfig& config)
    : config_(config),
      frame_(config.origin),
      terrain_(config.terrain),
      impl_(std::make_unique<Impl>()) {
  if (config_.path && config_.guidance.rate_hz <= 0)
    throw std::invalid_argument("guidance rate must be positive");
  if (config_.path && config_.guidance.lookahead_m <= 0)
    throw std::invalid_argument("look-ahead must be positive");
  if (config_.external_commands && !(config_.command_period_s > 0))
    throw std::invalid_argument("command period must be positive");
  impl_->c = &config_;
  impl_->terrain = &terrain_;
  impl_->frame = &frame_;
  impl_->Setup();
  impl_->Init();
}

TruthIntegrator::~TruthIntegrator() { impl_->Free(); }

long TruthIntegrator::steps() const {
  long n = 0;
  CVodeGetNumSteps(impl_->cvode, &n);
  return impl_->steps_before + n;
}
long TruthIntegrator::reinits() const { return impl_->reinits; }
long TruthIntegrator::commands() const { return static_cast<long>(impl_->schedule.size()); }
long TruthIntegrator::late_command_restarts() const { return impl_->late_restarts; }

void TruthIntegrator::SetCommand(Time t, double speed_mps, double steer_or_yaw_rate) {
  Impl& m = *impl_;
  if (!config_.external_commands)
    throw std::logic_error("SetCommand needs TruthConfig::external_commands");
  const double ts = ToSeconds(t);
  if (!m.schedule.empty() && ts < m.schedule.back().t_s)
    throw std::invalid_argument("truth commands must come in non-decreasing time order");
  m.schedule.Add({ts, speed_mps, steer_or_yaw_rate});
  // The grid instant where it acts: already handled (or the initial state, at t = 0) ⇒ replay.
  const double tick = std::ceil(ts / m.tick_s - 1e-9) * m.tick_s;
  const bool handled = tick < m.t_cur || (tick == m.t_cur && !m.pending);
  if (handled && !m.restart_needed) {
    m.restart_needed = true;
    if (!(m.t_cur == 0 && m.fresh)) ++m.late_restarts;  // nothing integrated yet: not late
  }
}
long TruthIntegrator::root_events() const { return impl_->roots; }
bool TruthIntegrator::restart_pending() const { return impl_->restart_needed; }

TruthSample TruthIntegrator::Sample(Time t) {
  Impl& m = *impl_;
  const double ts = ToSeconds(t);
  if (ts < 0) throw std::runtime_error("truth requested before t = 0");
  // dense output covers the last step only: an earlier request restarts from t = 0
  if (ts < m.t_lo || ts < m.last_request || m.restart_needed) m.Init();
  m.last_request = ts;
  m.AdvanceTo(ts);

  double s[kStateSize], d[kStateSize];
  if (m.fresh || ts == m.t_cur) {
    // at t_cur, y holds the state exactly (initial state, or CVODE's value at a root/stop time)
    m.FullState(ts, N_VGetArrayPointer(m.y), s);
  } else {
    m.Check(CVodeGetDky(m.cvode, ts, 0, m.work), "CVodeGetDky");
    m.FullState(ts, N_VGetArrayPointer(m.work), s);
  }
  m.Derivs(s, m.in, d);
  const HorizontalJets h = m.Jets(s, d);
  const BodyMotion b = CalcBodyMotion(terrain_, config_.vibration, h, ts);

  TruthSample out;
  out.t = t;
  out.p_NB_N_m = b.p_NB_N_m;
  out.p_EB_E_m = frame_.ToEcef(b.p_NB_N_m);
  Geodetic geo;
  out.gravity_N_mps2 = GeodeticAndGravity(frame_, out.p_EB_E_m, geo);
  out.lat_deg = geo.lat_deg;
  out.lon_deg = geo.lon_deg;
  out.height_m = geo.height_m;
  out.v_NB_N_mps = b.v_NB_N_mps;
  out.a_NB_N_mps2 = b.a_NB_N_mps2;
  out.q_NB = Eigen::Quaterniond(b.R_NB).normalized();
  out.w_NB_B_radps = b.w_NB_B_radps;
  out.alpha_NB_B_radps2 = b.alpha_NB_B_radps2;
  const Eigen::Matrix3d R_BN = b.R_NB.transpose();
  // specific force in an Earth-fixed frame: a + 2Ω×v − g (normal gravity includes the centrifugal
  // term)
  out.f_B_mps2 = R_BN * (b.a_NB_N_mps2 + 2 * m.w_IE_N.cross(b.v_NB_N_mps) - out.gravity_N_mps2);
  out.w_IB_B_radps = b.w_NB_B_radps + R_BN * m.w_IE_N;
  out.speed_mps = s[kV];
  const double yaw_rate = d[kYaw];
  out.steer_rad = m.diff_drive ? 0.0 : s[kU];
  const WheelGroundSpeeds wheels = WheelSpeedsOf(config_.vehicle, s[kV], yaw_rate);
  out.wheel_speed_left_mps = wheels.left_mps;
  out.wheel_speed_right_mps = wheels.right_mps;
  if (config_.path) {
    const PathProjection pr = config_.path->Project(b.p_NB_N_m.head<2>());
    out.cross_track_m = pr.cross_track_m;
    out.along_track_m = pr.along_m;
  }
  out.speed_cmd_mps = m.in.v_cmd;
  out.steer_cmd_rad = m.diff_drive ? 0.0 : m.in.u_cmd;
  return out;
}

}  // namespace hil::truth

// Which RTK fix episodes agree: the filter's frame and the other hypotheses (rtk_fix_frames.h).
#include "hil/estimator/rtk_fix_frames.h"

#include <limits>

#include <Eigen/Cholesky>

namespace hil::estimator {
namespace {

const Eigen::Vector3d kZero3 = Eigen::Vector3d::Zero();
const Eigen::Matrix3d kZero33 = Eigen::Matrix3d::Zero();

// (a − b)ᵀ C⁻¹ (a − b), infinite when C is not positive definite
double Nis(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Matrix3d& C) {
  const Eigen::LLT<Eigen::Matrix3d> llt(C);
  if (llt.info() != Eigen::Success) return std::numeric_limits<double>::infinity();
  const Eigen::Vector3d d = a - b;
  return d.dot(llt.solve(d));
}

// the log-likelihood of a zero-mean Gaussian with covariance C at x, less its constant;
// −infinity when C is not positive definite
double LogLikelihood(const Eigen::Vector3d& x, const Eigen::Matrix3d& C) {
  const Eigen::LLT<Eigen::Matrix3d> llt(C);
  if (llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  const Eigen::Matrix3d L = llt.matrixL();
  return -0.5 * x.dot(llt.solve(x)) - L.diagonal().array().log().sum();
}

}  // namespace

int RtkFixFrames::Match(const PositionInnovation& first_fix) const {
  int best = -1;
  double best_nis = same_frame_nis_;
  for (int k = 0; k < kMaxOtherFrames; ++k) {
    const Frame& f = others_[k];
    if (f.episodes == 0) continue;
    // both offsets carry the filter's error at their time: independent, the covariances add
    const double nis = Nis(first_fix.nu_m, f.offset_N_m, first_fix.S_m2 + f.cov_m2);
    if (nis <= best_nis) {
      best = k;
      best_nis = nis;
    }
  }
  return best;
}

int RtkFixFrames::FreeSlot() const {
  // a free slot, else the frame seen in the fewest episodes, the longest ago among them
  int slot = 0;
  for (int k = 0; k < kMaxOtherFrames; ++k) {
    const Frame& f = others_[k];
    const Frame& s = others_[slot];
    if (f.episodes == 0) return k;
    if (f.episodes < s.episodes || (f.episodes == s.episodes && f.last_episode < s.last_episode))
      slot = k;
  }
  return slot;
}

RtkFixFrames::Decision RtkFixFrames::Judge(const PositionInnovation& first_fix) {
  ++episodes_;
  current_ = -1;
  const bool first = filter_episodes_ == 0;
  // the filter follows no frame yet: its estimate is the float solution's
  if (first)
    anchor_ = PositionInnovation{Eigen::Vector3d::Zero(), Eigen::Matrix3d::Zero(), 0, true};
  if (!first_fix.valid || first_fix.nis <= same_frame_nis_) {
    ++filter_episodes_;
    if (first) anchor_ = first_fix;  // the filter goes over to the episode's frame
    return {};
  }
  int k = Match(first_fix);
  if (k < 0) {
    k = FreeSlot();
    others_[k] = Frame{first_fix.nu_m, first_fix.S_m2, 1, episodes_};
  } else {
    // one more measurement of that frame's offset: the two combined by their information
    Frame& f = others_[k];
    const Eigen::Matrix3d info_f = f.cov_m2.inverse(), info_n = first_fix.S_m2.inverse();
    f.cov_m2 = (info_f + info_n).inverse();
    f.offset_N_m = f.cov_m2 * (info_f * f.offset_N_m + info_n * first_fix.nu_m);
    ++f.episodes;
    f.last_episode = episodes_;
  }
  const int seen = others_[k].episodes;
  if (seen > filter_episodes_ || (seen == filter_episodes_ && FloatFavours(k))) return SwitchTo(k);
  return OtherFrame(k);
}

bool RtkFixFrames::FloatFavours(int k) const {
  if (!anchor_.valid) return false;
  // each frame's offset from the float solution the filter held before its first episode, as
  // log-likelihoods under each frame's covariance
  return LogLikelihood(anchor_.nu_m + others_[k].offset_N_m, anchor_.S_m2 + others_[k].cov_m2) >
         LogLikelihood(anchor_.nu_m, anchor_.S_m2);
}

RtkFixFrames::Decision RtkFixFrames::OtherFrame(int k) {
  current_ = k;
  Decision d;
  d.verdict = Verdict::kOtherFrame;
  d.offset_N_m = others_[k].offset_N_m;
  d.var_m2 = others_[k].cov_m2.diagonal();
  return d;
}

RtkFixFrames::Decision RtkFixFrames::SwitchTo(int k) {
  const Frame to = others_[k];
  // the filter's frame becomes a hypothesis, seen from the new one; the others move with it
  others_[k] = Frame{-to.offset_N_m, to.cov_m2, filter_episodes_, episodes_};
  for (int j = 0; j < kMaxOtherFrames; ++j) {
    if (j == k || others_[j].episodes == 0) continue;
    others_[j].offset_N_m -= to.offset_N_m;
    others_[j].cov_m2 += to.cov_m2;
  }
  filter_episodes_ = to.episodes;
  anchor_.nu_m += to.offset_N_m;
  anchor_.S_m2 += to.cov_m2;
  current_ = -1;
  ++switches_;
  Decision d;
  d.verdict = Verdict::kSwitch;
  d.offset_N_m = to.offset_N_m;
  d.var_m2 = to.cov_m2.diagonal();
  return d;
}

RtkFixFrames::Decision RtkFixFrames::AdoptCurrent() {
  if (current_ < 0) return {};
  return SwitchTo(current_);
}

void RtkFixFrames::Restart(const PositionInnovation& first_fix) {
  others_.fill(Frame{});
  anchor_ = first_fix;
  filter_episodes_ = 1;
  current_ = -1;
  ++episodes_;
}

double RtkFixFrames::NisFromCurrentFrame(const PositionInnovation& fix) const {
  if (!fix.valid) return 0.0;
  return Nis(fix.nu_m, current_offset_N_m(), fix.S_m2 + current_cov_m2());
}

const Eigen::Vector3d& RtkFixFrames::current_offset_N_m() const {
  return current_ < 0 ? kZero3 : others_[current_].offset_N_m;
}

const Eigen::Matrix3d& RtkFixFrames::current_cov_m2() const {
  return current_ < 0 ? kZero33 : others_[current_].cov_m2;
}

int RtkFixFrames::other_frames() const {
  int n = 0;
  for (const Frame& f : others_) n += f.episodes > 0 ? 1 : 0;
  return n;
}

}  // namespace hil::estimator

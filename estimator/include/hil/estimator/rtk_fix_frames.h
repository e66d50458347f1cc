#pragma once
/// @file
/// @system
/// name: RtkFixFrames (which RTK fix episodes agree: the filter's frame and the other hypotheses)
/// input: each fix episode's first fix as an innovation against the filter (offset and its
///        covariance, NIS)
/// output: whether the episode lies in the filter's frame, in another one (its offset), or
///         whether the filter is to move to another frame (by its offset, with its covariance)
/// @endsystem
///
/// A right RTK fix is the antenna's position within centimetres; a wrong one (wrong integers) is
/// off by a constant offset while the receiver holds it, decimetres, different for every wrong
/// fix. So all right episodes lie in one frame, and each wrong one in a frame of its own: GNSS
/// alone cannot tell which of two disagreeing episodes is right, but two independent episodes that
/// agree are right (two wrong ones agreeing by chance, within centimetres, are far less likely).
/// The filter follows one frame (that of the episodes it fused as they are); every episode whose
/// first fix disagrees with it is kept as a hypothesis, a frame with its offset from the filter's
/// and the number of episodes that lay in it. The filter moves to another frame when that frame
/// has been seen in more episodes than the filter's own: the filter had followed a wrong episode.
/// A tie is decided by the estimate the filter held before it followed any frame (the float
/// solution's, decimetres): the frame nearer to it in its covariance's likelihood. Fixed size, no
/// allocation.
#include <array>
#include <cstdint>

#include <Eigen/Core>

#include "hil/estimator/error_state_ekf.h"

namespace hil::estimator {

class RtkFixFrames {
 public:
  static constexpr int kMaxOtherFrames = 4;  ///< hypotheses kept besides the filter's frame
  enum class Verdict {
    kFilterFrame,  ///< the episode lies in the filter's frame: fuse it as it is
    kOtherFrame,   ///< it lies in another frame: fuse it less offset_N_m, its variance added
    kSwitch,       ///< that frame now has more episodes: move the filter by offset_N_m
  };
  struct Decision {
    Verdict verdict = Verdict::kFilterFrame;
    Eigen::Vector3d offset_N_m = Eigen::Vector3d::Zero();  ///< the frame less the filter's
    Eigen::Vector3d var_m2 = Eigen::Vector3d::Zero();      ///< the offset's variance per axis
  };

  RtkFixFrames() = default;
  explicit RtkFixFrames(double same_frame_nis) : same_frame_nis_(same_frame_nis) {}

  /// An episode's first fix: its innovation against the filter aided until just before.
  Decision Judge(const PositionInnovation& first_fix);
  /// The filter coasted (`first_fix`: the episode's first fix against it) or was reset onto a fix
  /// (an invalid one): its frame is that of the episode beginning now, and the other frames,
  /// measured from a filter that has moved since, are forgotten.
  void Restart(const PositionInnovation& first_fix = {});
  /// The current episode, in another frame, has been held long enough to be believed: the filter
  /// moves to its frame (kSwitch; kFilterFrame when the current episode is in the filter's).
  Decision AdoptCurrent();
  /// The NIS at which a fix is in a frame (RtkFixCheckParams::same_frame_nis).
  double same_frame_nis() const { return same_frame_nis_; }
  /// A fix's NIS against the frame of the current episode (its offset from the filter's, the
  /// offset's covariance added); 0 for an invalid innovation.
  double NisFromCurrentFrame(const PositionInnovation& fix) const;
  /// The offset and covariance of the frame the current episode lies in (zero: the filter's).
  const Eigen::Vector3d& current_offset_N_m() const;
  const Eigen::Matrix3d& current_cov_m2() const;
  int filter_frame_episodes() const { return filter_episodes_; }
  int other_frames() const;
  std::uint64_t switches() const { return switches_; }

 private:
  struct Frame {
    Eigen::Vector3d offset_N_m = Eigen::Vector3d::Zero();  // from the filter's frame
    Eigen::Matrix3d cov_m2 = Eigen::Matrix3d::Zero();
    int episodes = 0;  // 0: the slot is free
    std::uint64_t last_episode = 0;
  };
  int Match(const PositionInnovation& first_fix) const;
  int FreeSlot() const;
  Decision SwitchTo(int k);
  bool FloatFavours(int k) const;
  Decision OtherFrame(int k);

  double same_frame_nis_ = 16.27;
  std::array<Frame, kMaxOtherFrames> others_{};
  int filter_episodes_ = 0;
  // the filter's frame less the estimate it held before following any frame (the float
  // solution's, or the INS's after coasting), and its covariance: a tie's evidence
  PositionInnovation anchor_{};
  int current_ = -1;  // the other frame the current episode lies in, −1: the filter's
  std::uint64_t episodes_ = 0, switches_ = 0;
};

}  // namespace hil::estimator

// Wrong RTK fixes: which frame of fix episodes the filter follows (RtkFixFrames), and the fixes of
// a suspect episode (RtkFixCheck). A wrong integer fix puts the receiver's position decimetres off
// by an offset that stays while the receiver holds the fix; its Doppler velocity does not depend
// on the ambiguities. An episode in another frame than the filter's is fused less that frame's
// offset (its increments, which the offset does not touch), with the offset's variance added to
// its fixes', and its velocities as usual; when another frame has been seen in more episodes than
// the filter's, the filter moves to it. See estimator.md, "Wrong RTK fixes".
#include "hil/estimator/navigator.h"

namespace hil::estimator {

void Navigator::RecordRtkFrames() {
  stats_.rtk_suspect_episodes = rtk_check_.suspect_episodes();
  stats_.rtk_suspect_fixes = rtk_check_.suspect_fixes();
  stats_.rtk_frame_switches = rtk_frames_.switches();
  stats_.rtk_frame_episodes = static_cast<std::uint64_t>(rtk_frames_.filter_frame_episodes());
  stats_.rtk_other_frames = static_cast<std::uint64_t>(rtk_frames_.other_frames());
}

void Navigator::MoveToRtkFrame(const RtkFixFrames::Decision& d) {
  if (d.verdict != RtkFixFrames::Verdict::kSwitch) return;
  // the filter had followed a wrong episode: it moves by the right frame's offset, and its
  // position's variance takes that offset's (the filter's error when the offset was measured)
  ekf_.ShiftPosition(d.offset_N_m, d.var_m2);
  rtk_check_.EndSuspicion();
}

void Navigator::JudgeRtkEpisode(const GnssSample& g, const PositionInnovation& first_fix) {
  const RtkFixFrames::Decision d = rtk_frames_.Judge(first_fix);
  MoveToRtkFrame(d);
  if (d.verdict == RtkFixFrames::Verdict::kOtherFrame) rtk_check_.BeginSuspect(g.t);
  rtk_off_frame_fixes_ = 0;
  RecordRtkFrames();
}

std::optional<UpdateResult> Navigator::ControlRtkFix(const GnssSample& g,
                                                     const Eigen::Vector3d& p_antenna_N_m) {
  if (rtk_check_.BeginsEpisode(g.t, g.fix_quality)) {
    if (!rtk_check_.FilterAided(g.t, last_gnss_fused_t_)) {
      // a filter that coasted is no reference: the episode is taken as it comes
      rtk_frames_.Restart(ekf_.PositionInnovationOf(p_antenna_N_m, g.pos_std_enu_m));
      RecordRtkFrames();
      return std::nullopt;
    }
    JudgeRtkEpisode(g, ekf_.PositionInnovationOf(p_antenna_N_m, g.pos_std_enu_m));
    if (!rtk_check_.suspect()) return std::nullopt;
    return FuseSuspectRtkFix(g, p_antenna_N_m);
  }
  if (!rtk_check_.suspect()) return std::nullopt;
  if (rtk_check_.HoldOver(g.t)) {
    // held this long, the receiver is believed: the filter moves to its frame
    MoveToRtkFrame(rtk_frames_.AdoptCurrent());
    rtk_check_.EndSuspicion();
    RecordRtkFrames();
    return std::nullopt;
  }
  const PositionInnovation raw = ekf_.PositionInnovationOf(p_antenna_N_m, g.pos_std_enu_m);
  const double nis_from_frame = rtk_frames_.NisFromCurrentFrame(raw);
  if (raw.valid && raw.nis <= rtk_frames_.same_frame_nis() &&
      nis_from_frame > rtk_frames_.same_frame_nis()) {
    // the receiver's fixes left the episode's frame for the filter's: it re-fixed right
    rtk_check_.EndSuspicion();
    return std::nullopt;
  }
  rtk_check_.CountSuspectFix();
  RecordRtkFrames();
  if (nis_from_frame <= rtk_frames_.same_frame_nis()) {
    rtk_off_frame_fixes_ = 0;
    return FuseSuspectRtkFix(g, p_antenna_N_m);
  }
  // out of the episode's frame as well: its offset changed without a new fix (the geometry of
  // the wrong integers, or other ones). Not fused; a few such fixes in a row (a fix outside
  // 0.999 of its frame by chance three times running: 1e-9) make it a new episode
  if (++rtk_off_frame_fixes_ < kRtkOffFrameFixes) return RejectedFix();
  rtk_check_.EndSuspicion();
  JudgeRtkEpisode(g, raw);
  if (!rtk_check_.suspect()) return std::nullopt;
  return FuseSuspectRtkFix(g, p_antenna_N_m);
}

UpdateResult Navigator::RejectedFix() {
  // the raw fix is counted as rejected (gnss_rejected): its velocity is fused as usual
  UpdateResult r;
  r.dof = 3;
  return r;
}

UpdateResult Navigator::FuseSuspectRtkFix(const GnssSample& g,
                                          const Eigen::Vector3d& p_antenna_N_m) {
  // not in the innovation window, no fading: the receiver's error, not the filter's. The offset's
  // error is common to the episode's fixes: carried in their σ rather than averaged away
  const Eigen::Vector3d std_m =
      (g.pos_std_enu_m.array().square() + rtk_frames_.current_cov_m2().diagonal().array().max(0.0))
          .sqrt();
  ekf_.UpdatePosition(p_antenna_N_m - rtk_frames_.current_offset_N_m(), std_m);
  step_.Remember(g.t, p_antenna_N_m, g.pos_std_enu_m, ekf_.AntennaPosition());
  return RejectedFix();
}

}  // namespace hil::estimator

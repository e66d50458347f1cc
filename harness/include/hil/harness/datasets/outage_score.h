#pragma once
/// @file
/// A KF-GINS-format result scored the way the literature scores GNSS/INS through outages: per
/// outage window the largest and the RMS horizontal and 3-D error and the heading error at the
/// window's end; over all windows the RMS (and the mean and the worst) of the per-window maxima
/// (KF-GINS's paper: 60 s outages, RMS of the maxima); the RMSE where GNSS is present; and, with
/// the result's σ file (KF_GINS_STD.txt: sow, σ position NED, σ velocity NED, …), the mean NEES of
/// position (3 dof) and of position and velocity (6 dof).
/// The result is interpolated (linearly, attitude from the nearer epoch) at each truth epoch
/// bracketed by result epochs at most 0.2 s apart. A window [start, end) holds the truth epochs
/// start ≤ t < end (the import drops the fixes in the same span); the heading error is taken at
/// the window's last such epoch.

#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/harness/datasets/kfgins_text.h"
#include "hil/harness/datasets/outage_windows.h"

namespace hil::harness {

/// One line of a σ file: the first seven columns of KF-GINS's and navd's KF_GINS_STD.txt.
struct KfginsStdLine {
  double sow = 0;
  Eigen::Vector3d pos_ned_m = Eigen::Vector3d::Zero(), vel_ned_mps = Eigen::Vector3d::Zero();
};
/// @throws ImportInputError naming the file, line and field.
std::vector<KfginsStdLine> ReadKfginsStd(const std::string& path);

struct WindowScore {
  OutageWindow window;
  std::size_t epochs = 0;
  double max_h_m = 0, rms_h_m = 0, max_3d_m = 0, rms_3d_m = 0, heading_end_deg = 0;
};

struct OutageScore {
  std::vector<WindowScore> windows;
  double rms_of_max_h_m = 0, rms_of_max_3d_m = 0, mean_of_max_h_m = 0, worst_max_h_m = 0;
  double mean_of_max_3d_m = 0, worst_max_3d_m = 0, rms_heading_end_deg = 0;
  std::size_t gnss_epochs = 0;  ///< truth epochs from `from_s` on outside every window
  double rmse_h_gnss_m = 0, rmse_v_gnss_m = 0, rmse_3d_gnss_m = 0, max_h_gnss_m = 0;
  bool has_nees = false;
  std::size_t nees_epochs = 0;
  double mean_nees_pos = 0, mean_nees_posvel = 0;  ///< expected 3 and 6 when σ is honest
};

/// @param from_s seconds after the truth's first epoch before which GNSS-present epochs are not
/// scored. @throws std::runtime_error when no truth epoch is covered by the result.
OutageScore ScoreOutages(const std::vector<KfginsNavLine>& truth,
                         const std::vector<KfginsNavLine>& estimate,
                         const std::vector<OutageWindow>& windows, double from_s,
                         const std::vector<KfginsStdLine>* stds);

/// Text (one line a window, then the summary) and JSON forms.
std::string OutageScoreText(const OutageScore& s);
std::string OutageScoreJson(const OutageScore& s);

}  // namespace hil::harness

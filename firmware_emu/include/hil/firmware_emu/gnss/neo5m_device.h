#pragma once
/// @file
/// @system
/// name: Neo5mDevice (u-blox NEO-5M receiver emulator, or the RTK profile)
/// input: TruthSample at each navigation epoch; host bytes (UBX CFG/polls, $PUBX) on UART1
/// output: per epoch, after `output_lag`: the $GPTXT banner after (re)start, the enabled UBX NAV
///         messages and MON-HW, then the enabled NMEA sentences (RMC, VTG, GGA, GSA, GSV…, GLL,
///         ZDA, PUBX); replies to host commands (polled messages, ACK-ACK/ACK-NAK)
/// rate: the configured measurement rate (CFG-RATE; default 1 Hz)
/// @endsystem
///
/// Layers: ReceiverModel (errors) + Constellation (sky) + FixState (acquisition) → NavEpoch
/// (protocol-neutral) → UBX / NMEA encoders → whole SerialMessages for the UART queue of port 0
/// (UART1). The UART queue drops whole messages that do not fit, as the receiver does.
/// Answers to host commands are SerialMessage::reply: the port sends them after the message on
/// the wire, ahead of the rest of the epoch's output (UartTxQueue::SubmitAhead), so a poll is
/// answered within tens of ms at any time within the epoch (issue 40.7).
/// Host bytes reach the receiver at the port's baud: a command handed over at t (its first byte
/// written) is whole when its last byte has arrived, t + length × 10 bit times after the bytes
/// the host wrote before it (a 48-byte command: 50 ms at 9600 Bd), and is answered
/// `response_delay` after that. The device is handed the bytes when the host wrote them and its
/// settings change then; only the times of what it does (answers, restarts) follow the line.
///
/// Faults (self-contained; scripted in the scenario's `gnss.faults`): each {kind, start_s, end_s}
/// with kind `outage` (sky blocked: no satellites, no fix, re-acquisition afterwards),
/// `obstruction` (nothing received below `elevation_deg`: fewer satellites, worse DOP, 2D or no
/// fix), `step` (position offset `offset_m` ENU while active), `multipath` (extra correlated
/// error of `sigma_m` per axis while active), `data_gap` (the receiver keeps tracking and its fix
/// keeps its quality, but none of its periodic output reaches the link: the GNSS data removed from
/// a recorded run, as paper 004 injected its outages), `overload` (every NMEA sentence and UBX NAV
/// message the receiver knows is output each epoch, as after a careless CFG-MSG: at 9600 baud more
/// bytes than the line carries, so the transmit buffer — the UART queue of the port — overflows and
/// drops whole messages; `overloaded_epochs()` counts the epochs).

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/fix_state.h"
#include "hil/firmware_emu/gnss/nav_epoch.h"
#include "hil/firmware_emu/gnss/receiver_model.h"
#include "hil/firmware_emu/gnss/receiver_profile.h"
#include "hil/firmware_emu/gnss/rtk_solution.h"
#include "hil/firmware_emu/gnss/sky_shading.h"
#include "hil/firmware_emu/gnss/ubx_cfg_session.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"

namespace hil::gnss {

/// One scripted receiver fault, active for start ≤ t < end (emulated time).
struct GnssFault {
  enum class Kind {
    kOutage,
    kObstruction,
    kStep,
    kMultipath,
    kDataGap,
    kOverload
  } kind = Kind::kOutage;
  Time start{}, end{};
  double elevation_deg = 30.0;                           ///< obstruction
  Eigen::Vector3d offset_N_m = Eigen::Vector3d::Zero();  ///< step (ENU)
  double sigma_m = 3.0;                                  ///< multipath
};

struct Neo5mConfig {
  std::string name = "gps0";
  std::string profile = "neo-5m";
  int baud = 0;                                             ///< 0: the profile's default
  double rate_hz = 0;                                       ///< 0: the profile's default
  Duration output_lag = std::chrono::milliseconds(100);     ///< epoch → first byte ready
  Duration response_delay = std::chrono::milliseconds(10);  ///< host command → reply ready
  UnixTime start_utc{};                                     ///< UTC of scenario time 0
  std::optional<ReceiverModelConfig> model;  ///< errors; the profile's grade when empty
  StartKind start = StartKind::kHot;
  std::vector<GnssFault> faults;
  std::uint64_t common_seed = 0;  ///< error stream shared by all receivers of the scenario
  /// Whether the SBAS satellites in view broadcast corrections valid at the site (then, with
  /// CFG-SBAS usage diffCorr, fixes are differential: GGA quality 2, mode D). Off by default, as
  /// in the real u-blox 5 captures (SBAS tracked, quality 1).
  bool sbas_corrections = false;
  /// The sky's obstructions and the signal thresholds (SkyShading); inactive without obstacles.
  ShadingConfig shading;
  /// The `rtk` profile's rough mode (RtkSolution): float/fixed transitions, fix loss, wrong
  /// fixes. Empty: the profile's timer (float for `rtk_fixed_after_s`, then fixed).
  std::optional<RtkRoughness> rtk_rough;
};

class Neo5mDevice final : public Device {
 public:
  Neo5mDevice(const Neo5mConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override { return next_epoch_; }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int port) const override;

  /// The fix of the last epoch (invalid ones included; the raw-fix baseline keeps valid ones).
  const GnssFix& last_fix() const { return last_epoch_.fix; }
  const NavEpoch& last_epoch() const { return last_epoch_; }
  const ubx::ReceiverSettings& settings() const { return session_.current(); }
  const ReceiverProfile& profile() const { return profile_; }
  /// The rough RTK state of the last epoch (state kNone without `rtk_rough`).
  const RtkEpoch& last_rtk() const { return last_rtk_; }
  /// Epochs output under an `overload` fault.
  std::uint64_t overloaded_epochs() const { return overloaded_epochs_; }

 private:
  Duration Period() const;
  Time NextGridEpoch(Time after) const;
  void EmitEpoch(Time t_ready, DeviceOutput& out);
  /// `reply`: an answer to the host (SerialMessage::reply).
  void Push(DeviceOutput& out, Time t, std::string bytes, std::string name,
            bool reply = false) const;
  /// Applies the sky's obstructions to `cond` for the antenna at `p_NA_N_m`.
  void ShadeSky(SkyConditions& cond, const Eigen::Vector3d& p_NA_N_m) const;
  /// The position error and accuracy the multipath of the used satellites makes (into `in`), and
  /// their residuals (into the satellites' prRes).
  void ApplyMultipath(NavEpoch& e, const Dops& dops, ErrorInputs& in) const;
  /// The RTK state of the epoch (rough model or the profile's timer) and its errors (into `in`);
  /// true when float. Tracks the start of the current fix.
  bool RtkFloat(Time t, double dt_s, bool valid, const NavEpoch& e, ErrorInputs& in);
  void HandleUbx(const ubx::InputMessage& m, Time t, DeviceOutput& out);
  void HandleNmea(const ubx::InputMessage& m, Time t, DeviceOutput& out);
  bool OutputEnabled(std::uint16_t proto) const;

  Neo5mConfig config_;
  ReceiverProfile profile_;
  ReceiverModel model_;
  Constellation constellation_;
  FixState fix_state_;
  ubx::UbxCfgSession session_;
  ubx::InputParser parser_;
  Time next_epoch_{};
  Time last_epoch_time_{};
  bool first_epoch_ = true;
  bool banner_pending_ = true;
  bool stopped_ = false;
  std::uint64_t epoch_count_ = 0;
  bool position_known_ = false;
  Time t_fix_since_{};  // start of the current uninterrupted fix (RTK convergence)
  bool had_fix_last_ = false;
  double clk_bias_ns_ = 0, clk_drift_nsps_ = 0;
  NavEpoch last_epoch_;
  std::optional<RtkSolution> rtk_;
  RtkEpoch last_rtk_;
  Time rx_line_free_{};    // when the last host byte has arrived over the line
  bool overload_ = false;  // an overload fault is active at this epoch
  std::uint64_t overloaded_epochs_ = 0;
};

}  // namespace hil::gnss

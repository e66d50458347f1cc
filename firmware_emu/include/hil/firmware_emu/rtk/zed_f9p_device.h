#pragma once
/// @file
/// @system
/// name: ZedF9pDevice (a u-blox ZED-F9P-class RTK rover, UBX protocol 27+)
/// input: TruthSample at each navigation epoch; on UART1 (port 0) the host's UBX (CFG-VALSET/
///        VALGET/VALDEL, polls), NMEA and RTCM 3 (an NTRIP client on the host writes it there);
///        on UART2 the RTCM 3 stream of a base's correction radio (`radio_base`)
/// output: on UART1, per epoch after `output_lag`: the enabled UBX messages (NAV-PVT,
///         NAV-HPPOSLLH, NAV-RELPOSNED, NAV-SAT; before them RXM-RAWX) then the enabled NMEA 4.10
///         sentences (GGA, GLL, GSA, GSV, RMC, VTG); an RXM-RTCM for every RTCM message received
///         (when enabled); replies to host commands (VALGET answers, ACK-ACK/ACK-NAK, polled
///         messages)
/// rate: CFG-RATE-MEAS (default 1000 ms)
/// @endsystem
///
/// Layers: ReceiverModel (standalone errors) + Constellation + FixState → NavEpoch; RTCM 3 frames
/// (rtcm3_stream) → RoverRtk (corrections → float → fixed) → F9Epoch → ubx_f9_messages /
/// nmea_f9_sentences → SerialMessages on port 0; F9ConfigDb holds the configuration.
///
/// The correction radio on UART2: the rover's UART2 is wired to a radio modem that receives the
/// base's packets (a common RTK set-up: base radio → rover UART2). The device runs the base and
/// its RadioLink itself, from the same configuration and seed as the scenario's `rtk_base`
/// device, so the bytes that reach UART2 are the bytes of that device's link (RUN_DIR/ttyRTCM,
/// its capture), at the same times; UART2 is not a pty of the run. The bytes arrive at the
/// base's line rate, and a frame counts when its last byte has arrived; with CFG-UART2-BAUDRATE
/// at another rate (or CFG-UART2INPROT-RTCM3X off) nothing of it is decoded.
/// Only CFG-VALSET/VALGET/VALDEL configure it: the legacy CFG messages (CFG-PRT, CFG-MSG,
/// CFG-RATE…), which the real F9 still accepts as deprecated, are NAKed here (not implemented).
/// Corrections count for the RTK state when a base observation message (MSM) passes its CRC and
/// a station message (1005/1006) has given the base position (before it: refPosMiss).
///
/// Moving base (dual-antenna heading, `moving_base`): a second F9P on the vehicle (MovingBase)
/// sends 4072.0 and an MSM each epoch down a wire into UART2; RoverRtk runs on its corrections
/// with the antenna separation as baseline, and RELPOSNED gives the vector from the moving
/// base's antenna to the rover's (truth + the RTK error) with isMoving, its heading and
/// accHeading. The absolute solution (NAV-PVT, GGA) stays standalone: carrSoln 0. As the
/// integration manual (UBX-18010802 §3.1.5) describes the rover: relPosValid only when the
/// epoch's time-matched observations arrived in time — here, when the epoch's MSM has its last
/// byte in UART2 by the epoch's output (`output_lag`); otherwise refObsMiss and refPosMiss.
/// relPosHeadingValid "unless the length of the relative position vector and/or its accuracy are
/// not sufficient": here when accHeading ≤ `heading_valid_max_acc_deg`.
/// Heading accuracy (ours, geometry): the error across the baseline of horizontal length L,
/// 1-sigma σ_h per axis, turns it by accHeading = atan(σ_h / L); fixed, σ_h = (CEP 0.01 m +
/// 1 ppm × L) / 1.1774 (the data sheet's RTK accuracy, RoverRtk): 0.41° at L = 1.2 m.
///
/// Raw observations (RXM-RAWX, CFG-MSGOUT-UBX_RXM_RAWX_UART1): the RTK base's observation model
/// (BaseObservables: the constellation's geometry, the same atmosphere, ambiguities held while a
/// satellite stays tracked) evaluated at the rover antenna's truth position, with the rover's own
/// signals (GPS L1 C/A and L2 CL), noise, multipath and receiver clock (`raw`, F9pRawObservables;
/// `clock_*`). So RTKLIB (or any RTK engine) gets from the base's MSM and this rover's RAWX the
/// double differences of a real short baseline: what is common cancels. rcvTow is the epoch in the
/// receiver's clock (GPS time + bias); the clock runs free at `clock_drift_ppb` and is stepped by
/// 1 ms to stay within ±0.5 ms of GPS time, each step flagged clkReset, as u-blox receivers do.
/// The RAWX observations are independent of the RTK state (RoverRtk) the NAV messages report.

#include <cstdint>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "hil/firmware_emu/device.h"
#include "hil/firmware_emu/gnss/constellation.h"
#include "hil/firmware_emu/gnss/fix_state.h"
#include "hil/firmware_emu/gnss/receiver_model.h"
#include "hil/firmware_emu/gnss/ubx_f9_config.h"
#include "hil/firmware_emu/gnss/ubx_f9_messages.h"
#include "hil/firmware_emu/gnss/ubx_f9_rawx.h"
#include "hil/firmware_emu/gnss/ubx_frame.h"
#include "hil/firmware_emu/rtk/base_observables.h"
#include "hil/firmware_emu/rtk/moving_base.h"
#include "hil/firmware_emu/rtk/rover_rtk.h"
#include "hil/firmware_emu/rtk/rtcm3_moving_base.h"
#include "hil/firmware_emu/rtk/rtcm3_station.h"
#include "hil/firmware_emu/rtk/rtcm3_stream.h"
#include "hil/firmware_emu/rtk/rtk_base_device.h"

namespace hil::rtk {

/// The standalone error grade of a ZED-F9P: horizontal 1.5 m CEP (data sheet, UBX-17051259) →
/// per-axis sigma 1.27 m; vertical 1.6 × that (ours: the NEO-5M grade's vdop_ref/hdop_ref ratio).
gnss::ReceiverModelConfig F9pStandaloneModel();

/// The rover's observation model (RXM-RAWX): GPS L1 C/A (MSM id 2 → sigId 0) and L2 CL (MSM id
/// 16 → sigId 3), every one of our satellites broadcasting L2C (ours: the synthetic sky has no
/// blocks). Numbers are ours (u-blox gives no noise figures for RAWX): a 5° tracking mask (the
/// rover reports what it tracks; RTK engines apply their own mask), code noise 0.3 m (L1) and
/// 0.4 m (L2C) at the zenith, phase noise 3 mm (a patch antenna's PLL, 1 mm above the base's),
/// code multipath 0.5 m and carrier multipath 4 mm at the horizon (an open field's ground
/// reflections from a vehicle roof), CNR 35–47 dBHz (a patch antenna, 3 dB under a geodetic one),
/// L2C 3 dB under L1. The atmosphere is the base's (`ZedF9pDevice` copies it from `radio_base`).
BaseObservablesConfig F9pRawObservables();

/// The carrSoln of an RTK state (NAV-PVT, NAV-RELPOSNED).
gnss::ubx::CarrSoln CarrSolnOf(gnss::RtkState s);

struct ZedF9pConfig {
  std::string name = "f9p0";
  Duration output_lag = std::chrono::milliseconds(50);      ///< epoch → first byte ready (ours)
  Duration response_delay = std::chrono::milliseconds(10);  ///< command → reply ready (ours)
  UnixTime start_utc{};                                     ///< UTC of scenario time 0
  gnss::ReceiverModelConfig model = F9pStandaloneModel();
  gnss::StartKind start = gnss::StartKind::kHot;
  RoverRtkConfig rtk;
  /// The base whose radio feeds UART2, and the seed of the scenario's base device; none: UART2
  /// receives nothing.
  std::optional<RtkBaseConfig> radio_base;
  std::uint64_t radio_base_seed = 0;
  /// Configuration saved in the receiver's Flash before the run (key ID → value): RAM starts
  /// from it, as after a power-up.
  std::vector<std::pair<std::uint32_t, std::uint64_t>> flash;
  /// Sky outages (start ≤ t < end): no satellite received, no fix; afterwards the receiver
  /// re-acquires (FixState) and the RTK solution converges again (float, then fixed).
  std::vector<std::pair<Time, Time>> sky_outages;
  /// A moving base on the vehicle feeding UART2 (excludes `radio_base`).
  std::optional<MovingBaseConfig> moving_base;
  /// relPosHeadingValid when accHeading is at most this (ours: the receiver documents no bound).
  double heading_valid_max_acc_deg = 5.0;
  /// The observation model of RXM-RAWX (the base's model with the rover's receiver).
  BaseObservablesConfig raw = F9pRawObservables();
  /// Receiver clock at power-up (s from GPS time) and its free-running rate (ppb): 0.1 ms and
  /// 50 ppb, a TCXO after warm-up (ours: the data sheet gives no figure).
  double clock_offset_s = 1.0e-4;
  double clock_drift_ppb = 50.0;
};

/// One RTK state change, for the report's timeline.
struct RtkTransition {
  Time t{};
  gnss::ubx::CarrSoln carr_soln = gnss::ubx::CarrSoln::kNone;
  double correction_age_s = -1;
};

/// What the rover received.
struct ZedF9pStatistics {
  std::uint64_t rtcm_frames = 0, rtcm_crc_failed = 0, epochs = 0;
  std::uint64_t epochs_fixed = 0, epochs_float = 0;
  std::uint64_t epochs_wrong_fix = 0;  ///< fixed to wrong integers (RoverRtk's wrong fixes)
  /// Moving base: epochs with relPosHeadingValid, and their heading error against the truth of
  /// the baseline (relPosHeading − true heading).
  std::uint64_t heading_valid_epochs = 0;
  double heading_error_sum_sq_deg2 = 0, heading_error_max_deg = 0, acc_heading_sum_deg = 0;
};

class ZedF9pDevice final : public Device {
 public:
  ZedF9pDevice(const ZedF9pConfig& config, std::uint64_t seed);
  const std::string& name() const override { return config_.name; }
  Time next_event_time() const override;
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override;
  void OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) override;
  int baud(int port) const override;

  const gnss::ubx::F9Epoch& last_epoch() const { return last_; }
  /// The RXM-RAWX contents of the last epoch it was due at.
  const gnss::ubx::RawxEpoch& last_rawx() const { return rawx_; }
  const gnss::GnssFix& last_fix() const { return last_.nav.fix; }
  const gnss::ubx::F9ConfigDb& config_db() const { return db_; }
  const std::vector<RtkTransition>& timeline() const { return timeline_; }
  const ZedF9pStatistics& rover_statistics() const { return stats_; }

 private:
  struct PendingFrame {
    Time t{};  // its last byte has arrived
    rtcm3::ReceivedFrame frame;
  };
  Duration Period() const;
  Time NextGridEpoch(Time after) const;
  void RunNavEpoch(const TruthSample& truth, DeviceOutput& out);
  void RadioEpoch(Time t);
  /// Feeds a serial stream of `baud` into UART2; returns when its last byte arrived.
  Time FeedUart2(const std::vector<SerialMessage>& sent, int baud);
  void MovingBaseEpoch(const TruthSample& truth);
  void ApplyMovingBase(const TruthSample& truth, double dt_s, gnss::GnssFix& fix);
  bool ReferenceKnown(int station_id) const;
  void Receive(Time t, const PendingFrame& p, DeviceOutput& out);
  void ApplyRtk(Time t, double dt_s, gnss::GnssFix& fix);
  /// The rover's raw observations at `truth` (RXM-RAWX) into `rawx_`.
  void ObserveRaw(const TruthSample& truth, const gnss::GpsWeekTime& gps, bool sky_blocked);
  void FillRelPos();
  void EmitEpoch(Time t_ready, DeviceOutput& out);
  void EmitNmea(Time t_ready, DeviceOutput& out);
  void HandleUbx(const gnss::ubx::InputMessage& m, Time t, DeviceOutput& out);
  void Push(DeviceOutput& out, Time t, std::string bytes, std::string name, bool reply = false);
  bool Enabled(std::uint32_t key) const { return db_.Get(key) != 0; }
  /// A message whose CFG-MSGOUT rate is `key` is due at this epoch.
  bool Due(std::uint32_t key) const;

  ZedF9pConfig config_;
  gnss::ubx::F9ConfigDb db_;
  gnss::ReceiverModel model_;
  gnss::Constellation constellation_;
  gnss::FixState fix_state_;
  RoverRtk rtk_;
  gnss::ubx::InputParser parser_;
  rtcm3::StreamParser uart1_rtcm_, uart2_rtcm_;
  std::unique_ptr<RtkBaseDevice> radio_base_;
  std::unique_ptr<MovingBase> moving_base_;
  std::optional<rtcm3::MovingBasePvt> moving_ref_;  // the last 4072.0 received
  bool moving_matched_ = false;       // this epoch's moving-base MSM arrived before the output
  std::deque<PendingFrame> pending_;  // frames in arrival order, handled at their time
  std::optional<rtcm3::StationInfo> station_;
  Time next_epoch_{}, last_epoch_time_{}, rx1_free_{}, rx2_free_{}, last_ready_{};
  bool first_epoch_ = true, position_known_ = false;
  std::uint64_t epoch_count_ = 0;
  gnss::ubx::F9Epoch last_;
  BaseObservables raw_obs_;
  gnss::ubx::RawxEpoch rawx_;
  double clock_steps_ = 0;  // the 1 ms steps of the receiver clock so far
  std::vector<RtkTransition> timeline_;
  ZedF9pStatistics stats_;
};

}  // namespace hil::rtk

#pragma once
/// @file
/// Decoder of the IMU microcontroller's J1939 CAN frames (vectors/can/README.md, hil_imu.dbc):
/// ARI Angular Rate Information (PGN 61482), ACCS Acceleration Sensor (61485), SSI2 Slope Sensor
/// Information 2 (61481) and the project's HIL_TIME_PULSE (65360). An independent implementation
/// from the emulator's encoder (firmware_emu), tied to it by the golden vectors.
///
/// The message codecs (`DecodeAri` …) turn 8 data bytes into engineering values; the
/// `J1939ImuDecoder` filters frames by PGN and source address, pairs the ARI and ACCS of one IMU
/// sample and turns them into `ImuSample`s on GPS time. J1939 IMU frames carry no sample time, so
/// the time is the frame's receive time (kernel timestamp) minus the latency byte, mapped onto GPS
/// time through the HIL_TIME_PULSE frames (sent at the pulse edge plus the same latency) by an
/// `ArrivalClock`, and smoothed over the periodic stream. The MCU tick latched in each pulse gives
/// the MCU crystal's offset (reported) and MCU resets (tick going back: the clocks restart). Never
/// throws on input; every rejected frame is counted by its reason.

#include <array>
#include <cstdint>
#include <optional>

#include <Eigen/Core>

#include "hil/estimator/clock_sync.h"
#include "hil/estimator/drivers/arrival_clock.h"
#include "hil/estimator/drivers/arrival_imu_increments.h"
#include "hil/estimator/samples.h"

namespace hil::estimator::drivers {

inline constexpr std::uint32_t kPgnSsi2 = 61481;          ///< 0xF029
inline constexpr std::uint32_t kPgnAri = 61482;           ///< 0xF02A
inline constexpr std::uint32_t kPgnAccs = 61485;          ///< 0xF02D
inline constexpr std::uint32_t kPgnHilTimePulse = 65360;  ///< 0xFF50, proprietary B

/// The parts of a 29-bit J1939 identifier.
struct J1939Id {
  std::uint8_t priority = 0;
  std::uint32_t pgn = 0;  ///< PDU1: destination byte cleared; PDU2: group extension included
  std::uint8_t source = 0;
  std::uint8_t destination = 0xFF;  ///< PDU1 only (0xFF = global for PDU2)
};
J1939Id ParseJ1939Id(std::uint32_t id29);

/// ARI: rates in °/s as the message defines them (pitch = −ω_y, roll = +ω_x, yaw = +ω_z of FLU).
struct AriMessage {
  double pitch_rate_dps = 0, roll_rate_dps = 0, yaw_rate_dps = 0;
  std::array<std::uint8_t, 3>
      figure_of_merit{};  ///< pitch, roll, yaw (0 ok, 1 degraded, 2 error, 3 n/a)
  double latency_s = 0;
  bool available = true;  ///< false: a rate field is ≥ 0xFB00 (error / n/a)
};
/// ACCS: specific force in m/s² (lateral = f_y, longitudinal = f_x, vertical = f_z of FLU).
struct AccsMessage {
  double lateral_mps2 = 0, longitudinal_mps2 = 0, vertical_mps2 = 0;
  std::array<std::uint8_t, 3> figure_of_merit{};  ///< lateral, longitudinal, vertical
  double latency_s = 0;
  bool available = true;
};
/// SSI2: pitch (nose up) and roll (right side down) in degrees.
struct Ssi2Message {
  double pitch_deg = 0, roll_deg = 0;
  std::uint8_t pitch_compensation = 3, pitch_figure_of_merit = 3, roll_compensation = 3,
               roll_figure_of_merit = 3;
  double latency_s = 0;
  bool available = true;
};
/// HIL_TIME_PULSE: the MCU tick latched at a GPS time pulse edge.
struct HilTimePulseMessage {
  std::uint32_t tick = 0;
  std::uint32_t gps_tow_s = 0;  ///< whole seconds; meaningful when `time_valid`
  std::uint16_t gps_week_mod4096 = 0;
  bool time_valid = false;  ///< TOW field not all ones and < 604800
};

/// The codecs; nullopt when fewer than 8 data bytes.
std::optional<AriMessage> DecodeAri(const std::uint8_t* data, std::size_t len);
std::optional<AccsMessage> DecodeAccs(const std::uint8_t* data, std::size_t len);
std::optional<Ssi2Message> DecodeSsi2(const std::uint8_t* data, std::size_t len);
std::optional<HilTimePulseMessage> DecodeHilTimePulse(const std::uint8_t* data, std::size_t len);

/// Angular rate and specific force of the IMU frame (FLU) from one ARI + ACCS pair.
Eigen::Vector3d AngularRateFlu_radps(const AriMessage& ari);
Eigen::Vector3d SpecificForceFlu_mps2(const AccsMessage& accs);

/// One received CAN frame.
struct CanRxFrame {
  std::uint32_t id = 0;  ///< 29-bit (extended) or 11-bit identifier
  bool extended = true;
  std::uint8_t len = 0;
  std::array<std::uint8_t, 8> data{};
  std::int64_t rx_ns = 0;  ///< receive time on the host clock (monotonic)
};

struct J1939ImuDecoderConfig {
  std::uint8_t source_address = 0xE2;  ///< the MCU's J1939 source address
  bool any_source = false;             ///< accept every source address
  double max_gap_s = 0.5;              ///< a longer gap between samples restarts the integration
  double pair_window_s =
      0.05;  ///< ARI and ACCS of one sample arrive within this (< the IMU period)
  double default_latency_s = 0.001;  ///< pulse latency until an IMU frame tells it
};

struct J1939ImuStats : ArrivalImuCounts {
  std::uint64_t frames = 0, not_extended = 0, other_source = 0, unknown_pgn = 0, bad_length = 0;
  std::uint64_t not_available = 0;  ///< IMU messages with an error / n/a field
  std::uint64_t ari = 0, accs = 0, ssi2 = 0, pulses = 0, pulses_no_time = 0;
  std::uint64_t unpaired = 0;      ///< ARI without its ACCS, or ACCS without its ARI
  std::uint64_t out_of_order = 0;  ///< receive time going back
  std::uint64_t mcu_resets = 0;
};

class J1939ImuDecoder {
 public:
  explicit J1939ImuDecoder(J1939ImuDecoderConfig config = {})
      : config_(config), imu_(config.max_gap_s) {}
  /// Consumes one frame; returns an IMU sample when the frame completes one.
  std::optional<ImuSample> Add(const CanRxFrame& frame);
  const J1939ImuStats& stats() const { return stats_; }
  /// Host receive clock → GPS time.
  const ArrivalClock& arrival_clock() const { return arrival_; }
  /// MCU tick → GPS time (from the pulses' latched ticks); gives the crystal offset.
  const ClockSync& mcu_clock() const { return mcu_clock_; }
  /// The latest SSI2 message (levelling aid), if any.
  const std::optional<Ssi2Message>& last_slope() const { return last_slope_; }

 private:
  void OnPulse(const HilTimePulseMessage& p, std::int64_t rx_ns);
  std::optional<ImuSample> OnPair(const AriMessage& ari, const AccsMessage& accs,
                                  std::int64_t rx_ns);

  J1939ImuDecoderConfig config_;
  J1939ImuStats stats_;
  ArrivalClock arrival_;
  ClockSync mcu_clock_;
  bool have_tick_ = false;
  std::uint32_t last_tick_ = 0;
  double latency_s_ = -1;
  std::int64_t last_rx_ns_ = 0;
  bool have_rx_ = false;
  std::optional<AriMessage> pending_ari_;
  std::int64_t pending_ari_rx_ns_ = 0;
  std::optional<Ssi2Message> last_slope_;
  ArrivalImuIncrements imu_;
};

}  // namespace hil::estimator::drivers

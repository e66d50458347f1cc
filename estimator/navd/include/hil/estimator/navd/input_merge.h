#pragma once
/// @file
/// navd's input merge ([input] merge_window_s, off by default): what the decoders produce on all
/// links (GNSS epochs, MCU frames with their IMU samples, J1939 IMU samples) goes on to the filter
/// and the health counters in device-time order, each item held until the newest IMU sample is
/// `window` past it (or, while no IMU sample comes, the newest GNSS epoch twice that). The filter
/// then sees the same sequence whatever the order in which the links were read, as long as no
/// link is read more than window − (the longest GNSS link delay) ahead of another: a host that
/// hands the links over in batches (hil's virtual mode) gets the same solutions as one that sees
/// every message at once. Each item carries its own link's decoder counters as they were when it
/// was decoded, and a released item's counters are what the health object reports, so those do
/// not depend on how far the other link was read either.
/// Ties: at one time IMU items come before GNSS epochs (their bytes are made first), receivers in
/// index order, one link's items in arrival order. An item older than what was already released
/// (a link more than the window late) goes on at once. The cost: solutions leave `window` later;
/// off (0) every item goes on as it is decoded. Fixed capacity: when `capacity` items are held the
/// oldest goes on.

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "hil/estimator/drivers/j1939_imu_decoder.h"
#include "hil/estimator/drivers/mcu_frame_decoder.h"
#include "hil/estimator/drivers/mcu_imu_adapter.h"
#include "hil/estimator/drivers/nmea_decoder.h"
#include "hil/estimator/drivers/ubx_decoder.h"
#include "hil/estimator/samples.h"

namespace hil::estimator {

/// The decoder counters of each link as of the last item released from it.
struct MergedCounters {
  drivers::NmeaDecoderStats nmea;
  drivers::UbxDecoderStats ubx;
  drivers::McuDecoderStats mcu;
  drivers::McuAdapterStats mcu_adapter;
  drivers::J1939ImuStats j1939;
};

/// One decoded input with its link's counters when it was decoded.
struct MergeItem {
  enum class Kind : std::uint8_t { kImu = 0, kGnss = 1 };
  Kind kind = Kind::kImu;
  GpsTime t{};
  int link = 0;             ///< GNSS: the receiver index; IMU: 0
  std::uint64_t seq = 0;    ///< arrival order (set by InputMerge)
  bool from_mcu = false;    ///< IMU: an MCU frame (frame, mcu, mcu_adapter); else a J1939 sample
  drivers::McuFrame frame;  ///< from_mcu: the frame (the health counters take every frame)
  std::optional<ImuSample> imu;  ///< the IMU sample (an MCU frame may have none)
  GnssSample gnss;
  drivers::NmeaDecoderStats nmea;
  drivers::UbxDecoderStats ubx;
  drivers::McuDecoderStats mcu;
  drivers::McuAdapterStats mcu_adapter;
  drivers::J1939ImuStats j1939;
};

class InputMerge {
 public:
  using Release = std::function<void(const MergeItem&)>;
  /// `window` 0: every item is released as it is added.
  InputMerge(Nanoseconds window, std::size_t capacity, Release release);
  bool enabled() const { return window_ > Nanoseconds{0}; }
  /// An item as it is decoded (its t, for an MCU frame without a sample: the last IMU time).
  void Add(MergeItem item);
  /// Releases everything held, in order (at shutdown).
  void ReleaseAll();
  std::size_t held() const { return items_.size() - head_; }
  /// The counters of the items released so far, per link kind.
  const MergedCounters& counters() const { return counters_; }

 private:
  void ReleaseUpTo(GpsTime watermark);
  void ReleaseFront();
  void Pass(const MergeItem& m);

  Nanoseconds window_;
  std::size_t capacity_;
  Release release_;
  std::vector<MergeItem> items_;  // sorted from head_ on; reserved once
  std::size_t head_ = 0;
  std::uint64_t next_seq_ = 0;
  std::optional<GpsTime> newest_imu_, newest_gnss_, released_to_;
  MergedCounters counters_;
};

}  // namespace hil::estimator

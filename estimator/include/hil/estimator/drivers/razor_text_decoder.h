#pragma once
/// @file
/// Tolerant decoder of the 9DOF Razor IMU v13 stock text lines (vectors/mcu/razor_text_formats.md):
///   raw  `$,ax,ay,az,gx,gy,gz,mx,my,mz,#` (then CR LF)
///   v19  `!Data:ax,ay,az,gx,gy,gz,mx,my,mz#` (then LF CR)
/// Nine signed decimal integers: ADXL345 counts, raw 10-bit gyro ADC readings, HMC5843 counts.
/// Bytes may arrive in any pieces; bytes outside a line are counted as garbage (line ends are not);
/// a line that is malformed, out of range, too long or cut by a new start is counted and dropped.
/// No allocation; never throws on input. The lines carry no time: the caller stamps them.

#include <array>
#include <cstdint>
#include <functional>
#include <string_view>

#include <Eigen/Core>

namespace hil::estimator::drivers {

/// One decoded line.
struct RazorTextSample {
  enum class Format : std::uint8_t { kRaw, kV19 } format = Format::kRaw;
  std::array<int, 3> accel_counts{};  ///< ADXL345, −512 … 511
  std::array<int, 3> gyro_adc{};      ///< 10-bit ADC, 0 … 1023
  std::array<int, 3> mag_counts{};    ///< HMC5843, −4096 … 2047
};

/// Conversion to engineering units (defaults: the stock board, razor_text_formats.md).
struct RazorScales {
  double accel_mps2_per_count = 9.80665 / 256.0;
  double gyro_zero_adc = 382.0;
  double gyro_dps_per_adc = (3.3 / 1024.0) / 3.33e-3;
  double mag_uT_per_count = 100.0 / 1300.0;
};

Eigen::Vector3d RazorAccel_mps2(const RazorTextSample& s, const RazorScales& k = {});
Eigen::Vector3d RazorGyro_radps(const RazorTextSample& s, const RazorScales& k = {});
Eigen::Vector3d RazorMag_uT(const RazorTextSample& s, const RazorScales& k = {});

struct RazorTextStats {
  std::uint64_t lines_ok = 0, bad_lines = 0, garbage_bytes = 0;
};

class RazorTextDecoder {
 public:
  using Handler = std::function<void(const RazorTextSample&)>;
  explicit RazorTextDecoder(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const RazorTextStats& stats() const { return stats_; }

  /// Parses one complete line (start character through `#`, no line end); false when malformed.
  static bool ParseLine(std::string_view line, RazorTextSample& out);

 private:
  static constexpr std::size_t kMaxLine = 80;
  Handler handler_;
  RazorTextStats stats_;
  std::array<char, kMaxLine> buf_{};
  std::size_t len_ = 0;
  bool in_line_ = false;
};

}  // namespace hil::estimator::drivers

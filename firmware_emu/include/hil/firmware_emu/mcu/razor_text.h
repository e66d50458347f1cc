#pragma once
/// @file
/// The stock SparkFun 9DOF Razor IMU (v13) firmware's text output lines, for compatibility with
/// hosts written for that board (format documented in vectors/mcu/razor_text_formats.md):
///  - kRaw: `$,ax,ay,az,gx,gy,gz,mx,my,mz,#\r\n` ("9DOF Serial" raw output, menu [4]);
///  - kV19: `!Data:ax,ay,az,gx,gy,gz,mx,my,mz#\n\r` (firmware v19 raw/autorun frame).
/// Accelerometer and compass in register counts, gyros as raw 10-bit ADC readings; decimal.

#include <array>
#include <cstdint>
#include <string>

namespace hil::mcu {

enum class RazorTextFormat { kRaw, kV19 };

/// One line of the chosen format, terminator included.
std::string EncodeRazorLine(RazorTextFormat format, const std::array<int, 3>& accel,
                            const std::array<int, 3>& gyro_adc, const std::array<int, 3>& mag);

}  // namespace hil::mcu

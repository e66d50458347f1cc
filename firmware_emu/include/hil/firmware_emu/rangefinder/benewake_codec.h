#pragma once
/// @file
/// Field meaning of the Benewake frames (seeds_001_003.md §C.3.1; TF-Luna manual SJ-PM-TF-Luna
/// A05, TFmini-S SJ-PM-TFmini-S A01): the data frame's distance, strength (Amp) and chip
/// temperature (°C = raw/8 − 256), all little-endian u16; the command IDs and their payloads.
/// Framing is benewake_framing.h.

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace hil::rangefinder {

/// Command IDs (TF-Luna manual).
enum class CommandId : std::uint8_t {
  kVersion = 0x01,
  kSystemReset = 0x02,
  kFrameRate = 0x03,
  kTrigger = 0x04,
  kOutputFormat = 0x05,
  kBaudRate = 0x06,
  kOutputEnable = 0x07,
  kRestoreDefaults = 0x10,
  kSave = 0x11,
};

/// Output formats (payload of kOutputFormat).
enum class OutputFormat : std::uint8_t { kCm9Byte = 0x01, kPixAscii = 0x02, kMm9Byte = 0x06 };

/// The values of one data frame, raw.
struct DataFields {
  std::uint16_t dist = 0;  ///< cm (kCm9Byte) or mm (kMm9Byte)
  std::uint16_t amp = 0;
  std::uint16_t temp_raw = 0;  ///< °C = temp_raw / 8 − 256
};

std::array<std::uint8_t, 6> EncodeDataFields(const DataFields& f);
/// Fields of a framed 9-byte data frame (header and checksum not checked here).
DataFields DecodeDataFields(std::string_view frame);
/// raw = (°C + 256) · 8, rounded and clamped to u16.
std::uint16_t TemperatureToRaw(double temperature_c);
double TemperatureFromRaw(std::uint16_t raw);
/// PIX format: the distance in metres with two decimals and CR LF ("0.50\r\n").
std::string PixLine(double distance_m);

/// Payload encoders and decoders of the commands with arguments (little-endian).
std::string U16Payload(std::uint16_t v);
std::string U32Payload(std::uint32_t v);
std::optional<std::uint16_t> PayloadU16(std::string_view payload);
std::optional<std::uint32_t> PayloadU32(std::string_view payload);

/// Baud rates the TF-Luna manual lists for kBaudRate.
bool IsSupportedBaud(std::uint32_t baud);

}  // namespace hil::rangefinder

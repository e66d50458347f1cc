#pragma once
/// @file
/// HIL-UWB-TDOA0: the project's own frame for raw TDOA differences (no standard TDOA tag frame was
/// found: seeds_001_003.md §C.2.3). Specified in vectors/uwb/README.md; 24 bytes, little-endian:
///
/// | offset | size | field |
/// |---|---|---|
/// | 0 | 2 | 0x55 0xD7 (header, mark: shares NLink's 0x55 header; no NLink frame uses 0xD7) |
/// | 2 | 1 | tag id |
/// | 3 | 1 | n = number of differences (3: BS2, BS3, BS4 against BS1) |
/// | 4 | 4 | system_time (uint32, ms since power-on) |
/// | 8 | 4·3 | t_i1 = t_i − t_1 (int32, picoseconds), i = 2, 3, 4 |
/// | 20 | 3 | reserved (0) |
/// | 23 | 1 | sum-8 of bytes 0–22 |
///
/// Range differences r_i1 = c·t_i1 with c = 3×10⁸ m/s exactly (paper 003, eq. 3): 1 ps = 0.3 mm.

#include <array>
#include <cstdint>
#include <string>

namespace hil::uwb {

inline constexpr std::size_t kTdoaFrameSize = 24;
inline constexpr std::uint8_t kTdoaFrameHeader = 0x55, kTdoaFrameMark = 0xD7;
inline constexpr std::size_t kTdoaDifferences = 3;
inline constexpr double kTdoaSpeedOfLight_mps = 3.0e8;

struct TdoaFrame {
  std::uint8_t id = 0;
  std::uint32_t system_time_ms = 0;
  std::array<std::int32_t, kTdoaDifferences> t_i1_ps{};
};

/// Picoseconds of a range difference (rounded, saturated to int32: ±644 km).
std::int32_t TdoaPicoseconds(double r_i1_m);
std::string EncodeTdoaFrame(const TdoaFrame& f);

}  // namespace hil::uwb

#pragma once
/// @file
/// A seeded random source whose output is fixed by the C++ standard (std::mt19937_64) plus
/// transforms written here (uniform from 53 bits, Box–Muller normals), so golden vectors do not
/// depend on the standard library's distribution implementations.

#include <cstdint>
#include <random>

namespace hil::mcu {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [0, 1).
  double Uniform();
  /// Standard normal N(0, 1).
  double Normal();
  /// A derived seed for an independent stream (the engine advances by one draw).
  std::uint64_t NextSeed() { return engine_(); }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0;
};

}  // namespace hil::mcu

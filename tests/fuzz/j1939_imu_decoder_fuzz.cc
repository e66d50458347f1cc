// Fuzz target: navd's J1939 IMU decoder (ARI / ACCS / SSI2 / HIL_TIME_PULSE → IMU samples on GPS
// time) survives any frame sequence with any receive times. Input: candump -l text (the seed corpus
// vectors/can/*.candump) when it starts with '(', else binary records of 15 bytes
// (id u32 LE, flags: bit 7 extended + len in bits 0-3, 8 data bytes, receive-time step u16 LE µs).
// Checked: every frame is counted once, every IMU sample is finite with 0 < dt ≤ max_gap.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "hil/estimator/drivers/j1939_imu_decoder.h"

namespace {

using hil::estimator::drivers::CanRxFrame;
using hil::estimator::drivers::J1939ImuDecoder;

void Check(J1939ImuDecoder& dec, const CanRxFrame& f, std::uint64_t& fed) {
  const auto s = dec.Add(f);
  ++fed;
  if (dec.stats().frames != fed) std::abort();
  if (!s) return;
  if (!(s->dt_s > 0 && s->dt_s <= 0.5)) std::abort();
  if (!s->delta_angle_B_rad.allFinite() || !s->delta_velocity_B_mps.allFinite()) std::abort();
  // |ω| ≤ √3 · 263 °/s, |f| ≤ √3 · 336 m/s²: the fields' ranges
  if (s->delta_angle_B_rad.norm() > 8.0 * s->dt_s ||
      s->delta_velocity_B_mps.norm() > 600.0 * s->dt_s)
    std::abort();
}

int Hex(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

// lenient candump -l: "(secs.micros) iface ID#HEX"
void FeedText(std::string_view text, J1939ImuDecoder& dec, std::uint64_t& fed) {
  while (!text.empty()) {
    const std::size_t nl = text.find('\n');
    const std::string_view line = text.substr(0, nl);
    text = nl == std::string_view::npos ? std::string_view() : text.substr(nl + 1);
    const std::size_t close = line.find(')'), hash = line.find('#');
    if (line.size() < 2 || line[0] != '(' || close == std::string_view::npos ||
        hash == std::string_view::npos)
      continue;
    const std::size_t sp = line.rfind(' ', hash);
    if (sp == std::string_view::npos || sp < close) continue;
    CanRxFrame f;
    std::int64_t sec = 0, usec = 0;
    bool frac = false;
    for (std::size_t i = 1; i < close; ++i) {
      if (line[i] == '.')
        frac = true;
      else if (line[i] >= '0' && line[i] <= '9')
        (frac ? usec : sec) = ((frac ? usec : sec) % 100000000000LL) * 10 + (line[i] - '0');
    }
    f.rx_ns = (sec % 4000000000LL) * 1000000000LL +
              (usec % 1000000) * 1000;  // candump seconds, kept in range
    std::uint32_t id = 0;
    for (std::size_t i = sp + 1; i < hash; ++i)
      id = (id << 4) | static_cast<std::uint32_t>(Hex(line[i]) & 0xF);
    f.id = id;
    f.extended = hash - sp - 1 == 8;
    std::size_t n = 0;
    for (std::size_t i = hash + 1; i + 1 < line.size() && n < 8; i += 2) {
      const int hi = Hex(line[i]), lo = Hex(line[i + 1]);
      if (hi < 0 || lo < 0) break;
      f.data[n++] = static_cast<std::uint8_t>(hi * 16 + lo);
    }
    f.len = static_cast<std::uint8_t>(n);
    Check(dec, f, fed);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  J1939ImuDecoder dec;
  std::uint64_t fed = 0;
  if (size > 0 && data[0] == '(') {
    FeedText(std::string_view(reinterpret_cast<const char*>(data), size), dec, fed);
    return 0;
  }
  std::int64_t rx = 0;
  for (std::size_t i = 0; i + 15 <= size; i += 15) {
    const std::uint8_t* r = data + i;
    CanRxFrame f;
    f.id = static_cast<std::uint32_t>(r[0]) | (static_cast<std::uint32_t>(r[1]) << 8) |
           (static_cast<std::uint32_t>(r[2]) << 16) | (static_cast<std::uint32_t>(r[3]) << 24);
    f.extended = (r[4] & 0x80) != 0;
    f.len = static_cast<std::uint8_t>(r[4] & 0x0F);
    for (std::size_t k = 0; k < 8; ++k) f.data[k] = r[5 + k];
    const int step = static_cast<int>(r[13]) | (static_cast<int>(r[14]) << 8);
    rx += (step - 1024) * 1000LL;  // steps back are allowed: out-of-order receive times
    f.rx_ns = rx;
    Check(dec, f, fed);
  }
  return 0;
}

// hil validate --protocol mcu: the MCU frame protocol v1 (vectors/mcu/mcu_frame_protocol.md):
// sync A5 5A, version 1, type and its payload length, CRC-16/CCITT-FALSE, sequence continuity
// (resets allowed: restart at 0 with a STATUS whose reset count grew), per-type tick monotonicity,
// IMU rate against the STATUS nominal period, TIME_PULSE spacing (1 s of GPS time, ≈1e6 ticks).
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <span>

#include "hil/firmware_emu/little_endian.h"
#include "hil/firmware_emu/mcu/mcu_frame.h"
#include "hil/harness/validate/validate.h"

#include "garbage_run.h"

namespace hil::harness {
namespace {

constexpr double kMaxTickRateErrorPpm = 500.0;  // crystal ±100 ppm plus margin
constexpr double kMaxImuRateError = 0.02;

struct TypeSpec {
  const char* name;
  int length;
};
const std::map<int, TypeSpec> kTypes{
    {1, {"IMU_SAMPLE", 12}}, {2, {"MAG_SAMPLE", 6}}, {3, {"TIME_PULSE", 7}}, {4, {"STATUS", 26}}};

// What the checks carry from frame to frame (the ticks and the pulse since the last reset).
struct McuStreamState {
  std::optional<std::uint16_t> last_seq;
  std::optional<std::uint16_t> reset_count;
  std::map<int, std::uint32_t> last_tick;
  std::map<int, std::vector<double>> ticks;  // unwrapped, per type, since the last reset
  std::map<int, std::uint64_t> wrap;
  std::optional<std::uint32_t> imu_period_ticks;
  bool have_pulse = false;
  std::uint32_t pulse_tow_ms = 0, pulse_tick = 0;
};

// The checks of one well-formed frame of `type` at `pos` (stream offset `off`): STATUS and resets,
// sequence continuity, tick monotonicity per type, TIME_PULSE spacing.
void CheckFrame(const std::string& b, std::size_t pos, int type, const char* name, std::int64_t off,
                McuStreamState& st, ValidationReport& rep) {
  const auto seq = LeRead<std::uint16_t>(b, pos + 5);
  const std::uint32_t tick = LeRead<std::uint32_t>(b, pos + 7);
  const std::size_t p = pos + 11;
  bool reset = false;
  if (type == 4) {  // STATUS
    const auto count = LeRead<std::uint16_t>(b, p + 2);
    reset = seq == 0 && (!st.reset_count || count > *st.reset_count);
    if (seq == 0 && st.reset_count && count <= *st.reset_count) {
      rep.findings.push_back(
          {true, "reset", "sequence restarted at 0 without a higher reset count", off});
    }
    st.reset_count = count;
    st.imu_period_ticks = LeRead<std::uint32_t>(b, p + 8);
    if (LeRead<std::uint32_t>(b, p + 4) != 1000000)
      rep.findings.push_back({true, "status", "nominal tick rate is not 1 MHz", off});
  }
  if (reset) {
    st.last_tick.clear();
    st.ticks.clear();
    st.wrap.clear();
    st.have_pulse = false;
  } else if (st.last_seq && seq != static_cast<std::uint16_t>(*st.last_seq + 1)) {
    rep.findings.push_back({true, "sequence_gap",
                            std::to_string(static_cast<std::uint16_t>(seq - *st.last_seq - 1)) +
                                " frame(s) missing before sequence " + std::to_string(seq),
                            off});
  }
  st.last_seq = seq;
  if (const auto it = st.last_tick.find(type); it != st.last_tick.end()) {
    const std::uint32_t d = tick - it->second;  // modulo 2^32
    if (d == 0 || d > 0x80000000u) {
      rep.findings.push_back(
          {true, "tick_monotonic", std::string(name) + " tick did not increase", off});
    } else if (tick < it->second) {
      st.wrap[type] += 1ull << 32;
    }
  }
  st.last_tick[type] = tick;
  st.ticks[type].push_back(static_cast<double>(st.wrap[type] + tick));
  if (type == 3) {  // TIME_PULSE
    const std::uint32_t tow = LeRead<std::uint32_t>(b, p + 2);
    const bool valid = (static_cast<unsigned char>(b[p + 6]) & 1) != 0;
    if (valid && tow % 1000 != 0)
      rep.findings.push_back({true, "time_pulse", "pulse TOW is not a whole second", off});
    if (valid && st.have_pulse && tow > st.pulse_tow_ms) {
      const double ds = (tow - st.pulse_tow_ms) * 1e-3;
      const double rate =
          static_cast<double>(static_cast<std::uint32_t>(tick - st.pulse_tick)) / ds;
      if (std::abs(rate / 1e6 - 1.0) * 1e6 > kMaxTickRateErrorPpm) {
        char msg[96];
        std::snprintf(msg, sizeof msg, "tick rate between pulses %.0f Hz (nominal 1 MHz)", rate);
        rep.findings.push_back({true, "time_pulse", msg, off});
      }
    }
    if (valid) {
      st.have_pulse = true;
      st.pulse_tow_ms = tow;
      st.pulse_tick = tick;
    }
  }
}

// Each type's rate over the ticks, and the IMU rate against the STATUS nominal period.
void CheckRates(const McuStreamState& st, ValidationReport& rep) {
  for (const auto& [type, t] : st.ticks) {
    if (t.size() < 2 || t.back() <= t.front()) continue;
    const std::string name = kTypes.at(type).name;
    rep.messages[name].rate_hz =
        static_cast<double>(t.size() - 1) / ((t.back() - t.front()) * 1e-6);
  }
  if (st.imu_period_ticks && *st.imu_period_ticks > 0 && rep.messages.count("IMU_SAMPLE") &&
      rep.messages["IMU_SAMPLE"].rate_hz > 0) {
    const double expected = 1e6 / *st.imu_period_ticks, got = rep.messages["IMU_SAMPLE"].rate_hz;
    rep.epoch_rate_hz = got;
    if (std::abs(got / expected - 1.0) > kMaxImuRateError) {
      char msg[96];
      std::snprintf(msg, sizeof msg, "IMU rate %.3f Hz, STATUS says %.3f Hz", got, expected);
      rep.findings.push_back({true, "rate", msg, -1});
    }
  }
}

}  // namespace

ValidationReport ValidateMcuStream(const ByteStream& s) {
  ValidationReport rep;
  rep.protocol = "mcu";
  rep.description = s.description;
  rep.bytes = s.bytes.size();
  const std::string& b = s.bytes;
  McuStreamState st;
  std::size_t pos = 0;
  GarbageRun garbage;
  const auto flush = [&](std::size_t end) { rep.garbage_bytes += garbage.End(end, rep); };
  while (pos < b.size()) {
    if (!(static_cast<unsigned char>(b[pos]) == 0xA5 && pos + 1 < b.size() &&
          static_cast<unsigned char>(b[pos + 1]) == 0x5A)) {
      garbage.Add(pos);
      ++pos;
      continue;
    }
    flush(pos);
    const auto off = static_cast<std::int64_t>(pos);
    if (pos + 13 > b.size()) {
      rep.findings.push_back({false, "truncated", "frame cut off at the end of the stream", off});
      break;
    }
    const int version = static_cast<unsigned char>(b[pos + 2]),
              type = static_cast<unsigned char>(b[pos + 3]);
    const std::size_t n = static_cast<unsigned char>(b[pos + 4]);
    const auto spec = kTypes.find(type);
    if (version != 1 || spec == kTypes.end() || static_cast<int>(n) != spec->second.length) {
      char msg[96];
      std::snprintf(msg, sizeof msg,
                    "frame with version %d, type 0x%02X, length %zu is not in the protocol",
                    version, type, n);
      rep.findings.push_back({true, "frame_header", msg, off});
      ++rep.bad_frames;
      pos += 1;
      continue;
    }
    if (pos + 13 + n > b.size()) {
      rep.findings.push_back({false, "truncated", "frame cut off at the end of the stream", off});
      break;
    }
    if (mcu::Crc16CcittFalse(std::span(reinterpret_cast<const std::uint8_t*>(b.data()) + pos + 2,
                                       9 + n)) != LeRead<std::uint16_t>(b, pos + 11 + n)) {
      rep.findings.push_back(
          {true, "checksum", std::string(spec->second.name) + " CRC mismatch", off});
      ++rep.bad_frames;
      pos += 1;
      continue;
    }
    ++rep.frames;
    rep.messages[spec->second.name].count++;
    CheckFrame(b, pos, type, spec->second.name, off, st, rep);
    pos += 13 + n;
  }
  flush(pos < b.size() ? pos : b.size());
  CheckRates(st, rep);
  CheckLineRate(s, rep);
  rep.epochs = rep.messages.count("TIME_PULSE") ? rep.messages["TIME_PULSE"].count : 0;
  if (rep.frames == 0) rep.findings.push_back({true, "empty", "no valid frame in the stream", -1});
  return rep;
}

}  // namespace hil::harness

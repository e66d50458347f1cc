#include "hil/harness/datasets/capture_imu.h"

#include <cmath>
#include <cstring>
#include <optional>
#include <span>
#include <stdexcept>

#include "hil/firmware_emu/little_endian.h"
#include "hil/firmware_emu/mcu/mcu_frame.h"
#include "hil/harness/links/capture_format.h"

namespace hil::harness {
namespace {

struct RawSample {
  std::int64_t tick;
  Eigen::Vector3d w, a;
};
struct Pulse {
  std::int64_t tick;
  double t_gps_s;
};

// one well-formed frame's content (type, unwrapped tick, payload offset), in stream order
class Decoder {
 public:
  explicit Decoder(CaptureImu& out) : out_(out) {}

  void Frame(const std::string& b, std::int64_t t_emu_ns) {
    if (b.size() < 13 || b[0] != '\xa5' || b[1] != '\x5a' ||
        b.size() != 13u + static_cast<unsigned char>(b[4]) ||
        mcu::Crc16CcittFalse(std::span(reinterpret_cast<const std::uint8_t*>(b.data()) + 2,
                                       b.size() - 4)) != LeRead<std::uint16_t>(b, b.size() - 2)) {
      ++out_.bad_frames;
      return;
    }
    ++out_.frames;
    const int type = b[3];
    const auto seq = LeRead<std::uint16_t>(b, 5);
    const std::uint32_t raw = LeRead<std::uint32_t>(b, 7);
    if (type == 4 && seq == 0 && have_tick_) Reset();
    if (have_tick_ && raw < last_raw_ && last_raw_ - raw > 0x80000000u) wraps_ += 1LL << 32;
    have_tick_ = true;
    last_raw_ = raw;
    const std::int64_t tick = wraps_ + raw;
    if (type == 4) {
      float a = 0, g = 0;
      std::uint32_t u = LeRead<std::uint32_t>(b, 11 + 12);
      std::memcpy(&a, &u, 4);
      u = LeRead<std::uint32_t>(b, 11 + 16);
      std::memcpy(&g, &u, 4);
      accel_scale_ = a;
      gyro_scale_ = g;
    } else if (type == 3 && (b[11 + 6] & 1)) {
      const double t =
          LeRead<std::uint16_t>(b, 11) * 604800.0 + LeRead<std::uint32_t>(b, 13) * 1e-3;
      if (out_.pulses == 0)
        out_.gps_at_emulated_zero_s = t - std::floor(static_cast<double>(t_emu_ns) * 1e-9);
      pulses_.push_back({tick, t});
      ++out_.pulses;
    } else if (type == 1 && accel_scale_ > 0) {
      RawSample s{tick, {}, {}};
      for (int k = 0; k < 3; ++k) {
        s.a[k] = LeRead<std::int16_t>(b, 11 + 2 * k) * static_cast<double>(accel_scale_);
        s.w[k] = LeRead<std::int16_t>(b, 17 + 2 * k) * static_cast<double>(gyro_scale_);
      }
      segment_.push_back(s);
    }
  }

  // the samples of the current reset segment as increments on GPS time
  void Flush() {
    std::optional<std::pair<double, RawSample>> prev;
    std::size_t pulse = 0;  // samples come in tick order: the pulse index only moves forward
    for (const RawSample& s : segment_) {
      const std::optional<double> t = ToGps(s.tick, pulse);
      if (!t) {
        ++out_.before_first_pulse;
        continue;
      }
      out_.points.push_back({*t, s.w, s.a});
      if (prev) {
        CaptureImuSample o;
        o.t_gps_s = *t;
        o.dt_s = *t - prev->first;
        o.dtheta_flu_rad = 0.5 * (prev->second.w + s.w) * o.dt_s;
        o.dvel_flu_mps = 0.5 * (prev->second.a + s.a) * o.dt_s;
        if (o.dt_s > 0) out_.samples.push_back(o);
      }
      prev = {*t, s};
    }
    segment_.clear();
    pulses_.clear();
  }

 private:
  void Reset() {
    Flush();
    ++out_.resets;
    wraps_ = 0;
  }

  std::optional<double> ToGps(std::int64_t tick, std::size_t& i) const {
    if (pulses_.empty() || tick < pulses_.front().tick) return std::nullopt;
    while (i + 2 < pulses_.size() && pulses_[i + 1].tick <= tick) ++i;
    const Pulse& a = pulses_[i];
    if (i + 1 >= pulses_.size()) return a.t_gps_s + static_cast<double>(tick - a.tick) * 1e-6;
    const Pulse& b = pulses_[i + 1];
    const double rate = static_cast<double>(b.tick - a.tick) / (b.t_gps_s - a.t_gps_s);
    return a.t_gps_s + static_cast<double>(tick - a.tick) / rate;
  }

  CaptureImu& out_;
  bool have_tick_ = false;
  std::uint32_t last_raw_ = 0;
  std::int64_t wraps_ = 0;
  float accel_scale_ = 0, gyro_scale_ = 0;
  std::vector<RawSample> segment_;
  std::vector<Pulse> pulses_;
};

}  // namespace

CaptureImu ReadCaptureImu(const std::string& path) {
  const Capture cap = ReadCapture(path);
  CaptureImu out;
  Decoder d(out);
  for (const CaptureRecord& r : cap.records)
    if (r.dir == CaptureDir::kTx) d.Frame(r.bytes, r.t_emu_ns);
  d.Flush();
  if (out.pulses == 0) throw std::runtime_error(path + ": no TIME_PULSE frame: no GPS time");
  return out;
}

}  // namespace hil::harness

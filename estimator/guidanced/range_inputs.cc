#include "range_inputs.h"

#include <fcntl.h>
#include <termios.h>
#include <unistd.h>

#include <cmath>
#include <memory>

namespace hil::guidanced {
namespace {

namespace drv = hil::estimator::drivers;

speed_t Speed(int baud) {
  switch (baud) {
    case 9600:
      return B9600;
    case 57600:
      return B57600;
    case 230400:
      return B230400;
    case 460800:
      return B460800;
    case 921600:
      return B921600;
    default:
      return B115200;
  }
}

}  // namespace

void RangeInputs::Configure(bool tfmini_s, double rate_hz, int baud,
                            std::optional<estimator::GpsTime> start) {
  period_ = estimator::Nanoseconds{std::llround(1e9 / rate_hz)};
  transfer_ = estimator::Nanoseconds{std::llround(1e9 * 10.0 * kFrameBytes / baud)};
  start_ = start;
  drained_ = false;
  overflows_ = 0;
  for (std::size_t k = 0; k < kUnits; ++k) {
    units_[k] = Unit{};
    decoders_[k] = std::make_unique<drv::BenewakeDecoder>(
        tfmini_s ? drv::BenewakeModel::kTfminiS : drv::BenewakeModel::kTfLuna,
        [this, k](const drv::BenewakeRange& r) { Push(k, r); });
  }
}

bool RangeInputs::Open(const std::array<std::string, kUnits>& paths, int baud, bool tfmini_s,
                       double rate_hz, std::optional<estimator::GpsTime> start) {
  Configure(tfmini_s, rate_hz, baud, start);
  for (std::size_t k = 0; k < kUnits; ++k) {
    fds_[k] = open(paths[k].c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
    if (fds_[k] < 0) return false;
    termios t{};
    if (tcgetattr(fds_[k], &t) == 0) {
      cfmakeraw(&t);
      cfsetispeed(&t, Speed(baud));
      cfsetospeed(&t, Speed(baud));
      tcsetattr(fds_[k], TCSANOW, &t);
    }
  }
  return true;
}

// The frame's number from the place of its last byte in the stream (nearest whole frame).
void RangeInputs::Push(std::size_t k, const drv::BenewakeRange& r) {
  const std::uint64_t end = decoders_[k]->frame_end_bytes();
  Unit& u = units_[k];
  if (u.count == kQueue) {
    u.Pop();  // full: the oldest goes
    if (drained_) ++overflows_;
  }
  Frame& f = u.queue[(u.first + u.count) % kQueue];
  f.number = static_cast<std::int64_t>((end + kFrameBytes / 2) / kFrameBytes) - 1;
  f.range = r;
  ++u.count;
}

void RangeInputs::Advance(std::size_t k, std::int64_t n) {
  Unit& u = units_[k];
  while (u.count > 0 && u.front().number <= n) {
    u.last = u.front().range;
    u.Pop();
  }
}

estimator::guidance::RangeSet RangeInputs::MakeSet(estimator::GpsTime t) const {
  estimator::guidance::RangeSet s;
  s.t = t;
  s.right_front_m = units_[0].last.distance_m, s.right_front_ok = units_[0].last.valid;
  s.right_rear_m = units_[1].last.distance_m, s.right_rear_ok = units_[1].last.valid;
  s.left_front_m = units_[2].last.distance_m, s.left_front_ok = units_[2].last.valid;
  s.left_rear_m = units_[3].last.distance_m, s.left_rear_ok = units_[3].last.valid;
  return s;
}

void RangeInputs::Drain(estimator::GpsTime t,
                        const std::function<void(const estimator::guidance::RangeSet&)>& on_set) {
  for (std::size_t k = 0; k < kUnits; ++k) Read(k);
  drained_ = true;
  Unit& rf = units_[0];
  if (!start_) {  // no start given: the newest frame read now has just arrived
    if (rf.count == 0) return;
    const std::int64_t newest = rf.queue[(rf.first + rf.count - 1) % kQueue].number;
    start_ = t - transfer_ - period_ * (newest + 1);
  }
  const estimator::GpsTime oldest = t - kMaxAge;
  while (rf.count > 0 && FrameTime(rf.front().number) + transfer_ <= t) {
    const std::int64_t n = rf.front().number;
    Advance(0, n);
    for (std::size_t k = 1; k < kUnits; ++k) Advance(k, n);
    if (FrameTime(n) > oldest) on_set(MakeSet(FrameTime(n)));
  }
  // the other units' stale frames go too (a silent right-front unit must not fill their queues)
  const std::int64_t stale = (oldest - *start_) / period_ - 1;
  for (std::size_t k = 1; k < kUnits; ++k) Advance(k, stale);
}

void RangeInputs::Read(std::size_t k) {
  if (fds_[k] < 0) return;
  std::array<char, 512> buf{};
  for (;;) {
    const ssize_t n = read(fds_[k], buf.data(), buf.size());
    if (n <= 0) return;
    Feed(k, std::string_view(buf.data(), static_cast<std::size_t>(n)));
  }
}

void RangeInputs::Feed(std::size_t k, std::string_view bytes) { decoders_[k]->Feed(bytes); }

std::uint64_t RangeInputs::bad_bytes() const {
  std::uint64_t n = 0;
  for (const auto& d : decoders_)
    if (d) n += d->stats().bad_checksum + d->stats().garbage_bytes;
  return n;
}

}  // namespace hil::guidanced

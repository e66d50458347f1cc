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

bool RangeInputs::Open(const std::array<std::string, kUnits>& paths, int baud, bool tfmini_s,
                       double rate_hz) {
  period_ = estimator::Nanoseconds{std::llround(1e9 / rate_hz)};
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
    Unit& u = units_[k];
    decoders_[k] = std::make_unique<drv::BenewakeDecoder>(
        tfmini_s ? drv::BenewakeModel::kTfminiS : drv::BenewakeModel::kTfLuna,
        [&u](const drv::BenewakeRange& r) {
          u.queue[(u.first + u.count) % kQueue] = r;
          if (u.count < kQueue)
            ++u.count;
          else
            u.first = (u.first + 1) % kQueue;  // full: the oldest goes
        });
  }
  return true;
}

void RangeInputs::Drain(estimator::GpsTime t,
                        const std::function<void(const estimator::guidance::RangeSet&)>& on_set) {
  for (std::size_t k = 0; k < kUnits; ++k) Read(k);
  const std::size_t sets = units_[0].count;
  for (std::size_t i = 0; i < sets; ++i) {
    std::array<const drv::BenewakeRange*, kUnits> r{};
    for (std::size_t k = 0; k < kUnits; ++k) {
      Unit& u = units_[k];
      if (u.count > 0) u.last = u.at(std::min(u.count - 1, i * u.count / sets));
      r[k] = &u.last;
    }
    estimator::guidance::RangeSet s;
    s.t = t - period_ * static_cast<std::int64_t>(sets - 1 - i);
    s.right_front_m = r[0]->distance_m, s.right_front_ok = r[0]->valid;
    s.right_rear_m = r[1]->distance_m, s.right_rear_ok = r[1]->valid;
    s.left_front_m = r[2]->distance_m, s.left_front_ok = r[2]->valid;
    s.left_rear_m = r[3]->distance_m, s.left_rear_ok = r[3]->valid;
    on_set(s);
  }
  for (Unit& u : units_) u.count = 0, u.first = 0;
}

void RangeInputs::Read(std::size_t k) {
  std::array<char, 512> buf{};
  for (;;) {
    const ssize_t n = read(fds_[k], buf.data(), buf.size());
    if (n <= 0) return;
    decoders_[k]->Feed(std::string_view(buf.data(), static_cast<std::size_t>(n)));
  }
}

std::uint64_t RangeInputs::bad_bytes() const {
  std::uint64_t n = 0;
  for (const auto& d : decoders_)
    if (d) n += d->stats().bad_checksum + d->stats().garbage_bytes;
  return n;
}

}  // namespace hil::guidanced

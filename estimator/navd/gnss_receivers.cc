#include "gnss_receivers.h"

namespace hil::navd {

namespace est = hil::estimator;

GnssReceivers::Receiver::Receiver(const std::string& path, int baud, int index,
                                  const est::NavdConfig& cfg, const Handler& h)
    : device(path, baud, cfg.gnss_configure ? SerialDevice::kReadWrite : SerialDevice::kReadOnly),
      setup(cfg),
      nmea([this, index, leap = cfg.leap_seconds, acc = cfg.nmea_accuracy(),
            h](const est::drivers::NmeaFix& fix) {
        const auto m = nmea_epochs.Add(fix);
        if (!m) return;
        est::GnssSample g = est::drivers::ToGnssSample(*m, leap, acc);
        g.antenna = index;
        h(g);
      }),
      ubx([this, index, h,
           ubx_input = cfg.gnss_protocol == "ubx"](const est::drivers::UbxMessage& msg) {
        setup.OnMessage(msg);
        if (!ubx_input) return;
        for (est::GnssSample g : ubx_epochs.Add(msg)) {
          g.antenna = index;
          h(g);
        }
      }) {}

GnssReceivers::GnssReceivers(const est::NavdConfig& cfg, Handler handler)
    : ubx_(cfg.gnss_protocol == "ubx") {
  const std::vector<std::string> devices = cfg.GnssDevices();
  for (std::size_t i = 0; i < devices.size(); ++i) {
    rx_.push_back(
        std::make_unique<Receiver>(devices[i], cfg.gnss_baud, static_cast<int>(i), cfg, handler));
  }
}

void GnssReceivers::Feed(std::size_t i, const std::string& bytes) {
  Receiver& r = *rx_[i];
  if (ubx_) {
    r.ubx.Feed(bytes);
  } else {
    if (r.setup.active()) r.ubx.Feed(bytes);  // the ACKs of the start-up configuration
    r.nmea.Feed(bytes);
  }
  nmea_totals_ = nmea_stats();
  ubx_totals_ = ubx_stats();
}

void GnssReceivers::Service(std::int64_t now_ns) {
  for (auto& r : rx_) {
    if (r->device.EnsureOpen() >= 0) r->setup.Service(r->device, now_ns);
  }
}

est::drivers::NmeaDecoderStats GnssReceivers::nmea_stats() const {
  est::drivers::NmeaDecoderStats s;
  for (const auto& r : rx_) {
    const auto& x = r->nmea.stats();
    s.sentences_ok += x.sentences_ok, s.bad_checksum += x.bad_checksum, s.malformed += x.malformed;
    s.unsupported += x.unsupported, s.overlong += x.overlong, s.garbage_bytes += x.garbage_bytes;
  }
  return s;
}

est::drivers::UbxDecoderStats GnssReceivers::ubx_stats() const {
  est::drivers::UbxDecoderStats s;
  for (const auto& r : rx_) {
    const auto& x = r->ubx.stats();
    s.frames_ok += x.frames_ok, s.bad_checksum += x.bad_checksum, s.overlong += x.overlong;
    s.unsupported += x.unsupported, s.garbage_bytes += x.garbage_bytes, s.acks += x.acks,
        s.naks += x.naks;
  }
  return s;
}

std::uint64_t GnssReceivers::reopens() const {
  std::uint64_t n = 0;
  for (const auto& r : rx_) n += r->device.reopen_count();
  return n;
}

}  // namespace hil::navd

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
        if (PvtSupersedes(g.t)) return;  // the same receiver's NAV-PVT holds this epoch
        g.antenna = index;
        h(g);
      }),
      ubx([this, index, h, ubx_input = cfg.gnss_protocol == "ubx",
           pvt_input = cfg.gnss_protocol == "nmea" && cfg.gnss_nav_pvt, leap = cfg.leap_seconds,
           acc = cfg.ubx_pvt_accuracy](const est::drivers::UbxMessage& msg) {
        setup.OnMessage(msg);
        if (pvt_input && msg.cls == 0x01 && msg.id == 0x07) {
          auto g = est::drivers::NavPvtToGnssSample(msg, leap, acc);
          if (!g) return;
          last_pvt_t = g->t;
          g->antenna = index;
          h(*g);
        }
        if (!ubx_input) return;
        for (est::GnssSample g : ubx_epochs.Add(msg)) {
          g.antenna = index;
          h(g);
        }
      }) {
  // NMEA and UBX share the line: the UBX decoder frames the stream and passes the rest to NMEA
  if (cfg.gnss_protocol == "nmea")
    ubx.SetOtherBytesSink([this](std::string_view b) { nmea.Feed(b); });
}

bool GnssReceivers::Receiver::PvtSupersedes(est::GpsTime t) const {
  if (!last_pvt_t) return false;
  const auto d = t - *last_pvt_t;
  return d < kPvtHoldover && d > -kPvtHoldover;
}

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
  r.ubx.Feed(bytes);  // nmea: the UBX frames (ACKs, NAV-PVT), the rest to the NMEA decoder
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

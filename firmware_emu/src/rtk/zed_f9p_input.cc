// The ZED-F9P's inputs: the host's bytes on UART1 (UBX, NMEA, RTCM 3), the correction radio's
// on UART2, and what the receiver does with each RTCM 3 frame.
#include <algorithm>

#include "hil/firmware_emu/gnss/ubx_messages.h"
#include "hil/firmware_emu/rtk/zed_f9p_device.h"

namespace hil::rtk {
namespace {

namespace key = gnss::ubx::f9key;

// 10 bit times a byte (8N1) at `baud`.
Duration ByteTime(std::uint64_t baud) {
  return Duration{static_cast<std::int64_t>((1000000000ULL * 10 + baud / 2) / baud)};
}

bool IsMsm(int number) { return number >= 1071 && number <= 1137; }

}  // namespace

void ZedF9pDevice::RadioEpoch(Time t) {
  // the base's packet, after its radio, reaches the modem's end and goes down the line to UART2
  DeviceOutput sent;
  radio_base_->OnEvent(TruthSample{.t = t}, sent);
  FeedUart2(sent.serial, radio_base_->baud(0));
}

Time ZedF9pDevice::FeedUart2(const std::vector<SerialMessage>& sent, int baud) {
  const Duration byte_time = ByteTime(static_cast<std::uint64_t>(baud));
  // a UART2 set to another rate than the line's decodes nothing (framing errors)
  const bool accept = Enabled(key::kUart2InRtcm3) &&
                      db_.Get(key::kUart2Baudrate) == static_cast<std::uint64_t>(baud);
  std::vector<rtcm3::ReceivedFrame> frames;
  for (const SerialMessage& m : sent) {
    Time t_byte_end = std::max(m.t_ready, rx2_free_);
    for (const char c : m.bytes) {
      t_byte_end += byte_time;
      frames.clear();
      uart2_rtcm_.Feed(c, frames);
      for (auto& f : frames) {
        if (accept) pending_.push_back({t_byte_end, std::move(f)});
      }
    }
    rx2_free_ = t_byte_end;
  }
  return accept ? rx2_free_ : Time::max();
}

bool ZedF9pDevice::ReferenceKnown(int station_id) const {
  return (station_ && station_id == station_->station_id) ||
         (moving_ref_ && station_id == moving_ref_->station_id);
}

void ZedF9pDevice::Receive(Time t, const PendingFrame& p, DeviceOutput& out) {
  const int number = p.frame.message_number();
  ++stats_.rtcm_frames;
  bool used = false;
  int ref_station = p.frame.station_id();  // 4072: the 12 bits after DF002 are its sub-type
  if (p.frame.crc_failed) {
    ++stats_.rtcm_crc_failed;
  } else if (number == 1005 || number == 1006) {
    station_ = rtcm3::DecodeStation(p.frame.body);
    used = true;
  } else if (number == rtcm3::kMovingBaseMessage &&
             rtcm3::Subtype4072(p.frame.body) == rtcm3::kMovingBaseSubtype &&
             p.frame.body.size() == rtcm3::kMovingBasePvtBytes) {
    moving_ref_ = rtcm3::Decode4072Pvt(p.frame.body);
    ref_station = moving_ref_->station_id;
    used = true;
  } else if (IsMsm(number) && ReferenceKnown(p.frame.station_id())) {
    rtk_.OnCorrection(t);
    used = true;
  }
  if (!Enabled(key::kUart1OutUbx) || !Enabled(key::kRxmRtcmUart1)) return;
  Push(out, t,
       gnss::ubx::Frame(gnss::ubx::kRxm, gnss::ubx::kRxmRtcm,
                        gnss::ubx::EncodeRxmRtcm(number, ref_station, p.frame.crc_failed, used)),
       "UBX-RXM-RTCM");
}

void ZedF9pDevice::OnHostBytes(int port, Time t, std::string_view bytes, DeviceOutput& out) {
  if (port != 0) return;
  const Duration byte_time = ByteTime(static_cast<std::uint64_t>(baud(0)));
  Time t_byte_end = std::max(t, rx1_free_);
  std::vector<rtcm3::ReceivedFrame> frames;
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    t_byte_end += byte_time;
    for (const gnss::ubx::InputMessage& m : parser_.Feed(bytes.substr(k, 1))) {
      if (m.kind == gnss::ubx::InputMessage::Kind::kUbx && Enabled(key::kUart1InUbx))
        HandleUbx(m, t_byte_end, out);
    }
    frames.clear();
    uart1_rtcm_.Feed(bytes[k], frames);
    if (!Enabled(key::kUart1InRtcm3)) continue;
    for (auto& f : frames) {
      // in arrival order among the radio's frames
      PendingFrame p{t_byte_end, std::move(f)};
      const auto at = std::upper_bound(pending_.begin(), pending_.end(), p.t,
                                       [](Time a, const PendingFrame& b) { return a < b.t; });
      pending_.insert(at, std::move(p));
    }
  }
  rx1_free_ = t_byte_end;
}

void ZedF9pDevice::HandleUbx(const gnss::ubx::InputMessage& m, Time t, DeviceOutput& out) {
  namespace ubx = gnss::ubx;
  const Time t_reply = t + config_.response_delay;
  std::vector<ubx::Reply> replies;
  if (m.cls == ubx::kCfg &&
      (m.id == ubx::kCfgValset || m.id == ubx::kCfgValget || m.id == ubx::kCfgValdel)) {
    const Duration period_before = Period();
    replies = db_.Handle(m.id, m.payload);
    // a new rate runs from the command on
    if (Period() != period_before) next_epoch_ = NextGridEpoch(std::max(last_epoch_time_, t));
  } else if (m.cls == ubx::kCfg) {
    replies.push_back(
        {ubx::Ack(false, m.cls, m.id), "UBX-ACK-NAK"});  // protocol 27+: no legacy CFG here
  } else if (m.payload.empty() && m.cls == ubx::kMon && m.id == ubx::kMonVer) {
    replies.push_back({ubx::Frame(m.cls, m.id, ubx::EncodeF9MonVer()), "UBX-MON-VER"});
  } else if (m.payload.empty() && m.cls == ubx::kNav && m.id == ubx::kNavPvt) {
    replies.push_back({ubx::Frame(m.cls, m.id, ubx::EncodeNavPvt(last_)), "UBX-NAV-PVT"});
  } else if (m.payload.empty() && m.cls == ubx::kNav && m.id == ubx::kNavRelposned) {
    replies.push_back(
        {ubx::Frame(m.cls, m.id, ubx::EncodeNavRelposned(last_)), "UBX-NAV-RELPOSNED"});
  }
  if (!Enabled(key::kUart1OutUbx)) return;
  for (auto& r : replies) Push(out, t_reply, std::move(r.bytes), std::move(r.name), true);
}

}  // namespace hil::rtk

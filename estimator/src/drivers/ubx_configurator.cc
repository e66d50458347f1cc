#include "hil/estimator/drivers/ubx_configurator.h"

#include <array>
#include <cmath>
#include <utility>

namespace hil::estimator::drivers {
namespace {

constexpr std::uint8_t kClsCfg = 0x06, kIdMsg = 0x01, kIdRate = 0x08;
constexpr std::uint8_t kClsAck = 0x05, kIdAck = 0x01, kIdNak = 0x00;

UbxCommand Make(std::string name, std::uint8_t id, const std::string& payload) {
  UbxCommand c;
  c.name = std::move(name);
  c.cls = kClsCfg;
  c.id = id;
  std::array<char, 64> buf{};
  const std::size_t n = UbxDecoder::Encode(kClsCfg, id, payload, buf.data(), buf.size());
  c.frame.assign(buf.data(), n);
  return c;
}

UbxCommand MsgRate(const char* msg_name, std::uint8_t cls, std::uint8_t id, std::uint8_t rate) {
  const std::string payload{static_cast<char>(cls), static_cast<char>(id), static_cast<char>(rate)};
  return Make(std::string("CFG-MSG ") + msg_name + " " + std::to_string(rate), kIdMsg, payload);
}

std::string U2(unsigned v) {
  return {static_cast<char>(v & 0xFF), static_cast<char>((v >> 8) & 0xFF)};
}

}  // namespace

std::vector<UbxCommand> UbxSetupCommands(const ReceiverSetup& setup) {
  std::vector<UbxCommand> cmds;
  struct Nmea {
    const char* name;
    std::uint8_t id;
  };
  constexpr std::array<Nmea, 6> kNmea{
      {{"GGA", 0x00}, {"GLL", 0x01}, {"GSA", 0x02}, {"GSV", 0x03}, {"RMC", 0x04}, {"VTG", 0x05}}};
  if (setup.nmea_off || setup.nmea_minimal) {
    for (const Nmea& s : kNmea) {
      const bool keep = setup.nmea_minimal && !setup.nmea_off && (s.id == 0x00 || s.id == 0x04);
      if (!keep) cmds.push_back(MsgRate((std::string("NMEA-") + s.name).c_str(), 0xF0, s.id, 0));
    }
  }
  if (setup.nmea_minimal && !setup.nmea_off) {
    cmds.push_back(MsgRate("NMEA-GGA", 0xF0, 0x00, 1));
    cmds.push_back(MsgRate("NMEA-RMC", 0xF0, 0x04, 1));
  }
  if (setup.ubx_navigation) {
    cmds.push_back(MsgRate("NAV-POSLLH", 0x01, 0x02, 1));
    cmds.push_back(MsgRate("NAV-VELNED", 0x01, 0x12, 1));
    cmds.push_back(MsgRate("NAV-SOL", 0x01, 0x06, 1));
    cmds.push_back(MsgRate("NAV-TIMEGPS", 0x01, 0x20, 1));
  }
  // the rate last: raised before the message set shrinks, the output can exceed the baud and the
  // receiver drops messages, ACKs included
  if (setup.rate_hz > 0) {
    const auto ms = static_cast<unsigned>(std::lround(1000.0 / setup.rate_hz));
    cmds.push_back(Make("CFG-RATE " + std::to_string(ms) + " ms", kIdRate, U2(ms) + U2(1) + U2(1)));
  }
  return cmds;
}

UbxConfigurator::UbxConfigurator(std::vector<UbxCommand> commands, std::int64_t timeout_ns,
                                 int max_attempts)
    : commands_(std::move(commands)),
      timeout_ns_(timeout_ns),
      max_attempts_(max_attempts < 1 ? 1 : max_attempts) {}

std::optional<std::string> UbxConfigurator::Poll(std::int64_t now_ns) {
  while (!done()) {
    UbxCommand& c = commands_[next_];
    if (sent_at_ns_ && now_ns - *sent_at_ns_ < timeout_ns_)
      return std::nullopt;  // waiting for its ACK
    if (c.attempts >= max_attempts_) {
      c.result = UbxCommand::Result::kTimedOut;
      ++next_;
      sent_at_ns_.reset();
      continue;
    }
    ++c.attempts;
    sent_at_ns_ = now_ns;
    return c.frame;
  }
  return std::nullopt;
}

void UbxConfigurator::OnMessage(const UbxMessage& m) {
  if (done() || !sent_at_ns_ || m.cls != kClsAck || (m.id != kIdAck && m.id != kIdNak)) return;
  UbxCommand& c = commands_[next_];
  if (m.ack_cls != c.cls || m.ack_id != c.id) return;  // a late answer to an earlier command
  c.result = m.id == kIdAck ? UbxCommand::Result::kAcked : UbxCommand::Result::kNaked;
  ++next_;
  sent_at_ns_.reset();
}

void UbxConfigurator::Restart() {
  for (UbxCommand& c : commands_) {
    c.result = UbxCommand::Result::kPending;
    c.attempts = 0;
  }
  next_ = 0;
  sent_at_ns_.reset();
}

bool UbxConfigurator::all_acked() const {
  for (const UbxCommand& c : commands_) {
    if (c.result != UbxCommand::Result::kAcked) return false;
  }
  return true;
}

std::string UbxConfigurator::Summary() const {
  int acked = 0, naked = 0, timed_out = 0;
  std::string failed;
  for (const UbxCommand& c : commands_) {
    if (c.result == UbxCommand::Result::kAcked) ++acked;
    if (c.result == UbxCommand::Result::kNaked) ++naked;
    if (c.result == UbxCommand::Result::kTimedOut) ++timed_out;
    if (c.result == UbxCommand::Result::kNaked || c.result == UbxCommand::Result::kTimedOut) {
      failed += (failed.empty() ? "" : ", ") + c.name +
                (c.result == UbxCommand::Result::kNaked ? " NAK" : " no answer");
    }
  }
  std::string s = std::to_string(commands_.size()) + " commands: " + std::to_string(acked) +
                  " acked, " + std::to_string(naked) + " refused, " + std::to_string(timed_out) +
                  " unanswered";
  if (!failed.empty()) s += " (" + failed + ")";
  return s;
}

}  // namespace hil::estimator::drivers

// TfLunaDevice's command session: what each 5A command does and what the module answers
// (vectors/rangefinder/README.md, "Commands").
#include <algorithm>

#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

namespace hil::rangefinder {
namespace {

constexpr std::uint8_t kPass = 0x00;

std::string Status(CommandId id, std::uint8_t status) {
  return FrameCommand(static_cast<std::uint8_t>(id), std::string(1, static_cast<char>(status)));
}

bool KnownFormat(std::uint8_t f) {
  return f == static_cast<std::uint8_t>(OutputFormat::kCm9Byte) ||
         f == static_cast<std::uint8_t>(OutputFormat::kPixAscii) ||
         f == static_cast<std::uint8_t>(OutputFormat::kMm9Byte);
}

}  // namespace

void TfLunaDevice::Handle(const CommandFrame& f, DeviceOutput& out) {
  ++stats_.commands;
  switch (static_cast<CommandId>(f.id)) {
    case CommandId::kVersion: {
      const auto& v = config_.firmware_version;  // reply bytes: patch, minor, major
      const std::string payload{static_cast<char>(v[2]), static_cast<char>(v[1]),
                                static_cast<char>(v[0])};
      Reply(FrameCommand(f.id, payload), out);
      return;
    }
    case CommandId::kSystemReset:
      Reply(Status(CommandId::kSystemReset, kPass), out);
      settings_ = flash_;  // a reboot: the saved settings, output after the boot time
      trigger_pending_ = false;
      ++stats_.resets;
      next_frame_ = effective_rate_hz() > 0 ? now_ + config_.boot_time : Time::max();
      return;
    case CommandId::kTrigger:
      if (!f.payload.empty()) break;
      trigger_pending_ = true;  // one frame at once, whatever the mode
      next_frame_ = now_;
      return;
    case CommandId::kRestoreDefaults:
      settings_ = config_.settings;
      Reply(Status(CommandId::kRestoreDefaults, kPass), out);
      Schedule(now_);
      return;
    case CommandId::kSave:
      flash_ = settings_;
      ++stats_.saves;
      Reply(Status(CommandId::kSave, kPass), out);
      return;
    default:
      HandleSetting(f, out);
      return;
  }
  ++stats_.unsupported;
}

void TfLunaDevice::HandleSetting(const CommandFrame& f, DeviceOutput& out) {
  const std::string echo = FrameCommand(f.id, f.payload);
  switch (static_cast<CommandId>(f.id)) {
    case CommandId::kFrameRate:
      if (const auto hz = PayloadU16(f.payload); hz && *hz <= 250) {
        settings_.frame_rate_hz = *hz;
        Reply(echo, out);
        Schedule(now_);
        return;
      }
      break;
    case CommandId::kOutputFormat:
      if (f.payload.size() == 1 && KnownFormat(static_cast<std::uint8_t>(f.payload[0]))) {
        settings_.format = static_cast<OutputFormat>(f.payload[0]);
        Reply(echo, out);
        return;
      }
      break;
    case CommandId::kBaudRate:
      if (const auto baud = PayloadU32(f.payload); baud && IsSupportedBaud(*baud)) {
        Reply(echo, out);  // the echo still leaves at the old rate (UART model queues it first)
        settings_.baud = *baud;
        return;
      }
      break;
    case CommandId::kOutputEnable:
      if (f.payload.size() == 1 && static_cast<std::uint8_t>(f.payload[0]) <= 1) {
        settings_.output_enabled = f.payload[0] == 1;
        Reply(echo, out);
        Schedule(now_);
        return;
      }
      break;
    default:
      break;
  }
  ++stats_.unsupported;  // unknown ID or bad argument: no reply (UNVERIFIED)
}

}  // namespace hil::rangefinder

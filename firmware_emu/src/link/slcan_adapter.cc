#include "hil/firmware_emu/link/slcan_adapter.h"

#include <array>
#include <utility>

namespace hil::link {
namespace {

constexpr std::array<int, 9> kBitrates{10000,  20000,  50000,  100000, 125000,
                                       250000, 500000, 800000, 1000000};
constexpr char kOk = '\r';
constexpr char kBell = '\a';

bool AllHex(std::string_view s) {
  for (const char c : s) {
    const bool hex = (c >= '0' && c <= '9') || (c >= 'A' && c <= 'F') || (c >= 'a' && c <= 'f');
    if (!hex) return false;
  }
  return true;
}

}  // namespace

SlcanAdapter::SlcanAdapter(std::string serial_number) : serial_number_(std::move(serial_number)) {}

void SlcanAdapter::OnHostBytes(Time t, std::string_view bytes, std::string& reply,
                               std::vector<CanFrame>& frames) {
  for (const char c : bytes) {
    if (!splitter_.Feed(c)) continue;
    if (splitter_.line().empty()) continue;  // a bare CR (hosts send a few to flush): no answer
    ++counters_.records;
    reply += Execute(t, splitter_.line(), frames);
  }
}

std::string SlcanAdapter::Refuse() {
  ++counters_.refused;
  return std::string(1, kBell);
}

std::string SlcanAdapter::Transmit(Time t, const std::string& record,
                                   std::vector<CanFrame>& frames) {
  if (!open_ || listen_only_) return Refuse();
  CanFrame f;
  f.t = t;
  if (DecodeSlcanFrame(record, f) != SlcanFrameError::kNone) return Refuse();
  ++counters_.frames_from_host;
  frames.push_back(f);
  return std::string(f.extended ? "Z" : "z") + kOk;
}

std::string SlcanAdapter::Execute(Time t, const std::string& record,
                                  std::vector<CanFrame>& frames) {
  const char cmd = record[0];
  const std::string_view arg = std::string_view(record).substr(1);
  switch (cmd) {
    case 't':
    case 'T':
    case 'r':
    case 'R':
      return Transmit(t, record, frames);
    case 'S':
      if (open_ || arg.size() != 1 || arg[0] < '0' || arg[0] > '8') return Refuse();
      bitrate_bps_ = kBitrates[static_cast<std::size_t>(arg[0] - '0')];
      return std::string(1, kOk);
    case 's':
      if (open_ || arg.size() != 4 || !AllHex(arg)) return Refuse();
      bitrate_bps_ = 0;
      return std::string(1, kOk);
    case 'O':
    case 'L':
      if (open_ || !arg.empty()) return Refuse();
      open_ = true;
      listen_only_ = cmd == 'L';
      ++counters_.opens;
      return std::string(1, kOk);
    case 'C':  // closing a closed channel is no error (hosts close first to start clean)
      if (!arg.empty()) return Refuse();
      if (open_) ++counters_.closes;
      open_ = false;
      listen_only_ = false;
      return std::string(1, kOk);
    case 'V':
      return arg.empty() ? std::string("V1013") + kOk : Refuse();
    case 'N':
      return arg.empty() ? "N" + serial_number_ + kOk : Refuse();
    case 'F':
      return arg.empty() && open_ ? std::string("F00") + kOk : Refuse();
    case 'Z':
      if (arg.size() != 1 || (arg[0] != '0' && arg[0] != '1')) return Refuse();
      timestamps_ = arg[0] == '1';
      return std::string(1, kOk);
    case 'M':
    case 'm':
      return arg.size() == 8 && AllHex(arg) ? std::string(1, kOk) : Refuse();
    default:
      return Refuse();
  }
}

std::string SlcanAdapter::ToHost(const CanFrame& frame) {
  if (!open_) {
    ++counters_.dropped_closed;
    return {};
  }
  ++counters_.frames_to_host;
  std::string s = EncodeSlcanFrame(frame);
  if (timestamps_) {
    static constexpr char kHex[] = "0123456789ABCDEF";
    const auto ms = static_cast<std::uint32_t>((ToNs(frame.t) / 1'000'000) % 60000);
    s.pop_back();
    for (int i = 3; i >= 0; --i) s.push_back(kHex[(ms >> (4 * i)) & 0xF]);
    s.push_back(kOk);
  }
  return s;
}

}  // namespace hil::link

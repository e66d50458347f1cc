#include "hil/harness/dut/n2k_fast_packet.h"

namespace hil::harness {

std::uint32_t N2kPgnFromId(std::uint32_t id29) {
  const std::uint32_t dp = (id29 >> 24) & 3, pf = (id29 >> 16) & 0xFF, ps = (id29 >> 8) & 0xFF;
  return (dp << 16) | (pf << 8) | (pf >= 240 ? ps : 0);
}

std::optional<std::string> N2kFastPacketAssembler::Add(std::uint8_t source, std::uint32_t pgn,
                                                       std::string_view data) {
  ++stats_.frames;
  if (data.empty()) {
    ++stats_.bad_frames;
    return std::nullopt;
  }
  Partial& p = partial_[(static_cast<std::uint64_t>(pgn) << 8) | source];
  const auto b0 = static_cast<unsigned char>(data[0]);
  const int sequence = b0 >> 5, index = b0 & 0x1F;
  if (index == 0) {
    const bool incomplete = p.expected > 0;
    if (data.size() < 2 || static_cast<unsigned char>(data[1]) > kMaxPayload || data[1] == 0) {
      ++stats_.bad_frames;
      p = Partial{};
      return std::nullopt;
    }
    if (incomplete) ++stats_.abandoned;
    p = Partial{sequence, 1, static_cast<unsigned char>(data[1]), std::string(data.substr(2))};
  } else if (p.expected == 0 || sequence != p.sequence || index != p.next_index) {
    ++stats_.out_of_turn;
    p = Partial{};
    return std::nullopt;
  } else {
    p.bytes.append(data.substr(1));
    ++p.next_index;
  }
  if (p.bytes.size() < p.expected) return std::nullopt;
  std::string out = p.bytes.substr(0, p.expected);
  p = Partial{};
  ++stats_.messages;
  return out;
}

}  // namespace hil::harness

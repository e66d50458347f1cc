// Fuzz target: the harness's NMEA 2000 fast-packet reassembly (harness/src/n2k_fast_packet.cc).
// Input: [payload length byte][payload][noise frames…]. Oracles:
//  1. round trip: the payload, split into fast-packet frames (sequence counter from the input),
//     with frames of another source and another PGN interleaved, reassembles to exactly itself;
//  2. navd's own 129029 encoder (estimator/src/outputs/n2k_encoder.cc) with latitude and longitude
//     from the input reassembles to its 43-byte payload with those values within their resolution;
//  3. arbitrary frames (the rest of the input, 9 bytes each: source, 8 data) never yield a message
//     longer than 223 bytes or different from its announced length.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>
#include <string_view>

#include "hil/estimator/outputs/n2k_encoder.h"
#include "hil/harness/dut/n2k_fast_packet.h"

namespace {

using hil::harness::N2kFastPacketAssembler;

std::string Frame(int seq, int index, std::string_view bytes) {
  std::string f(1, static_cast<char>((seq & 7) << 5 | (index & 0x1F)));
  f += bytes;
  f.resize(8, static_cast<char>(0xFF));
  return f;
}

std::int64_t I64(const std::string& b, std::size_t at) {
  std::uint64_t v = 0;
  for (int k = 7; k >= 0; --k)
    v = (v << 8) | static_cast<unsigned char>(b[at + static_cast<std::size_t>(k)]);
  return static_cast<std::int64_t>(v);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 2) return 0;
  const std::string_view in(reinterpret_cast<const char*>(data), size);
  // 1. generic round trip
  const std::size_t len =
      1 + static_cast<unsigned char>(in[0]) % N2kFastPacketAssembler::kMaxPayload;
  const int seq = static_cast<unsigned char>(in[1]) & 7;
  std::string payload(in.substr(2, len));
  payload.resize(len, '\x5A');
  N2kFastPacketAssembler a;
  constexpr std::uint32_t kPgn = 129029, kOtherPgn = 126996;
  std::optional<std::string> got;
  std::size_t at = 0;
  for (int index = 0; at < len; ++index) {
    const std::size_t n = index == 0 ? 6 : 7;
    std::string body = index == 0 ? std::string(1, static_cast<char>(len)) : std::string();
    body += payload.substr(at, n);
    at += n;
    if (got) std::abort();  // complete before the last frame
    got = a.Add(0x80, kPgn, Frame(seq, index, body));
    // noise on the bus between the frames: another source, another PGN of the same source
    (void)a.Add(0x81, kPgn, Frame(seq + 1, index, "noise"));
    (void)a.Add(0x80, kOtherPgn, Frame(seq, index + 1, "other"));
  }
  if (!got || *got != payload) std::abort();

  // 2. navd's 129029 encoder
  double lat = 0, lon = 0;
  if (size >= 18) {
    std::int64_t ilat = 0, ilon = 0;
    std::memcpy(&ilat, data + 2, 8);
    std::memcpy(&ilon, data + 10, 8);
    lat = static_cast<double>(ilat % 900000000) * 1e-7;
    lon = static_cast<double>(ilon % 1800000000) * 1e-7;
  }
  const auto fp = hil::estimator::outputs::EncodeGnssPosition(
      1, 19000, 3600.5, lat, lon, 12.5, 1, 9, 0.9, static_cast<std::uint8_t>(seq), 0x80);
  N2kFastPacketAssembler b;
  std::optional<std::string> msg;
  for (int i = 0; i < fp.count; ++i) {
    const auto& f = fp.frames[static_cast<std::size_t>(i)];
    if (hil::harness::N2kPgnFromId(f.id) != kPgn || hil::harness::N2kSourceFromId(f.id) != 0x80)
      std::abort();
    msg = b.Add(0x80, kPgn, std::string_view(reinterpret_cast<const char*>(f.data.data()), f.len));
  }
  if (!msg || msg->size() != 43) std::abort();
  if (std::abs(static_cast<double>(I64(*msg, 7)) * 1e-16 - lat) > 1e-9) std::abort();
  if (std::abs(static_cast<double>(I64(*msg, 15)) * 1e-16 - lon) > 1e-9) std::abort();

  // 3. arbitrary frames
  N2kFastPacketAssembler c;
  for (std::size_t i = 2; i + 9 <= size; i += 9) {
    const auto m =
        c.Add(static_cast<std::uint8_t>(data[i] & 3), kPgn, in.substr(i + 1, 1 + data[i] % 8));
    if (m && (m->empty() || m->size() > N2kFastPacketAssembler::kMaxPayload)) std::abort();
  }
  if (c.stats().messages > c.stats().frames) std::abort();
  return 0;
}

#pragma once
/// @file
/// Slamtec RPLIDAR A1/A2 request framing (host → device; seeds_001_003.md §C.4): `A5 CMD` for
/// commands without payload, `A5 CMD SIZE PAYLOAD… CS` for those with the 0x80 flag, CS = XOR of
/// 0xA5, CMD, SIZE and every payload byte.

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>

namespace hil::lidar {

inline constexpr unsigned char kSyncA5 = 0xA5, kSync5A = 0x5A;

/// Request codes.
enum class Request : std::uint8_t {
  kStop = 0x25,
  kReset = 0x40,
  kScan = 0x20,
  kForceScan = 0x21,
  kExpressScan = 0x82,
  kGetInfo = 0x50,
  kGetHealth = 0x52,
  kGetSampleRate = 0x59,
  kSetMotorPwm = 0xF0,
  kGetAccBoardFlag = 0xFF,
};

/// `A5 CMD` or, when `cmd` has the 0x80 flag, `A5 CMD SIZE PAYLOAD CS`.
std::string EncodeRequest(std::uint8_t cmd, std::string_view payload = {});

struct RequestFrame {
  std::uint8_t cmd = 0;
  std::string payload;
};

struct RequestReaderStats {
  std::uint64_t requests = 0, bad_checksum = 0, garbage_bytes = 0;
};

/// Extracts requests from bytes arriving in any pieces; a byte other than A5 where a request must
/// start is garbage, a bad checksum drops the request (counted) and the search resumes one byte
/// after its A5.
class RequestReader {
 public:
  using Handler = std::function<void(const RequestFrame&)>;
  explicit RequestReader(Handler h) : handler_(std::move(h)) {}
  void Feed(std::string_view bytes);
  const RequestReaderStats& stats() const { return stats_; }

 private:
  Handler handler_;
  std::string buf_;
  RequestReaderStats stats_;
};

}  // namespace hil::lidar

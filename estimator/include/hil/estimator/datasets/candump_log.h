#pragma once
/// @file
/// Reader of can-utils `candump -L` logs (also written by `candump -l` and by the harness's CAN
/// captures, captures/<iface>.candump): one frame per line, `(SECONDS.FRACTION) IFACE ID#DATA`,
/// with an 11-bit (3 hex digits) or 29-bit (8 hex digits) identifier, up to 8 data bytes in hex,
/// `ID#R` (or `ID#Rn`) for a remote frame, an optional `_D` length code after the data, and an
/// optional trailing direction token (`R`/`T`, candump -x). CAN FD frames (`ID##F…`) are refused:
/// the J1939 IMU frames are classic CAN. Blank lines and `#` comments are skipped. A malformed
/// line is an error naming the file, the line and the field; a well-formed frame that is not an
/// IMU frame is the decoder's to count.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "hil/estimator/datasets/dataset_error.h"
#include "hil/estimator/drivers/j1939_imu_decoder.h"

namespace hil::estimator::datasets {

/// One frame of a candump log.
struct CandumpRecord {
  drivers::CanRxFrame frame;  ///< rx_ns: the recorded Unix time of the frame, in ns
  bool remote = false;        ///< a remote (RTR) frame: no data
  std::string interface;
};

/// Parses one line (without its newline). @throws DatasetError naming `path`, `line_no` and the
/// field.
CandumpRecord ParseCandumpLine(std::string_view line, const std::string& path, long line_no);

/// Every frame of the file, in file order. @throws DatasetError (cannot open, malformed line).
std::vector<CandumpRecord> ReadCandumpLog(const std::string& path);

/// True when the first line that is not blank or a comment looks like a candump frame line
/// (starts with '(' followed by a digit).
bool LooksLikeCandump(std::string_view text);

}  // namespace hil::estimator::datasets

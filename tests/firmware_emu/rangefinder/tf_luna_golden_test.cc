// Golden vectors of the TF-Luna emulator (vectors/rangefinder): the byte stream of a 4 s session
// (the right-front unit of a vehicle driving from the headland into aisle 0, with the command
// session of the README) and, per message, what a decoder must read back. Re-created byte for
// byte from a fixed seed; HIL_REGEN_VECTORS=1 rewrites them.
#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "hil/firmware_emu/rangefinder/benewake_codec.h"
#include "hil/firmware_emu/rangefinder/tf_luna_device.h"

#include "aisle_truth.h"
#include "golden_file.h"
#include "hex_bytes.h"

namespace hil::rangefinder {
namespace {

constexpr std::uint64_t kSeed = 20200501;

std::vector<test::HostCommand> SessionCommands() {
  auto at = [](double s, std::string b) { return test::HostCommand{TimeFromSeconds(s), b}; };
  auto one = [](int b) { return std::string(1, static_cast<char>(b)); };
  return {
      at(1.500, FrameCommand(0x01, "")),                      // version
      at(1.600, FrameCommand(0x03, U16Payload(250))),         // 250 Hz
      at(1.800, FrameCommand(0x05, one(0x06))),               // 9-byte, mm
      at(2.000, FrameCommand(0x07, one(0x00))),               // output off
      at(2.100, std::string("\x5A\x05\x07\x01\x00", 5)),      // output on, checksum 00
      at(2.200, std::string("\x5A\x05\x07\x00\x77\x13", 6)),  // bad checksum + garbage: ignored
      at(2.300, FrameCommand(0x03, U16Payload(0))),           // trigger mode
      at(2.400, FrameCommand(0x04, "")),                      // trigger one frame
      at(2.500, FrameCommand(0x05, one(0x02))),               // PIX text
      at(2.550, FrameCommand(0x04, "")),
      at(2.600, FrameCommand(0x05, one(0x01))),        // 9-byte, cm
      at(2.610, FrameCommand(0x03, U16Payload(100))),  // 100 Hz
      at(2.700, FrameCommand(0x11, "")),               // save
      at(2.800, FrameCommand(0x03, U16Payload(50))),   // 50 Hz, not saved
      at(3.000, FrameCommand(0x02, "")),               // reset: saved settings, 1 s boot
  };
}

std::string Hex(const std::string& b) { return hil::test::HexBytes(b, {.upper = true}); }

TEST(TfLunaGolden, SessionBytesAndExpectations) {
  const world::GreenhouseWorld w(test::SmallGreenhouse());
  TfLunaConfig c;
  c.mount = {0.2, -0.25, 0.15, -90};  // right-front
  TfLunaDevice dev(c, w, kSeed);
  std::ostringstream csv;
  csv << "t_ready_ns,kind,true_range_m,measured_m,dist_raw,amp,temp_raw,valid_or_hex\n";
  std::string bin;
  test::RunDevice(
      dev, test::AisleTruth{}, TimeFromSeconds(4.0), SessionCommands(),
      [&](const SerialMessage& m, bool data) {
        bin += m.bytes;
        char row[160];
        if (!data) {
          csv << ToNs(m.t_ready) << ",reply,,,,,," << Hex(m.bytes) << "\n";
          return;
        }
        const Reading& r = dev.last_reading();
        std::snprintf(row, sizeof row, "%lld,%s,%.6f,%.6f,%u,%u,%u,%d\n",
                      static_cast<long long>(ToNs(m.t_ready)), m.name == "TF-PIX" ? "pix" : "data",
                      dev.last_target().present ? dev.last_target().range_m : 0.0, r.measured_m,
                      r.fields.dist, r.fields.amp, r.fields.temp_raw, r.valid ? 1 : 0);
        csv << row;
      });
  EXPECT_EQ(dev.stats().replies, 12u);
  EXPECT_EQ(dev.command_stats().bad_checksum, 1u);
  EXPECT_EQ(dev.command_stats().zero_checksum, 1u);
  EXPECT_GT(dev.stats().invalid_frames, 50u);  // the headland: the film wall returns too little
  test::CheckOrWriteGolden("vectors/rangefinder/tf_luna_session.bin", bin);
  test::CheckOrWriteGolden("vectors/rangefinder/tf_luna_session.expected.csv", csv.str());
}

}  // namespace
}  // namespace hil::rangefinder

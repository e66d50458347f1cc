// The frames others put on the CAN bus are kept only until every reader has taken them (issue 40,
// minor: hil's memory per emulated hour): the devices (TakeUnrouted) and the estimator's NMEA 2000
// output reader (TakeUncollected). Before, every frame of the run stayed in the list.
#include <algorithm>
#include <cstdint>
#include <memory>
#include <vector>

#include <gtest/gtest.h>

#include "hil/harness/engine/device_io.h"
#include "hil/harness/engine/virtual_pacer.h"

namespace hil::harness {
namespace {

CanFrame FrameNumber(std::uint32_t k) {
  CanFrame f;
  f.t = TimeFromSeconds(0.01 * k);
  f.id = k;
  f.extended = true;
  return f;
}

struct Io {
  VirtualPacer pacer;
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  DeviceIo io{EngineDevices{devices, endpoints}, pacer, false};
};

TEST(DeviceIoBusTest, FramesTheDevicesTookAreNotKept) {
  Io s;
  constexpr std::uint32_t kFrames = 40000;  // an hour of a 10 Hz, 1-frame output and more
  std::uint32_t routed = 0;
  for (std::uint32_t k = 0; k < kFrames; ++k) {
    s.io.bus_frames().push_back(FrameNumber(k));  // as a host turn's arrivals
    for (const CanFrame& f : s.io.TakeUnrouted()) EXPECT_EQ(f.id, routed++);
  }
  EXPECT_EQ(routed, kFrames);
  EXPECT_EQ(s.io.bus_frames().size(), 0u);
}

TEST(DeviceIoBusTest, WithTheOutputReaderAFrameStaysUntilBothTookIt) {
  Io s;
  s.io.KeepBusFramesForCollector();
  constexpr std::uint32_t kFrames = 40000;
  std::uint32_t routed = 0, collected = 0;
  std::size_t most_kept = 0;
  for (std::uint32_t k = 0; k < kFrames; ++k) {
    s.io.bus_frames().push_back(FrameNumber(k));
    for (const CanFrame& f : s.io.TakeUnrouted()) EXPECT_EQ(f.id, routed++);
    if (k % 10 == 9) {  // the output reader polls less often than the devices take
      for (const CanFrame& f : s.io.TakeUncollected()) EXPECT_EQ(f.id, collected++);
    }
    most_kept = std::max(most_kept, s.io.bus_frames().size());
  }
  EXPECT_EQ(routed, kFrames);
  EXPECT_EQ(collected, kFrames);  // every frame once, in order
  EXPECT_LE(most_kept, 10u);
  EXPECT_EQ(s.io.bus_frames().size(), 0u);
}

}  // namespace
}  // namespace hil::harness

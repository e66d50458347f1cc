// ReplayDevice: recorded chunks and frames come out at their recorded times, in time order, with
// their recorded byte timing and every frame flag; driven by the Engine in virtual mode, a
// serial endpoint's capture holds exactly the recorded times.
#include "hil/harness/replay/replay_device.h"

#include <unistd.h>

#include <filesystem>

#include <gtest/gtest.h>

#include "hil/firmware_emu/link/can_wire_frame.h"
#include "hil/harness/engine/engine.h"
#include "hil/harness/engine/virtual_pacer.h"
#include "hil/harness/links/capture_format.h"
#include "hil/harness/run/device_set.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;

ReplayItem Chunk(std::int64_t t_ns, int port, std::string bytes, std::int64_t period_ns) {
  ReplayItem item;
  item.t = TimeFromNs(t_ns);
  item.port = port;
  item.record.t_emu_ns = t_ns;
  item.record.byte_period_ns = period_ns;
  item.record.name = "chunk" + std::to_string(t_ns);
  item.record.bytes = std::move(bytes);
  return item;
}

TEST(ReplayDeviceTest, HandsOverEachInstantInTimeOrderWithRecordedTiming) {
  std::vector<ReplayItem> items;
  items.push_back(Chunk(3000, 1, "late", 50));
  items.push_back(Chunk(1000, 0, "first", 1042));
  items.push_back(Chunk(1000, 1, "same instant", 7));
  ReplayDevice dev(std::move(items), {9600, 115200});
  EXPECT_EQ(dev.serial_port_count(), 2);
  EXPECT_EQ(dev.baud(1), 115200);
  ASSERT_EQ(dev.next_event_time(), TimeFromNs(1000));

  TruthSample at;
  at.t = dev.next_event_time();
  DeviceOutput out;
  dev.OnEvent(at, out);
  ASSERT_EQ(out.serial.size(), 2u);  // both items of t = 1000 ns, in their given order
  EXPECT_EQ(out.serial[0].bytes, "first");
  EXPECT_EQ(out.serial[0].port, 0);
  ASSERT_TRUE(out.serial[0].byte_period.has_value());
  EXPECT_EQ(out.serial[0].byte_period->count(), 1042);
  EXPECT_EQ(out.serial[1].bytes, "same instant");
  EXPECT_EQ(out.serial[1].name, "chunk1000");
  EXPECT_EQ(dev.next_event_time(), TimeFromNs(3000));

  out.clear();
  at.t = dev.next_event_time();
  dev.OnEvent(at, out);
  ASSERT_EQ(out.serial.size(), 1u);
  EXPECT_EQ(out.serial[0].t_ready, TimeFromNs(3000));
  EXPECT_EQ(dev.next_event_time(), Time::max());  // nothing left
}

TEST(ReplayDeviceTest, RecordedFramesKeepEveryFlagOnTheWire) {
  link::CanWireFrame w;
  w.id = 0x123;
  w.rtr = true;
  w.len = 4;  // the length asked for
  CanFrame f = link::ToDeviceFrame(w, TimeFromNs(5));
  EXPECT_EQ(link::FromDeviceFrame(f), w);
  link::CanWireFrame fd;
  fd.id = 0x18FF0080;
  fd.extended = true;
  fd.fd = true;
  fd.fd_flags = 1;  // BRS
  fd.len = 12;
  for (std::uint8_t i = 0; i < 12; ++i) fd.data[i] = static_cast<std::uint8_t>(i + 1);
  EXPECT_EQ(link::FromDeviceFrame(link::ToDeviceFrame(fd, TimeFromNs(6))), fd);
}

class OnlyTheEnd final : public EngineMonitor {
 public:
  void OnDeviceEvents(Time t) override { served.push_back(t); }
  bool KeepGoing(Time) override { return true; }
  std::vector<Time> served;
};

TEST(ReplayDeviceTest, TheEnginePlaysItOnItsRecordedTimesInVirtualMode) {
  const fs::path dir =
      fs::temp_directory_path() / ("hil_replay_device_" + std::to_string(getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir / "captures");
  {
    DeviceSet set;
    std::vector<ReplayItem> items{Chunk(2'000'000, 0, "abc", 1'000'000),
                                  Chunk(1'000'000, 0, "xy", 260417)};
    set.devices.push_back(std::make_unique<ReplayDevice>(std::move(items), std::vector<int>{9600}));
    std::vector<std::unique_ptr<SerialEndpoint>> ports;
    // a tiny transmit buffer: recorded chunks do not go through the UART model, so none is dropped
    ports.push_back(std::make_unique<SerialEndpoint>("ttyGPS", (dir / "ttyGPS").string(), 9600, 1,
                                                     (dir / "captures" / "ttyGPS.cap").string()));
    set.endpoints.push_back(std::move(ports));
    VirtualPacer pacer;
    Engine engine(EngineDevices{set.devices, set.endpoints, set.can.get(), set.base, set.steering},
                  pacer, std::make_unique<NoHostTurns>(), TimeFromNs(2'000'000));
    OnlyTheEnd monitor;
    engine.Run(monitor, nullptr);
    engine.Flush();
    EXPECT_EQ(monitor.served, (std::vector<Time>{TimeFromNs(1'000'000), TimeFromNs(2'000'000)}));
  }
  const Capture c = ReadCapture(dir / "captures" / "ttyGPS.cap");
  ASSERT_EQ(c.records.size(), 2u);
  EXPECT_EQ(c.records[0].bytes, "xy");
  EXPECT_EQ(c.records[0].t_emu_ns, 1'000'000);
  EXPECT_EQ(c.records[0].byte_period_ns, 260417);
  EXPECT_EQ(c.records[1].bytes, "abc");
  EXPECT_EQ(c.records[1].t_emu_ns, 2'000'000);
  EXPECT_EQ(c.records[1].byte_period_ns, 1'000'000);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace hil::harness

// A closed loop's actuator frames on a real vcan0 (DeviceIo with hold_actuators, as virtual mode's
// host turns use it): the steering ECU's status frames reach the controller's socket only at the
// next host turn (ReleaseHeld), not when the ECU makes them, and once AwaitReleasedFrames has
// returned the controller's socket holds them already. Before, the frames went on the bus when
// made, and which of them guidanced had read when a solution came depended on the machine
// (tractor_autosteer_command_loss_socketcan: a stale reset request, engagements 3 instead of 2).
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "hil/harness/engine/device_io.h"
#include "hil/harness/engine/virtual_pacer.h"
#include "hil/harness/links/can_endpoint.h"

#include "vcan_test_util.h"

namespace hil::harness {
namespace {

namespace fs = std::filesystem;
using link::test::Iface;

constexpr std::int64_t kStartUnixNs = 1370851200000000000LL;  // 2013-06-10T08:00:00Z

/// A device that makes nothing by itself (the test dispatches its output).
class QuietDevice : public Device {
 public:
  const std::string& name() const override { return name_; }
  Time next_event_time() const override { return Time::max(); }
  void OnEvent(const TruthSample& truth, DeviceOutput& out) override { (void)truth, (void)out; }
  int baud(int port) const override { return (void)port, 115200; }
  int serial_port_count() const override { return 0; }

 private:
  std::string name_ = "steering_ecu";
};

CanFrame MachineInfoAt(double t_s, std::uint8_t k) {
  CanFrame f;
  f.t = TimeFromSeconds(t_s);
  f.id = 0x0CACFF1C;  // Guidance Machine Info from the ECU (0x1C)
  f.len = 8;
  f.data[0] = k;
  return f;
}

fs::path TempCaptureDir() {
  const fs::path d = fs::temp_directory_path() / ("hil_device_io_hold_" + std::to_string(getpid()));
  fs::create_directories(d);
  return d;
}

/// The run's bus, the steering ECU as an actuator, and a controller's socket on the same bus.
struct ClosedLoopBus {
  explicit ClosedLoopBus(bool hold)
      : dir(TempCaptureDir()), can(Iface(), dir.string(), UnixTimeFromNs(kStartUnixNs)) {
    devices.push_back(std::make_unique<QuietDevice>());
    endpoints.resize(1);
    io = std::make_unique<DeviceIo>(
        EngineDevices{devices, endpoints, &can, nullptr, devices[0].get()}, pacer, hold);
  }
  ~ClosedLoopBus() { fs::remove_all(dir); }
  /// The ECU's output at an event: two status frames.
  void EcuMakesStatus() {
    DeviceOutput out;
    out.can = {MachineInfoAt(15.3, 1), MachineInfoAt(15.4, 2)};
    io->Dispatch(0, out);
  }

  fs::path dir;
  VirtualPacer pacer;
  std::vector<std::unique_ptr<Device>> devices;
  std::vector<std::vector<std::unique_ptr<SerialEndpoint>>> endpoints;
  link::SocketCanPort controller{Iface()};  // opened before the frames are made
  CanEndpoint can;
  std::unique_ptr<DeviceIo> io;
};

TEST(DeviceIoHoldVcanTest, ActuatorFramesReachTheControllerAtTheTurnNotWhenMade) {
  ClosedLoopBus bus(true);
  bus.EcuMakesStatus();
  EXPECT_TRUE(link::test::ReceiveFrames(bus.controller, 1, std::chrono::milliseconds(200)).empty())
      << "the ECU's frames went on the bus before the host turn";
  ASSERT_TRUE(bus.io->ReleaseHeld());
  const auto got = link::test::ReceiveFrames(bus.controller, 2, std::chrono::seconds(1));
  ASSERT_EQ(got.size(), 2u);
  EXPECT_EQ(got[0].frame.data[0], 1);  // in the order they were made
  EXPECT_EQ(got[1].frame.data[0], 2);
  EXPECT_FALSE(bus.io->ReleaseHeld());  // nothing held any more
}

TEST(DeviceIoHoldVcanTest, AfterTheAwaitTheControllersSocketHoldsTheReleasedFrames) {
  ClosedLoopBus bus(true);
  EXPECT_FALSE(bus.io->AwaitReleasedFrames());  // nothing released: no wait
  bus.EcuMakesStatus();
  ASSERT_TRUE(bus.io->ReleaseHeld());
  ASSERT_TRUE(bus.io->AwaitReleasedFrames());
  // no waiting here: the kernel handed them to every socket with the echoes AwaitReleasedFrames
  // read (what lets a host turn then wait only for the host to sleep)
  for (const int k : {1, 2}) {
    const auto r = bus.controller.Receive(Duration::zero());
    ASSERT_TRUE(r.has_value()) << "frame " << k << " not in the controller's socket yet";
    EXPECT_EQ(r->frame.data[0], k);
  }
  EXPECT_FALSE(bus.io->AwaitReleasedFrames());  // awaited once
}

TEST(DeviceIoHoldVcanTest, WithoutHoldingFramesGoOnTheBusWhenMade) {
  ClosedLoopBus bus(false);  // open loop, free running: as before
  bus.EcuMakesStatus();
  EXPECT_EQ(link::test::ReceiveFrames(bus.controller, 2, std::chrono::seconds(1)).size(), 2u);
  EXPECT_FALSE(bus.io->ReleaseHeld());
}

}  // namespace
}  // namespace hil::harness

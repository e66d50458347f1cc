// The steering ECU as a scheduler device on both transports: SLCAN records on its serial port
// and frames from the bus reach the ECU at their arrival; its status frames leave as records or
// CAN frames every 100 ms; its road-wheel angle drives the truth (left positive); bad commands are
// refused with the ECU's exit reason and counted; missing commands are counted at control ticks.
#include "hil/firmware_emu/actuator/isobus_steering_device.h"

#include <cmath>

#include <gtest/gtest.h>

namespace hil::actuator {
namespace {

Time Ms(std::int64_t ms) { return TimeFromNs(ms * 1000000); }

IsobusSteeringDeviceConfig Config(IsobusTransport transport) {
  IsobusSteeringDeviceConfig c;
  c.transport = transport;
  c.ecu.wheelbase_m = 2.3;
  c.speed_mps = 1.0;
  c.first_command_due = Ms(0);
  return c;
}

// Runs the device's grid events up to `t_end` at 1 m/s; returns the last vehicle command.
VehicleCommand RunTo(IsobusSteeringDevice& d, Time t_end, DeviceOutput& out) {
  VehicleCommand last;
  while (d.next_event_time() <= t_end) {
    TruthSample s;
    s.t = d.next_event_time();
    s.speed_mps = 1.0;
    d.OnEvent(s, out);
    if (auto c = d.TakeVehicleCommand()) last = *c;
  }
  return last;
}

// "T0CAD1C80 8 <curvature raw LE> <status|0xFC> FF…": a Guidance System Command record.
std::string CommandRecord(double curvature_per_km, int status, int len = 8) {
  const auto raw = static_cast<unsigned>(std::lround((curvature_per_km + 8032.0) * 4.0));
  char buf[64];
  std::snprintf(buf, sizeof buf, "T0CAD1C80%d%02X%02X%02X", len, raw & 0xFF, raw >> 8,
                0xFC | status);
  std::string s = buf;
  for (int i = 3; i < len; ++i) s += "FF";
  return s + "\r";
}

TEST(IsobusSteeringDeviceTest, SlcanCommandsSteerTheTruthLeftPositive) {
  IsobusSteeringDevice d(Config(IsobusTransport::kSlcan));
  ASSERT_EQ(d.serial_port_count(), 1);
  DeviceOutput out;
  d.OnHostBytes(0, Ms(0), "C\rS5\rO\r", out);
  ASSERT_EQ(out.serial.size(), 1u);
  EXPECT_EQ(out.serial[0].bytes, "\r\r\r");
  out.clear();
  // 100 km⁻¹ to the left (ISOBUS −100) every 100 ms for 3 s
  VehicleCommand c;
  for (int k = 0; k < 30; ++k) {
    d.OnHostBytes(0, Ms(100 * k), CommandRecord(-100, 1), out);
    c = RunTo(d, Ms(100 * k + 99), out);
  }
  EXPECT_TRUE(d.ecu().engaged());
  EXPECT_NEAR(std::tan(c.steer_or_yaw_rate) / 2.3, 0.1, 0.002) << "κ = tan δ / L, left positive";
  EXPECT_DOUBLE_EQ(c.speed_mps, 1.0);
  // the status pair every 100 ms as SLCAN records, plus the Z acknowledgements
  int machine_info = 0, wheel_speed = 0;
  for (const SerialMessage& m : out.serial) {
    machine_info += m.bytes.rfind("T0CACFF1C8", 0) == 0 ? 1 : 0;
    wheel_speed += m.bytes.rfind("T0CFE481C8", 0) == 0 ? 1 : 0;
  }
  EXPECT_EQ(machine_info, 30);
  EXPECT_EQ(wheel_speed, 30);
  EXPECT_EQ(d.ecu().counters().commands_accepted, 30u);
  EXPECT_EQ(d.counters().missing_commands, 0u);
}

TEST(IsobusSteeringDeviceTest, BadCommandsAreRefusedAndCountedWithTheExitReason) {
  IsobusSteeringDevice d(Config(IsobusTransport::kSlcan));
  DeviceOutput out;
  d.OnHostBytes(0, Ms(0), "S5\rO\r" + CommandRecord(0, 1), out);
  RunTo(d, Ms(50), out);
  ASSERT_TRUE(d.ecu().engaged());
  d.OnHostBytes(0, Ms(60), CommandRecord(0, 1, 3), out);          // wrong length
  d.OnHostBytes(0, Ms(70), "T0CAD1C818807DFDFFFFFFFFFF\r", out);  // unknown source 0x81
  d.OnHostBytes(0, Ms(80), "T0CAD1C80GG\r", out);                 // not a record: BEL
  RunTo(d, Ms(90), out);
  EXPECT_TRUE(d.ecu().engaged()) << "ignored frames do not disengage";
  d.OnHostBytes(0, Ms(95), "T0CAD1C80880FBFDFFFFFFFFFF\r", out);  // raw 64384: out of range
  RunTo(d, Ms(200), out);
  EXPECT_FALSE(d.ecu().engaged());
  EXPECT_EQ(d.ecu().exit_reason(), ExitReason::kRemoteCommandOutOfRange);
  EXPECT_EQ(d.ecu().counters().wrong_length, 1u);
  EXPECT_EQ(d.ecu().counters().unknown_source, 1u);
  EXPECT_EQ(d.ecu().counters().out_of_range, 1u);
  EXPECT_EQ(d.adapter().counters().refused, 1u);
}

TEST(IsobusSteeringDeviceTest, SocketCanFramesAndTheWatchdogOnCommandLoss) {
  IsobusSteeringDeviceConfig cfg = Config(IsobusTransport::kSocketCan);
  IsobusSteeringDevice d(cfg);
  EXPECT_EQ(d.serial_port_count(), 0);
  DeviceOutput out;
  CanFrame f;
  f.id = 0x0CAD1C80;
  f.len = 8;
  f.data = {};
  f.data[0] = 0x80;
  f.data[1] = 0x7D;  // 0 km⁻¹
  f.data[2] = 0xFD;
  for (int i = 3; i < 8; ++i) f.data[i] = 0xFF;
  for (int k = 0; k < 10; ++k) {
    d.OnBusFrame(Ms(100 * k), f, out);
    RunTo(d, Ms(100 * k + 99), out);
  }
  EXPECT_TRUE(d.ecu().engaged());
  EXPECT_TRUE(out.serial.empty());
  EXPECT_EQ(out.can.size(), 20u) << "Machine Info and Wheel-based Speed every 100 ms";
  RunTo(d, Ms(2000), out);  // the controller went silent after 0.9 s
  EXPECT_FALSE(d.ecu().engaged());
  EXPECT_EQ(d.ecu().exit_reason(), ExitReason::kRemoteCommandTimeout);
  EXPECT_EQ(d.ecu().counters().last_watchdog_trip, Ms(900 + 300));
  EXPECT_GE(d.counters().missing_commands, 7u) << "ticks 1.3 s … 2.0 s";
}

}  // namespace
}  // namespace hil::actuator

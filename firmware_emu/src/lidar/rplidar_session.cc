// RplidarDevice's request session: what each request does and answers (vectors/rplidar/README.md).
#include <cstdio>

#include "hil/firmware_emu/lidar/rplidar_device.h"

namespace hil::lidar {

std::string RplidarDevice::Banner() const {
  char buf[128];
  std::snprintf(buf, sizeof buf,
                "RP LIDAR System.\r\nFirmware Ver %u.%02u - rc0, HW Ver %u\r\nModel: %02X\r\n",
                unsigned{config_.info.firmware_major}, unsigned{config_.info.firmware_minor},
                unsigned{config_.info.hardware}, unsigned{config_.info.model});
  return buf;
}

void RplidarDevice::Handle(const RequestFrame& r, DeviceOutput& out) {
  ++stats_.requests;
  const bool scanning = mode_ != Mode::kIdle;
  switch (static_cast<Request>(r.cmd)) {
    case Request::kStop:
      mode_ = Mode::kIdle;
      next_event_ = Time::max();
      return;
    case Request::kReset:
      mode_ = Mode::kIdle;
      next_event_ = Time::max();
      ++stats_.resets;
      out.serial.push_back({now_ + config_.banner_delay, 0, Banner(), "RPLIDAR-BANNER"});
      return;
    case Request::kScan:
    case Request::kForceScan:
      Send(EncodeDescriptor(kNodeSize, true, DataType::kScanNode), "RPLIDAR-DESCRIPTOR", out);
      StartScan(Mode::kScan, r.cmd == static_cast<std::uint8_t>(Request::kForceScan));
      return;
    case Request::kExpressScan:
      if (r.payload.size() != 5 || r.payload[0] != 0) break;  // legacy capsules only
      Send(EncodeDescriptor(kCapsuleSize, true, DataType::kExpressCapsule), "RPLIDAR-DESCRIPTOR",
           out);
      StartScan(Mode::kExpress, false);
      return;
    case Request::kSetMotorPwm:
      if (config_.model != RplidarModel::kA2M8 || r.payload.size() != 2) break;
      if (r.payload[0] == 0 && r.payload[1] == 0) {
        motor_on_ = false;
        next_event_ = Time::max();
      } else if (!motor_on_) {
        StartMotor(now_);
        if (scanning) StartScan(mode_, false);
      }
      return;
    default:
      if (scanning) break;  // while scanning only STOP, RESET, scans and the motor (UNVERIFIED)
      switch (static_cast<Request>(r.cmd)) {
        case Request::kGetInfo:
          Send(EncodeDescriptor(20, false, DataType::kDeviceInfo) + EncodeDeviceInfo(config_.info),
               "RPLIDAR-INFO", out);
          return;
        case Request::kGetHealth:
          Send(EncodeDescriptor(3, false, DataType::kHealth) + EncodeHealth(0, 0), "RPLIDAR-HEALTH",
               out);
          return;
        case Request::kGetSampleRate:
          Send(EncodeDescriptor(4, false, DataType::kSampleRate) +
                   EncodeSampleRate(config_.standard_sample_us, config_.express_sample_us),
               "RPLIDAR-SAMPLERATE", out);
          return;
        case Request::kGetAccBoardFlag:
          Send(EncodeDescriptor(4, false, DataType::kAccBoardFlag) +
                   EncodeU32(config_.model == RplidarModel::kA2M8 ? 1u : 0u),
               "RPLIDAR-ACCBOARD", out);
          return;
        default:
          break;
      }
  }
  ++stats_.ignored;
}

}  // namespace hil::lidar

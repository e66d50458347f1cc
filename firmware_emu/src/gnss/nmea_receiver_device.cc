#include "hil/firmware_emu/gnss/nmea_receiver_device.h"

#include "hil/firmware_emu/gnss/nmea_encoder.h"

namespace hil::gnss {

NmeaReceiverDevice::NmeaReceiverDevice(const NmeaReceiverConfig& config, std::uint64_t seed)
    : config_(config), model_(config.model, seed) {}

void NmeaReceiverDevice::OnEvent(const TruthSample& truth, DeviceOutput& out) {
  const double dt_s = first_ ? 0.0 : ToSeconds(truth.t - last_epoch_);
  first_ = false;
  last_epoch_ = truth.t;
  last_fix_ = model_.Calc(truth, config_.start_unix_ns + ToNs(truth.t), dt_s);
  const Time t_ready = truth.t + config_.output_lag;
  out.serial.push_back({t_ready, 0, nmea::EncodeRmc(last_fix_), "NMEA-RMC"});
  out.serial.push_back({t_ready, 0, nmea::EncodeGga(last_fix_), "NMEA-GGA"});
  next_epoch_ = truth.t + PeriodFromHz(config_.rate_hz);
}

}  // namespace hil::gnss

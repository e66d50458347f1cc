#include "hil/firmware_emu/gnss/receiver_profile.h"

#include <stdexcept>

namespace hil::gnss {

ReceiverProfile ProfileByName(const std::string& name) {
  ReceiverProfile p;
  p.name = name;
  if (name == "neo-5m") {
    p.nmea_rates = {{0x00, 1}, {0x01, 1}, {0x02, 1}, {0x03, 1}, {0x04, 1}, {0x05, 1}};
    p.banner = {"u-blox ag - www.u-blox.com",
                "HW  UBX-G50xx  00040005 ",
                "EXT CORE 6.02 (36023) Oct 15 2009 16:52:22",
                "ROM BASE 5.00 (28483) Jun  6 2008 14:45:11",
                "MOD NEO-5M-0",
                "ANTSUPERV=AC SD PDoS SR",
                "ANTSTATUS=OK"};
    p.sw_version = "6.02 (36023)";
    p.hw_version = "00040005";
    p.version_extensions = {"ROM BASE 5.00 (28483)"};  // 30 characters at most
    return p;
  }
  if (name == "rtk") {
    p.baud = 115200;
    p.rate_hz = 10.0;
    p.max_rate_hz = 20.0;
    p.cfg_rate_max_hz = 20.0;
    p.nmea_rates = {{0x00, 1}, {0x04, 1}, {0x05, 1}, {0x02, 10}, {0x03, 10}};
    p.sw_version = "RTK 1.00";
    p.hw_version = "00000000";
    p.format.minute_decimals = 7;
    p.format.diff_station = true;
    p.fix_state.ttff_hot_s = 5.0;
    p.fix_state.reacquisition_s = 2.0;
    p.model.horizontal_sigma_m = 0.008;
    p.model.vertical_sigma_m = 0.015;
    p.model.correlation_time_s = 30.0;
    p.model.velocity_sigma_mps = 0.01;
    p.model.common_fraction = 0.0;
    p.rtk = true;
    return p;
  }
  throw std::invalid_argument("unknown GNSS receiver profile '" + name + "' (known: neo-5m, rtk)");
}

}  // namespace hil::gnss

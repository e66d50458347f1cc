#include "hil/firmware_emu/link/can_wire_frame.h"

#include <algorithm>

namespace hil::link {

CanWireFrame FromDeviceFrame(const CanFrame& f) {
  CanWireFrame w;
  w.id = f.id & (f.extended ? 0x1FFFFFFFU : 0x7FFU);
  w.extended = f.extended;
  w.fd = f.fd;
  w.rtr = f.rtr;
  w.error = f.error;
  w.fd_flags = f.fd_flags;
  w.len = std::min<std::uint8_t>(f.len, f.fd ? 64 : 8);
  std::copy_n(f.data.begin(), w.len, w.data.begin());
  return w;
}

CanFrame ToDeviceFrame(const CanWireFrame& w, Time t) {
  CanFrame f;
  f.t = t;
  f.id = w.id;
  f.extended = w.extended;
  f.fd = w.fd;
  f.rtr = w.rtr;
  f.error = w.error;
  f.fd_flags = w.fd_flags;
  f.len = w.len;  // a remote frame's length is the one it asks for; it carries no data
  std::copy_n(w.data.begin(), w.rtr ? 0 : w.len, f.data.begin());
  return f;
}

}  // namespace hil::link

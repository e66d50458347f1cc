#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <functional>
#include <optional>
#include <string>

#include "hil/harness/engine/device_io.h"

namespace hil::harness {

/// What the programs wrote, read at their turns and waiting for the emulated time it reaches its
/// device: serial bytes (by device and port) and CAN frames for the emulated devices on the bus.
/// Both host-turn policies (VirtualHostTurns, ClockedHostTurns) read and deliver through it; they
/// differ only in when a turn is due and in what they do after a delivery.
class HostArrivals {
 public:
  /// A host's bytes delivered to a device.
  struct Delivered {
    std::size_t device = 0;
    Time t{};
    bool answered = false;  ///< the device queued serial bytes in reply
  };

  /// The earliest pending arrival; Time::max() when none.
  Time Next() const;
  bool has_bytes() const { return !bytes_.empty(); }

  /// Reads every host port with something to read (one poll for all) and queues it, arriving at
  /// `t_rx`; `on_read` (if given) is told each endpoint read from.
  void ReadHosts(Time t_rx, DeviceIo& io,
                 const std::function<void(const SerialEndpoint&)>& on_read = {});
  /// The frames the programs put on the bus, arriving at `t_rx`; those for the emulated devices
  /// are queued. Returns how many were queued.
  std::size_t ReadBus(Time t_rx, DeviceIo& io);

  /// The first host bytes due by `limit`, delivered to their device (which may answer: the answer
  /// is dispatched). Nothing when none is due.
  std::optional<Delivered> DeliverBytes(Time limit, DeviceIo& io, DeviceOutput& out);
  /// The first bus frame due by `limit`, delivered. False when none is due.
  bool DeliverFrame(Time limit, DeviceIo& io, DeviceOutput& out);

 private:
  struct HostBytes {
    Time t{};
    std::size_t device = 0, port = 0;
    std::string bytes;
  };
  struct BusArrival {
    Time t{};
    CanFrame frame;
  };
  std::deque<HostBytes> bytes_;    // in time order, not yet delivered
  std::deque<BusArrival> frames_;  // others' frames, in time order
};

}  // namespace hil::harness

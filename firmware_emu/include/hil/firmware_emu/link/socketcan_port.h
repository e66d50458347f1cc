#pragma once
/// @file
/// A raw SocketCAN socket (PF_CAN, SOCK_RAW, CAN_RAW) bound to one named interface (`vcan0`,
/// `can0`). Classic frames always; CAN FD when asked for and the interface's MTU allows it.
/// Receives carry the kernel's receive timestamp (SO_TIMESTAMPNS, CLOCK_REALTIME). Faults are
/// counted, never thrown in the data path: error frames the controller reports (CAN_RAW_ERR_FILTER:
/// bus-off, protocol/bus errors, controller RX/TX overflow) and frames the socket's receive queue
/// dropped (SO_RXQ_OVFL).
///
/// The development machines' kernel has no AF_CAN: construction then throws, and Available() says
/// so up front. CAN tests run in the vcan VM (ci/vcan/run_in_vm).

#include <cstdint>
#include <optional>
#include <string>

#include "hil/firmware_emu/link/can_wire_frame.h"
#include "hil/firmware_emu/sim_time.h"
#include "hil/firmware_emu/unix_time.h"
#include "hil/firmware_emu/wall_time.h"

namespace hil::link {

/// A frame read from the bus.
struct ReceivedCanFrame {
  CanWireFrame frame;
  UnixTime t_kernel{};     ///< kernel receive time (CLOCK_REALTIME); the epoch if none came
  WallTime t_read_mono{};  ///< when this process read it
  bool own = false;        ///< our own frame echoed back (receive_own_frames)
};

/// Counters of one port.
struct CanPortStats {
  std::uint64_t frames_sent = 0;
  std::uint64_t send_failures = 0;    ///< write errors other than a full queue
  std::uint64_t send_queue_full = 0;  ///< ENOBUFS/EAGAIN: the interface's TX queue was full
  std::uint64_t frames_received =
      0;  ///< data and remote frames others sent (error frames and own echoes not included)
  std::uint64_t own_frames_received = 0;  ///< our own frames echoed back (receive_own_frames)
  std::uint64_t error_frames = 0;         ///< every error frame
  std::uint64_t bus_off = 0;              ///< error frames with the bus-off class
  std::uint64_t bus_errors =
      0;  ///< protocol violations, bus errors, missing ACK, transceiver faults
  std::uint64_t controller_overflows = 0;  ///< controller RX/TX buffer overflow reports
  std::uint64_t rx_queue_drops = 0;  ///< frames the socket receive queue dropped (SO_RXQ_OVFL)
};

class SocketCanPort {
 public:
  struct Options {
    bool fd = false;  ///< ask for CAN FD frames (granted when the MTU allows it)
    bool receive_own_frames =
        false;                 ///< also receive what this socket sends (CAN_RAW_RECV_OWN_MSGS)
    bool loopback = true;      ///< other sockets on this host see our frames (CAN_RAW_LOOPBACK)
    bool error_frames = true;  ///< subscribe to every error class
    /// receive queue size (SO_RCVBUFFORCE when privileged, else SO_RCVBUF up to the system limit):
    /// the kernel's default (~200 kB, a few thousand frames) overflows when the reader is held up
    /// for a moment while a sender bursts, e.g. canplayer replaying at 1 ms gaps on a loaded
    /// machine
    int receive_buffer_bytes = 4 << 20;
  };

  /// Opens and binds a raw socket on `ifname`.
  /// @throws std::runtime_error naming the interface and the system error (e.g. "Address family not
  /// supported by protocol" on a kernel without CAN, "No such device" for an unknown interface).
  SocketCanPort(const std::string& ifname, const Options& options);
  explicit SocketCanPort(const std::string& ifname) : SocketCanPort(ifname, Options{}) {}
  ~SocketCanPort();
  SocketCanPort(const SocketCanPort&) = delete;
  SocketCanPort& operator=(const SocketCanPort&) = delete;

  /// Sends one frame. Returns the CLOCK_MONOTONIC time just after the kernel accepted it, or
  /// nothing when it did not (counted; a full TX queue is retried for up to 10 ms first).
  std::optional<WallTime> Send(const CanWireFrame& frame);
  /// Waits up to `timeout` (zero: poll) for a frame. Error frames are counted and returned too
  /// (frame.error set); nothing on timeout.
  std::optional<ReceivedCanFrame> Receive(Duration timeout);

  const std::string& ifname() const { return ifname_; }
  /// Whether FD frames can be sent and received on this socket.
  bool fd_enabled() const { return fd_enabled_; }
  /// The interface's MTU: 16 classic only, 72 CAN FD capable.
  int mtu() const { return mtu_; }
  int fd() const { return fd_; }
  const CanPortStats& stats() const { return stats_; }

  /// True when this kernel can open a raw CAN socket at all.
  static bool Available();

 private:
  void CountErrorFrame(const CanWireFrame& f);

  std::string ifname_;
  int fd_ = -1;
  int mtu_ = 0;
  bool fd_enabled_ = false;
  std::uint32_t last_drop_count_ = 0;
  CanPortStats stats_;
};

}  // namespace hil::link

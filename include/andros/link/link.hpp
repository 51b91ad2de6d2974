#pragma once
/// Where frames go: a serial device (or the simulator's pseudo-terminal) or a
/// TCP serial server. A link never throws and never blocks the frame clock
/// for long: when the far end is gone it reports so, keeps reconnecting on its
/// own schedule, and the run loop goes on computing frames.

#include <cstdint>
#include <memory>
#include <string>

#include "andros/link/link_status.hpp"
#include "andros/protocol/frame.hpp"

namespace andros::link {

class Link {
 public:
  virtual ~Link() = default;

  /// Sends one frame if the link can take it now; when the link is down, may
  /// try to reconnect first (at most every few hundred ms). now_ns is the
  /// monotonic clock, for the link's own retry timing.
  virtual SendResult send(const protocol::Frame& frame, std::int64_t now_ns) = 0;

  /// Waits, at most timeout_ms, until the bytes written have left (a serial
  /// driver's queue is empty; a TCP server has acknowledged them); then
  /// closes. False when they had not: the link was down, or they were still
  /// waiting at the timeout.
  virtual bool drain_and_close(int timeout_ms) = 0;

  [[nodiscard]] virtual LinkState state() const = 0;
  /// What the link is, for the operator ("/dev/ttyUSB0 9600 8N1", "tcp 10.0.0.5:4001").
  [[nodiscard]] virtual const std::string& name() const = 0;
  /// Why it is not up (the last error), empty when up.
  [[nodiscard]] virtual const std::string& detail() const = 0;
  [[nodiscard]] virtual const LinkCounters& counters() const = 0;
  /// False while the far end may keep frames to deliver later (a TCP server
  /// that stalled and has not been seen reading since): the run loop then
  /// sends only neutral frames, so that nothing held there can move the vehicle.
  [[nodiscard]] virtual bool far_end_reading() const { return true; }

  /// Its state, detail, counters and far_end_reading() as one value, for the run loop's report.
  [[nodiscard]] LinkStatus status() const { return {state(), far_end_reading(), detail(), counters()}; }
};

}  // namespace andros::link

#pragma once
/// What the serial and TCP links share: opening on their own retry schedule,
/// the output-queue check before each frame, the loss of a connection on a
/// write error, and one log line per change of state.

#include <string>

#include "andros/base/clock.hpp"
#include "andros/base/unique_fd.hpp"
#include "andros/link/link.hpp"

namespace andros::link {

class ReconnectingLink : public Link {
 public:
  SendResult send(const protocol::Frame& frame, std::int64_t now_ns) final;
  bool drain_and_close(int timeout_ms) final;

  [[nodiscard]] LinkState state() const final { return state_; }
  [[nodiscard]] const std::string& name() const final { return name_; }
  [[nodiscard]] const std::string& detail() const final { return detail_; }
  [[nodiscard]] const LinkCounters& counters() const final { return counters_; }

 protected:
  /// min_retry_ms doubles after each failed attempt up to max_retry_ms. The
  /// drain at shutdown waits on drain_clock (nullptr: the monotonic clock);
  /// all other timing is the now_ns each send() is given.
  ReconnectingLink(std::string name, int min_retry_ms, int max_retry_ms, Clock* drain_clock = nullptr);

  enum class OpenResult : std::uint8_t { kOpen, kPending, kFailed };
  /// One attempt to open (or to finish opening) the far end into fd_. On
  /// kFailed, sets why (an errno text); kPending is called again next tick.
  virtual OpenResult open_step(std::int64_t now_ns, std::string& why) = 0;
  /// Bytes written but still in the driver, or -1 with errno set.
  virtual int queued_bytes() const = 0;
  /// Bytes written that the far end does not have yet, for the drain at
  /// shutdown (TCP: also those sent and not acknowledged).
  virtual int undelivered_bytes() const { return queued_bytes(); }
  /// Before each frame while up: bytes that hold this frame back (0: send
  /// it), or -1 with errno set. Sets stalled to why when the far end has
  /// taken nothing for too long: the link is then lost and reopened.
  virtual int backlog(std::int64_t now_ns, std::string& stalled);
  virtual long write_bytes(const std::uint8_t* data, std::size_t size);
  /// After the queue is empty: let the last bytes leave the hardware (tcdrain).
  virtual void finish_drain() {}
  /// Closes fd_ (when the link is lost, closed, or fails to open).
  virtual void close_fd() { fd_.reset(); }

  UniqueFd fd_;

 private:
  void lose(const std::string& why, std::int64_t now_ns);
  void fail_open(const std::string& why, std::int64_t now_ns);

  RealClock real_clock_;
  Clock& drain_clock_;
  std::string name_;
  std::string detail_ = "not opened yet";
  LinkState state_ = LinkState::kConnecting;
  LinkCounters counters_;
  int min_retry_ms_;
  int max_retry_ms_;
  int retry_ms_;
  std::int64_t next_attempt_ns_ = 0;
  static constexpr std::int64_t kFlapNs = kNsPerSecond;
  /// A connection lost sooner than this after it came up (a server that
  /// accepts and closes, a stalled one) does not reset the back-off.
  static constexpr std::int64_t kStableNs = 5'000'000'000;
  std::int64_t up_since_ns_ = 0;
  std::string last_loss_;
  bool quiet_ = false;  ///< flapping: the loss and the next recovery go unlogged
};

}  // namespace andros::link

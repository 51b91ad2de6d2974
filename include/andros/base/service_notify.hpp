#pragma once
/// The service manager's side channel (systemd's sd_notify protocol,
/// docs/running.md "As a service"): READY=1, WATCHDOG=1, STATUS=...,
/// RELOADING=1 and STOPPING=1 as datagrams to $NOTIFY_SOCKET.
///
/// A datagram sender of its own rather than libsystemd's sd_notify(): that
/// one opens a socket per message and sends without MSG_DONTWAIT, so a
/// receiver that stops reading (a hung manager, a test socket nobody reads)
/// blocks the caller once its queue is full, and the caller here is the frame
/// loop. This one opens its socket once and never waits: a message that does
/// not fit is dropped.

#include <cstdint>
#include <string>
#include <string_view>

#include "andros/base/clock.hpp"
#include "andros/base/unique_fd.hpp"

namespace andros {

class ServiceNotifier {
 public:
  /// From the environment the manager sets: NOTIFY_SOCKET (a path, or
  /// @name for an abstract socket), WATCHDOG_USEC and WATCHDOG_PID. Inactive
  /// (every call a no-op) when NOTIFY_SOCKET is unset or unusable.
  static ServiceNotifier from_environment();
  ServiceNotifier() = default;

  /// The longest watchdog period kept: a day. A manager that asks for more
  /// (up to systemd's 2^64-1 us) is pinged every half day, more often than it
  /// needs, and no time sum can overflow.
  static constexpr std::int64_t kMaxWatchdogNs = 24LL * 60 * 60 * kNsPerSecond;

  [[nodiscard]] bool active() const { return static_cast<bool>(fd_); }
  /// The watchdog period the manager asked for (WATCHDOG_USEC), at most
  /// kMaxWatchdogNs; 0 for none.
  [[nodiscard]] std::int64_t watchdog_ns() const { return watchdog_ns_; }

  /// Sends one message ("READY=1", "STATUS=..."); false when it was not sent.
  bool send(std::string_view message) const;
  /// WATCHDOG=1 when half the watchdog period has passed since the last one
  /// (now_ns on the monotonic clock). Call from the loop the watchdog guards.
  void watchdog(std::int64_t now_ns);

 private:
  UniqueFd fd_;
  std::string address_;  ///< sockaddr_un's sun_path bytes (a leading NUL for an abstract name)
  std::int64_t watchdog_ns_ = 0;
  std::int64_t last_ping_ns_ = -1;
};

/// True when fd is the journal's stream (JOURNAL_STREAM's device:inode):
/// lines written there may carry `<N>` priority prefixes.
bool is_journal_stream(int fd);

}  // namespace andros

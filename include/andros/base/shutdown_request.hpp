#pragma once
/// The one shutdown mechanism every loop uses (ending the run: never the
/// latched stop, which is the operating state's): a request that code raises
/// or a shutdown signal makes, that a loop checks once per turn, and that wakes a loop
/// waiting on it (sleep_until, wait_readable). The signals stay blocked and
/// are taken synchronously (BlockedSignals, a signalfd to wake on): no
/// handler ever runs, on any thread.

#include <atomic>
#include <csignal>
#include <cstdint>
#include <initializer_list>
#include <optional>

#include "andros/base/blocked_signals.hpp"
#include "andros/base/unique_fd.hpp"

namespace andros {

/// The signals that end `run` and `monitor` (docs/running.md).
inline constexpr std::initializer_list<int> kShutdownSignals = {SIGINT, SIGTERM, SIGHUP};
/// The signals that stop `run` (docs/running.md, "Signals"): kShutdownSignals
/// (SIGHUP reloads), and every other signal whose default action would end
/// the process between two frames, so that each ends it through the shutdown's
/// neutral frames instead. SIGXFSZ is ignored (main): a write past a file-size
/// limit fails with EFBIG.
inline constexpr std::initializer_list<int> kRunShutdownSignals = {
    SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGVTALRM, SIGPROF, SIGXCPU, SIGIO, SIGPWR, SIGSTKFLT};
/// The signals that end a `record` (docs/controllers.md); SIGHUP keeps its default there.
inline constexpr std::initializer_list<int> kRecordShutdownSignals = {SIGINT, SIGTERM};

/// For wait_readable: no time limit.
inline constexpr std::int64_t kNoDeadline = INT64_MAX;

class ShutdownRequest {
 public:
  /// A request only code raises (a thread's owner stopping it).
  ShutdownRequest();
  /// Also made by any of `signals`, which it blocks in the calling thread and
  /// so in every thread started later: construct before any thread starts.
  explicit ShutdownRequest(std::initializer_list<int> signals);
  ~ShutdownRequest();
  ShutdownRequest(const ShutdownRequest&) = delete;
  ShutdownRequest& operator=(const ShutdownRequest&) = delete;

  /// Asks whoever checks this to stop, and wakes them. Any thread.
  void raise();
  /// True once raised or a signal of the set arrived; stays true. Never blocks.
  bool requested();
  /// From now on SIGHUP (when in the set) asks for a reload (`systemctl
  /// reload`, docs/running.md), not a stop.
  void reload_on_hangup() { hangup_reloads_ = true; }
  /// True once for each SIGHUP taken since reload_on_hangup(). Never blocks.
  bool reload_requested();
  /// True when requested() or reload_requested() has news that no pending
  /// signal brings: raised, or a SIGHUP taken (perhaps by another caller of
  /// requested()) and not yet read. Without it and without signals_pending(),
  /// neither has anything new to say. Never blocks, no system call.
  [[nodiscard]] bool has_unread() const { return raised_ || reload_pending_; }
  /// The signal that asked (0: none, or raised by code).
  [[nodiscard]] int signal_number() const { return signal_.load(); }

  /// Sleeps until the monotonic clock reads abs_ns; false when a stop request
  /// cut the sleep short (or came before it).
  bool sleep_until(std::int64_t abs_ns);
  /// Waits until fd has something to read (or an error or hang-up to report)
  /// or abs_ns (kNoDeadline: none); false at abs_ns or on a stop request.
  bool wait_readable(int fd, std::int64_t abs_ns);

 private:
  bool wait(int fd, std::int64_t abs_ns);

  std::optional<BlockedSignals> signals_;
  UniqueFd signal_fd_;  ///< readable while a signal of the set is pending
  UniqueFd wake_;       ///< eventfd, readable once raised
  std::atomic<bool> raised_{false};
  std::atomic<int> signal_{0};
  std::atomic<bool> hangup_reloads_{false};
  std::atomic<bool> reload_pending_{false};
};

}  // namespace andros

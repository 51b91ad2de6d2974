#pragma once
/// A set of signals blocked in the calling thread (and so in every thread it
/// starts later) and taken synchronously, never handled: the one mechanism
/// behind ShutdownRequest and JobControlSignals.

#include <signal.h>

#include <initializer_list>

namespace andros {

class BlockedSignals {
 public:
  /// Blocks the signals. Construct before any thread starts.
  explicit BlockedSignals(std::initializer_list<int> signals);
  /// Discards what is still pending (it was answered already), then unblocks.
  ~BlockedSignals();
  BlockedSignals(const BlockedSignals&) = delete;
  BlockedSignals& operator=(const BlockedSignals&) = delete;

  /// One pending signal of the set, or 0 when none. Never blocks.
  int take();
  /// Takes `sig` (one of the set) if it is pending; false when it is not. Never blocks.
  bool take(int sig);
  /// Drops every pending signal of the set, or of `only` among them.
  void discard(std::initializer_list<int> only = {});

 private:
  sigset_t set_{};
  sigset_t old_{};
};

/// True when a signal is pending for the calling thread or the process: one
/// sigpending() call. A loop that asks several sets every turn (the run
/// loop: stop, reload, job control) asks this first, and the sets only when
/// it is true.
bool signals_pending();

}  // namespace andros

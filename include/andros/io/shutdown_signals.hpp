#pragma once
/// SIGINT, SIGTERM and SIGHUP as a request the run loop checks once per tick.
/// The signals are blocked rather than handled: every thread started later
/// inherits the mask, so no handler runs on some library's thread, and the
/// loop picks the request up synchronously (within one period).

#include <signal.h>

namespace andros::io {

class ShutdownSignals {
 public:
  /// Blocks the signals in the calling thread. Construct before any thread starts.
  ShutdownSignals();
  ~ShutdownSignals();
  ShutdownSignals(const ShutdownSignals&) = delete;
  ShutdownSignals& operator=(const ShutdownSignals&) = delete;

  /// True once a shutdown signal has arrived. Never blocks.
  bool requested();
  /// The signal that asked (0 for none yet).
  [[nodiscard]] int signal_number() const { return received_; }

 private:
  sigset_t set_{};
  sigset_t old_{};
  int received_ = 0;
};

}  // namespace andros::io

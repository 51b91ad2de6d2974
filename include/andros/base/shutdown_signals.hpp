#pragma once
/// SIGINT, SIGTERM and SIGHUP as a request the run loop checks once per tick.
/// The signals are blocked rather than handled: every thread started later
/// inherits the mask, so no handler runs on some library's thread, and the
/// loop picks the request up synchronously (within one period).

#include "andros/base/blocked_signals.hpp"

namespace andros {

class ShutdownSignals {
 public:
  /// Blocks the signals in the calling thread. Construct before any thread starts.
  ShutdownSignals() : signals_{SIGINT, SIGTERM, SIGHUP} {}

  /// True once a shutdown signal has arrived. Never blocks.
  bool requested();
  /// The signal that asked (0 for none yet).
  [[nodiscard]] int signal_number() const { return received_; }

 private:
  BlockedSignals signals_;  ///< one arriving during shutdown stays pending and is dropped: it was answered
  int received_ = 0;
};

}  // namespace andros

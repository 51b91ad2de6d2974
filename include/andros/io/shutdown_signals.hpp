#pragma once
/// SIGINT, SIGTERM and SIGHUP as a request the run loop checks once per tick:
/// each a stop, until reload_on_hangup() makes SIGHUP a reload request.
/// The signals are blocked rather than handled: every thread started later
/// inherits the mask, so no handler runs on some library's thread, and the
/// loop picks the request up synchronously (within one period).

#include "andros/io/blocked_signals.hpp"

namespace andros::io {

class ShutdownSignals {
 public:
  /// Blocks the signals in the calling thread. Construct before any thread starts.
  ShutdownSignals() : signals_{SIGINT, SIGTERM, SIGHUP} {}

  /// True once a shutdown signal has arrived. Never blocks.
  bool requested();
  /// The signal that asked (0 for none yet).
  [[nodiscard]] int signal_number() const { return received_; }
  /// From now on SIGHUP asks for a reload (`systemctl reload`), not a stop.
  void reload_on_hangup() { hangup_reloads_ = true; }
  /// True once per SIGHUP that arrived since reload_on_hangup(). Never blocks.
  bool reload_requested();

 private:
  BlockedSignals signals_;  ///< one arriving during shutdown stays pending and is dropped: it was answered
  int received_ = 0;
  bool hangup_reloads_ = false;
  bool reload_pending_ = false;
};

}  // namespace andros::io

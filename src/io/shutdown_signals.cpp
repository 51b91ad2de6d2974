#include "andros/io/shutdown_signals.hpp"

namespace andros::io {

bool ShutdownSignals::requested() {
  while (received_ == 0) {
    const int sig = signals_.take();
    if (sig == 0) break;
    if (sig == SIGHUP && hangup_reloads_) reload_pending_ = true;
    else received_ = sig;
  }
  return received_ != 0;
}

bool ShutdownSignals::reload_requested() {
  requested();
  const bool pending = reload_pending_;
  reload_pending_ = false;
  return pending;
}

}  // namespace andros::io

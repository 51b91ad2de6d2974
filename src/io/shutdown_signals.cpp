#include "andros/io/shutdown_signals.hpp"

#include <pthread.h>

#include <ctime>

namespace andros::io {

ShutdownSignals::ShutdownSignals() {
  sigemptyset(&set_);
  sigaddset(&set_, SIGINT);
  sigaddset(&set_, SIGTERM);
  sigaddset(&set_, SIGHUP);
  pthread_sigmask(SIG_BLOCK, &set_, &old_);
}

ShutdownSignals::~ShutdownSignals() {
  // A signal that arrived during shutdown stays pending; it was answered already.
  const timespec zero{0, 0};
  while (sigtimedwait(&set_, nullptr, &zero) > 0) {
  }
  pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

bool ShutdownSignals::requested() {
  if (received_ != 0) return true;
  const timespec zero{0, 0};
  const int sig = sigtimedwait(&set_, nullptr, &zero);
  if (sig > 0) received_ = sig;
  return received_ != 0;
}

}  // namespace andros::io

#include "andros/base/blocked_signals.hpp"

#include <pthread.h>

#include <ctime>

namespace andros {
namespace {

int take_from(const sigset_t& set) {
  const timespec zero{0, 0};
  const int sig = sigtimedwait(&set, nullptr, &zero);
  return sig > 0 ? sig : 0;
}

}  // namespace

BlockedSignals::BlockedSignals(std::initializer_list<int> signals) {
  sigemptyset(&set_);
  for (const int sig : signals) sigaddset(&set_, sig);
  pthread_sigmask(SIG_BLOCK, &set_, &old_);
}

BlockedSignals::~BlockedSignals() {
  discard();
  pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

int BlockedSignals::take() { return take_from(set_); }

bool BlockedSignals::take(int sig) {
  sigset_t one;
  sigemptyset(&one);
  sigaddset(&one, sig);
  return take_from(one) == sig;
}

void BlockedSignals::discard(std::initializer_list<int> only) {
  sigset_t set = set_;
  if (only.size() > 0) {
    sigemptyset(&set);
    for (const int sig : only) sigaddset(&set, sig);
  }
  while (take_from(set) != 0) {
  }
}

bool signals_pending() {
  sigset_t pending;
  sigemptyset(&pending);
  return sigpending(&pending) == 0 && !sigisemptyset(&pending);
}

}  // namespace andros

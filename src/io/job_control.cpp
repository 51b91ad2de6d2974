#include "andros/io/job_control.hpp"

#include <pthread.h>
#include <unistd.h>

#include <ctime>
#include <initializer_list>

namespace andros::io {
namespace {

void discard_pending(const sigset_t& set) {
  const timespec zero{0, 0};
  while (sigtimedwait(&set, nullptr, &zero) > 0) {
  }
}

}  // namespace

JobControlSignals::JobControlSignals() {
  sigemptyset(&set_);
  for (const int sig : {SIGTSTP, SIGTTIN, SIGTTOU, SIGCONT}) sigaddset(&set_, sig);
  pthread_sigmask(SIG_BLOCK, &set_, &old_);
}

JobControlSignals::~JobControlSignals() {
  // A Ctrl-Z during the shutdown was answered by it: it must not stop the process on the way out.
  discard_pending(set_);
  pthread_sigmask(SIG_SETMASK, &old_, nullptr);
}

JobControlSignals::Event JobControlSignals::poll() {
  const timespec zero{0, 0};
  Event event = Event::kNone;
  int sig = 0;
  while ((sig = sigtimedwait(&set_, nullptr, &zero)) > 0) {
    if (sig == SIGCONT) {
      if (event == Event::kNone) event = Event::kContinued;
    } else {
      stop_signal_ = sig;
      event = Event::kStopAsked;
    }
  }
  return event;
}

void JobControlSignals::stop_process() {
  // A second Ctrl-Z during the neutral frames is answered by this stop too.
  discard_pending(set_);
  kill(getpid(), SIGSTOP);
  // Continued: the SIGCONT that did it is answered by returning.
  sigset_t cont;
  sigemptyset(&cont);
  sigaddset(&cont, SIGCONT);
  discard_pending(cont);
}

}  // namespace andros::io

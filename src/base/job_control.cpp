#include "andros/base/job_control.hpp"

#include <unistd.h>

namespace andros {

JobControlSignals::Event JobControlSignals::poll() {
  Event event = Event::kNone;
  while (const int sig = signals_.take()) {
    if (sig == SIGCONT) {
      if (event == Event::kNone) event = Event::kContinued;
    } else {
      stop_signal_ = sig;
      event = Event::kStopAsked;
    }
  }
  return event;
}

JobControlSignals::Stop JobControlSignals::stop_process() {
  // A second Ctrl-Z during the neutral frames is answered by this stop too.
  signals_.discard({SIGTSTP, SIGTTIN, SIGTTOU});
  // The kernel keeps only the later of a stop signal and SIGCONT pending
  // (sending either clears the other), so a SIGCONT pending now came after
  // every Ctrl-Z: `fg` or `kill -CONT` has said "go on" already. A SIGSTOP
  // would clear it, and the process would stay stopped for good. (One sent
  // in the few instructions between this check and the kill is still lost:
  // there is no "stop unless continued" to ask the kernel for.)
  if (signals_.take(SIGCONT)) return Stop::kContinuedBeforeStop;
  kill(getpid(), SIGSTOP);
  // Continued: the SIGCONT that did it is answered by returning.
  signals_.discard({SIGCONT});
  return Stop::kStopped;
}

}  // namespace andros

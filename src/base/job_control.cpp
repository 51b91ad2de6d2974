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

void JobControlSignals::stop_process() {
  // A second Ctrl-Z during the neutral frames is answered by this stop too.
  signals_.discard();
  kill(getpid(), SIGSTOP);
  // Continued: the SIGCONT that did it is answered by returning.
  signals_.discard({SIGCONT});
}

}  // namespace andros

#pragma once
/// Job control (Ctrl-Z, SIGTTIN, SIGTTOU, SIGCONT) as requests the run loop
/// answers on its next tick, like a ShutdownRequest. The stop signals are
/// blocked, so that none can freeze the process between two frames with a
/// driving frame last: the loop sends its neutral frames first, then the
/// process stops itself (SIGSTOP) until continued. Blocked, SIGTTOU is never
/// raised by the terminal either: a bridge put in the background goes on
/// writing instead of stopping there.

#include <cstdint>

#include "andros/base/blocked_signals.hpp"

namespace andros {

class JobControlSignals {
 public:
  enum class Event : std::uint8_t {
    kNone,
    kStopAsked,  ///< SIGTSTP (Ctrl-Z), SIGTTIN or SIGTTOU
    kContinued,  ///< SIGCONT: the process was stopped (perhaps by a SIGSTOP it could not see) and goes on
  };

  /// Blocks the signals in the calling thread. Construct before any thread starts.
  JobControlSignals() : signals_{SIGTSTP, SIGTTIN, SIGTTOU, SIGCONT} {}

  /// What arrived since the last call. Never blocks.
  Event poll();
  /// The last stop signal seen (SIGTSTP...), 0 for none.
  [[nodiscard]] int stop_signal() const { return stop_signal_; }
  /// How stop_process() ended.
  enum class Stop : std::uint8_t {
    kStopped,              ///< stopped, then continued (fg, bg, SIGCONT)
    kContinuedBeforeStop,  ///< a SIGCONT came after the stop was asked: it was not stopped
  };

  /// Stops the whole process (SIGSTOP) and returns once it is continued.
  /// A SIGCONT that came after the last stop signal (during the neutral
  /// frames) already said "go on": then it returns at once, without
  /// stopping. Stop signals still pending (a second Ctrl-Z) are answered by
  /// this one stop.
  [[nodiscard]] Stop stop_process();

 private:
  /// A Ctrl-Z during the shutdown was answered by it: dropped on the way out, it cannot stop the process.
  BlockedSignals signals_;
  int stop_signal_ = 0;
};

}  // namespace andros

#pragma once
// The latched stop as the fault simulation's oracle (safety_oracle.hpp)
// reads it off the script. A stop button pressed since the last tick latches
// at the tick (but one made just before a new controller session: the loop
// cannot see it). The latch outlives its own tick and is never cleared by
// the deadman alone: at the earliest on a later tick, with no stop button
// pressed since the last one, every stop button released at least once since
// the stop (a reset by a deliberate hold of it, and the older rule's release
// of it, both need that), and what the caller checks besides (the pad there,
// the loop able to be stopped, every deadman up). Permissive about how a
// reset is made: the engine may keep the stop longer, never shorter.

#include <cstdint>

namespace andros::test {

struct StopLatch {
  bool pending = false;   ///< a stop button pressed since the last tick
  bool latched = false;   ///< stopped
  bool released = true;   ///< every stop button up at some moment since the latch
  std::int64_t tick = 0;  ///< the latch's tick

  /// At tick t, once its events are in: held_now, a stop button is down;
  /// may_clear, what else a reset needs holds. True when it latched now.
  bool at_tick(std::int64_t t, bool held_now, bool may_clear) {
    bool latched_now = false;
    if (latched) {
      if (t > tick && !pending && released && may_clear) latched = false;
    } else if (pending) {
      latched = latched_now = true;
      tick = t;
      released = !held_now;
    }
    pending = false;
    return latched_now;
  }
};

}  // namespace andros::test

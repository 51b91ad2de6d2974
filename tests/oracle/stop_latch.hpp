#pragma once
// The latched stop as the fault simulation's oracle (safety_oracle.hpp)
// reads it off the script (docs/safety-states.md), on the stop buttons of the
// mapping in force. A stop button pressed since the last tick, or held (not
// held on from a reset), latches at the tick (but one made just before a new
// controller session: the loop cannot see it); the stop is the supervisor's
// when the supervisor's button latched it or is pressed while stopped. The
// latch outlives its own tick and is never cleared by the deadman alone, nor
// by releasing the stop buttons: only a reset hold ends it, read tick by tick
// as the loop reads it (StopHold::tick), exactly (a reset the loop did not
// make would make a later press of the stop button a new stop here, a press
// of the reset there): that pad's stop button released after the stop, then
// pressed and held for `stop_reset_hold` with the deadman released. The
// supervisor's resets any stop, the operator's only the operator's (and the
// frame gate's, which never trips in the simulation: that is checked apart).

#include <cstdint>
#include <optional>

#include "andros/input/events.hpp"

namespace andros::test {

/// One pad's stop button, as a reset hold reads it (the mapping in force's).
struct StopHold {
  bool down = false;
  bool pressed = false;               ///< since the last tick
  bool let_go = false;                ///< since the last tick
  bool from_reset = false;            ///< held on since a reset hold completed: no stop until let go
  std::optional<std::int64_t> since;  ///< a hold under way since this tick

  /// The button moved (initial: stamped with the connect's time, the state the pad had, not a press).
  void moved(bool now, bool was, bool initial) {
    down = now;
    if (!now) from_reset = false;
    if (initial) return;
    if (now && !was) pressed = true;
    if (!now && was) let_go = true;
  }
  /// A stop: pressed since the last tick, or held (not held on from a reset).
  [[nodiscard]] bool stops() const { return pressed || (down && !from_reset); }

  // One tick of a reset hold: the stop button pressed since the last tick and
  // held, the deadman neither held nor pressed, begins it; let go or the
  // deadman touched ends it; true once it has lasted hold_ms.
  bool tick(bool reading, bool touched, std::int64_t t, std::int64_t hold_ms) {
    if (!reading || let_go || !down || touched) since.reset();
    if (reading && pressed && down && !touched) since = t;
    if (!since || t - *since < hold_ms) return false;
    since.reset();
    from_reset = true;  // held on after it, it stops nothing until let go
    return true;
  }
};

class StopLatch {
 public:
  /// What a tick did to the latch.
  enum class Outcome : std::uint8_t { kNone, kLatched, kOperatorReset, kSupervisorReset, kRefused };

  /// What the tick reads besides the stop buttons.
  struct Tick {
    bool reads_stops = true;  ///< every tick but a shutdown's reads the stop buttons
    bool in_stopped = false;  ///< the loop may spend the tick in "stopped" (not suspended, reloading, resumed)
    bool connected = false;   ///< the operator's pad
    bool sup_connected = false;
    bool touched = false;  ///< the deadman of the mapping in force held, or pressed since the last tick
    std::int64_t hold_ms = 0;
  };

  /// At tick t, once its events are in.
  Outcome at_tick(std::int64_t t, const Tick& in) {
    const bool sup_stop = in.sup_connected && sup.stops();
    const bool op_stop = in.connected && op.stops();
    Outcome out = Outcome::kNone;
    if (latched_) {
      // The loop reads the holds only at ticks it spends in "stopped"; a
      // suspend's or a reload's ticks, or a lost pad, end a hold (and read
      // the stop buttons as a stop: the supervisor's makes it the supervisor's).
      const bool in_stopped = t > tick_ && in.in_stopped;
      if (in_stopped ? in.sup_connected && sup.pressed : in.reads_stops && sup_stop) by_ = input::Pad::kSupervisor;
      const bool sup_done = sup.tick(in_stopped && in.sup_connected, in.touched, t, in.hold_ms);
      const bool op_done = op.tick(in_stopped && in.connected, in.touched, t, in.hold_ms);
      if (sup_done || (op_done && by_ == input::Pad::kOperator)) {
        latched_ = false;
        op.since.reset();
        sup.since.reset();
        reset_tick_ = t;
        out = sup_done ? Outcome::kSupervisorReset : Outcome::kOperatorReset;
      } else if (op_done) {
        out = Outcome::kRefused;
      }
    } else if (in.reads_stops && (op_stop || sup_stop)) {
      latched_ = true;
      by_ = sup_stop ? input::Pad::kSupervisor : input::Pad::kOperator;
      tick_ = t;
      out = Outcome::kLatched;
    }
    op.pressed = op.let_go = sup.pressed = sup.let_go = false;
    return out;
  }

  [[nodiscard]] bool latched() const { return latched_; }
  /// A deadman press at t comes after the last reset (the presses up to it are history).
  [[nodiscard]] bool after_reset(std::int64_t t) const { return t > reset_tick_; }

  StopHold op;   ///< the operator's stop button
  StopHold sup;  ///< the supervisor's

 private:
  bool latched_ = false;
  input::Pad by_ = input::Pad::kOperator;  ///< whose the latched stop is
  std::int64_t tick_ = 0;                  ///< the latch's tick
  std::int64_t reset_tick_ = -1;           ///< the last reset's tick
};

}  // namespace andros::test

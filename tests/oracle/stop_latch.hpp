#pragma once
// The latched stop as the fault simulation's oracle (safety_oracle.hpp)
// reads it off the script, written from the stop standards' words
// (ISO 13850: a stop device stops whenever it is actuated, and its reset is a
// separate, deliberate act that cannot complete while the device is still
// actuated; docs/safety-states.md, "Stops"), not from the loop's code:
// - a stop press always stops: a stop button (the operator's `estop`, the
//   supervisor's `stop`) pressed since the last tick, or held, latches at
//   the tick, whatever the state (but one made just before a new controller
//   session: the loop cannot see it);
// - no reset while any stop input is actuated: a stop button pressed or held
//   on any pad, or the deadman touched, ends a reset gesture under way, and
//   the gesture must be let go and made again;
// - a reset is the pad's reset gesture (`stop_reset`, the supervisor's
//   `reset`: every button of it held) made afresh while stopped and held
//   `stop_reset_hold`, read at the ticks the loop spends in "stopped";
// - no reset by a pad that is not the stopper's or the supervisor's: the
//   supervisor's resets the operator's stop from any pad in its role, a
//   role's own stop only from the pad that stopped (a pad is its connect's
//   name here: a script gives no more); the operator's never resets the supervisor's.
// The stop is the supervisor's once its button latched it or is pressed
// while stopped. The latch is never cleared by the deadman, nor by releasing
// the stop buttons. The frame gate never trips in the simulation: that is checked apart.

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "andros/input/events.hpp"

namespace andros::test {

/// One pad's stop button.
struct StopInput {
  bool down = false;
  bool pressed = false;  ///< since the last tick

  /// The button moved (initial: stamped with the connect's time, the state the pad had, not a press).
  void moved(bool now, bool was, bool initial) {
    down = now;
    if (now && !was && !initial) pressed = true;
  }
  /// Actuated at this tick: pressed since the last, or held.
  [[nodiscard]] bool actuated() const { return pressed || down; }
};

/// One pad's reset gesture: its buttons, each as the pad holds it.
struct ResetGesture {
  std::vector<input::InputKey> keys;
  std::vector<bool> down;
  bool let_go = false;                ///< a button of it let go since the last tick
  bool open = false;                  ///< seen not made since the last ending of a hold
  std::optional<std::int64_t> since;  ///< made at this tick, held since
  bool new_session = false;           ///< its pad connected since the last tick: what it holds then is not made afresh

  void moved(input::InputKey key, bool now) {
    for (std::size_t i = 0; i < keys.size(); ++i) {
      if (keys[i] != key) continue;
      if (down[i] && !now) let_go = true;
      down[i] = now;
    }
  }
  [[nodiscard]] bool made() const {
    if (keys.empty()) return false;
    for (const bool d : down) {
      if (!d) return false;
    }
    return true;
  }
  /// A new session, or a hold that must be made again: made now, it must be let go first.
  void close() {
    open = !made();
    since.reset();
  }
  // One tick; true once the gesture, made afresh, has lasted hold_ms with nothing actuated.
  bool tick(bool reading, bool blocked, std::int64_t t, std::int64_t hold_ms) {
    const bool was_let_go = std::exchange(let_go, false);
    if (!reading || std::exchange(new_session, false)) {
      close();
      return false;
    }
    if (blocked) {
      close();  // let go meanwhile: the next making is afresh
      return false;
    }
    if (!made() || was_let_go) {  // let go (and made again, perhaps, since the last tick)
      since.reset();
      open = true;
    }
    if (!made() || !open) return false;
    if (!since) since = t;
    if (t - *since < hold_ms) return false;
    close();
    return true;
  }
};

// [rule: stop-latch]
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
    const bool sup_stop = in.sup_connected && sup.actuated();
    const bool op_stop = in.connected && op.actuated();
    actuated_ = op_stop || sup_stop;
    Outcome out = Outcome::kNone;
    if (latched_) {
      // The loop reads the gestures only at ticks it spends in "stopped"; a
      // suspend's or a reload's ticks, or a lost pad, end a hold (and read
      // the stop buttons as a stop: the supervisor's makes it the supervisor's).
      const bool in_stopped = t > tick_ && in.in_stopped;
      if (in_stopped ? in.sup_connected && sup.pressed : in.reads_stops && sup_stop) take(input::Pad::kSupervisor);
      if (in_stopped && (op.pressed || sup.pressed)) ++presses_while_stopped_;
      const bool blocked = actuated_ || in.touched;
      const bool sup_done = sup_reset.tick(in_stopped && in.sup_connected, blocked, t, in.hold_ms);
      const bool op_done = op_reset.tick(in_stopped && in.connected, blocked, t, in.hold_ms);
      const bool sup_may = by_ != input::Pad::kSupervisor || sup_name == stopper_name_;
      const bool op_may = by_ == input::Pad::kOperator && op_name == stopper_name_;
      if ((sup_done && sup_may) || (op_done && op_may)) {
        latched_ = false;
        op_reset.close();
        sup_reset.close();
        reset_tick_ = t;
        out = sup_done && sup_may ? Outcome::kSupervisorReset : Outcome::kOperatorReset;
      } else if (op_done || sup_done) {
        out = Outcome::kRefused;
      }
    } else if (in.reads_stops && (op_stop || sup_stop)) {
      latched_ = true;
      by_ = sup_stop ? input::Pad::kSupervisor : input::Pad::kOperator;
      stopper_name_ = sup_stop ? sup_name : op_name;
      tick_ = t;
      op_reset.close();
      sup_reset.close();
      op_reset.let_go = sup_reset.let_go = false;
      out = Outcome::kLatched;
    } else {
      // Not stopped: a gesture made now is not made afresh while stopped.
      op_reset.close();
      sup_reset.close();
      op_reset.let_go = sup_reset.let_go = false;
    }
    op.pressed = sup.pressed = false;
    op_reset.new_session = sup_reset.new_session = false;  // closed above, whichever way
    return out;
  }

  [[nodiscard]] bool latched() const { return latched_; }
  /// A stop button pressed since the last tick or held, on a connected pad, at the last tick.
  [[nodiscard]] bool actuated() const { return actuated_; }
  /// A deadman press at t comes after the last reset (the presses up to it are history).
  [[nodiscard]] bool after_reset(std::int64_t t) const { return t > reset_tick_; }
  [[nodiscard]] std::int64_t presses_while_stopped() const { return presses_while_stopped_; }

  StopInput op;   ///< the operator's stop button
  StopInput sup;  ///< the supervisor's
  ResetGesture op_reset;
  ResetGesture sup_reset;
  std::string op_name;  ///< the pad in each role now: its connect's name
  std::string sup_name;

 private:
  void take(input::Pad by) {
    if (by_ == by) return;
    by_ = by;
    stopper_name_ = by == input::Pad::kSupervisor ? sup_name : op_name;
  }

  bool latched_ = false;
  bool actuated_ = false;
  input::Pad by_ = input::Pad::kOperator;  ///< whose the latched stop is
  std::string stopper_name_;               ///< the pad that stopped
  std::int64_t tick_ = 0;                  ///< the latch's tick
  std::int64_t reset_tick_ = -1;           ///< the last reset's tick
  std::int64_t presses_while_stopped_ = 0;
};

}  // namespace andros::test

#include "andros/run/deadman.hpp"

#include "andros/mapping/axis.hpp"

namespace andros::run {
namespace {

using mapping::DeadmanState;
using mapping::kDefaultThreshold;

bool past(std::int16_t value, double point) { return mapping::normalise_axis(value) >= point; }

}  // namespace

Deadman::Deadman(const mapping::Mapping& mapping)
    : key_(mapping.deadman ? std::optional(mapping.deadman->key) : std::nullopt),
      panic_(key_ && !key_->is_button() ? mapping.deadman_panic : std::nullopt) {}

void Deadman::start(const input::InputState& input, bool at_start_up) {
  base_ = 0;
  releases_seen_ = 0;
  presses_seen_ = 0;
  released_seen_ = false;
  held_at_read_ = false;
  panic_latched_ = false;
  timed_out_ = false;
  if (at_start_up && key_) {
    // Presses and releases made before it are history; a trigger released now may be squeezed afresh.
    base_ = input.button(*key_).presses;
    presses_seen_ = base_;
    connection_seen_ = input.connection();
    releases_seen_ = input.button(*key_).releases;
    released_seen_ = !held(input);
    // (held_at_read_ stays false: what the trigger did in this tick before the restart is history.)
  }
}

bool Deadman::held(const input::InputState& input) const {
  if (!key_ || !input.connected()) return false;
  return key_->is_button() ? input.button(*key_).down : past(input.axis(*key_), kDefaultThreshold);
}

bool Deadman::touched(const input::InputState& input) {
  if (!key_ || !input.connected()) return false;
  if (!key_->is_button()) return past(input.axis_span(*key_).high, kDefaultThreshold);
  const auto now = input.button(*key_);
  // Another controller session (a pad back while stopped) counts its presses from 0.
  if (input.connection() != connection_seen_) presses_seen_ = 0;
  connection_seen_ = input.connection();
  const bool pressed_between = now.presses > presses_seen_;  // pressed (and let go) since
  presses_seen_ = now.presses;
  return now.down || pressed_between;
}

bool Deadman::let_go_between(const input::InputState& input) const {
  if (key_->is_button()) return input.button(*key_).releases > releases_seen_;
  // A trigger released at the last read and squeezed since is a press, not a let go.
  return held_at_read_ && !past(input.axis_span(*key_).low, kDefaultThreshold);
}

bool Deadman::panic(const input::InputState& input) {
  if (!panic_) return false;
  const auto span = input.axis_span(*key_);
  const bool squeezed = past(span.high, *panic_);
  if (squeezed) {
    panic_latched_ = true;  // off at once; released and squeezed again to enable
    released_seen_ = false;
  }
  // Fully released since: within the same tick as a squeeze only if it is so now
  // (which came first is not known: the latch is kept).
  const std::int16_t lowest = squeezed ? input.axis(*key_) : span.low;
  if (panic_latched_ && !past(lowest, mapping::kDeadmanFullyReleased)) {
    panic_latched_ = false;  // fully released: the next squeeze to the middle is fresh
    released_seen_ = true;
  }
  return panic_latched_;
}

mapping::DeadmanState Deadman::read(const input::InputState& input) {
  if (!input.connected() || !key_) return DeadmanState::kNoPad;
  const bool let_go = let_go_between(input);
  held_at_read_ = held(input);
  if (key_->is_button()) {
    releases_seen_ = input.button(*key_).releases;
    presses_seen_ = input.button(*key_).presses;
    connection_seen_ = input.connection();
  }
  if (panic(input)) return DeadmanState::kPastPanic;
  if (!held(input) || let_go) {
    released_seen_ = true;
    timed_out_ = false;
    return DeadmanState::kReleased;
  }
  if (timed_out_) return DeadmanState::kTimedOut;
  // A button counts presses itself; a trigger must have been seen released.
  const bool fresh = key_->is_button() ? input.button(*key_).presses > base_ : released_seen_;
  return fresh ? DeadmanState::kFreshHold : DeadmanState::kHeldNotFresh;
}

void Deadman::time_out(const input::InputState& input) {
  timed_out_ = true;
  // A press or squeeze that began before it is history: the next one enables.
  if (key_) base_ = input.button(*key_).presses;
  released_seen_ = false;
}

}  // namespace andros::run

#include "andros/run/drive_guard.hpp"

#include <cstdlib>

namespace andros::run {
namespace {

/// For the enable timeout an axis has changed once it has moved this far
/// (of -32768..32767) from where it was at the last change: a pad's noise
/// does not keep the bridge enabled, a hand does.
constexpr int kActivityBand = 1024;

}  // namespace

DriveGuard::DriveGuard(const mapping::Mapping& mapping)
    : inputs_(mapping::read_inputs(mapping)),
      enable_timeout_(mapping.enable_timeout_ms),
      deadman_(mapping),
      stops_(mapping) {}

void DriveGuard::start_session(const input::InputState& input, bool at_start_up) {
  connection_ = input.connection();
  supervisor_connection_ = input.supervisor().connection();
  deadman_.start(input, at_start_up);
  was_enabled_ = false;
  // A stop pressed in a new session counts from its connect; at start-up the presses so far are history.
  stops_.start(input, at_start_up);
}

void DriveGuard::follow_sessions(const input::InputState& input) {
  if (!started_) {
    started_ = true;
    start_session(input, true);
  } else if (input.connection() != connection_) {
    start_session(input, false);
  } else if (input.supervisor().connection() != supervisor_connection_) {
    // The supervisor's controller new or back: afresh, as after any stop (the
    // deadman held through it is history); a stop tapped meanwhile is still a stop.
    const auto stops = stops_;
    start_session(input, true);
    stops_ = stops;
  }
}

void DriveGuard::rebase(const input::InputState& now) {
  started_ = true;
  start_session(now, true);
}

mapping::InputFacts DriveGuard::facts(const input::InputState& input, std::int64_t now_ms, bool enabled) {
  follow_sessions(input);
  enable_ = deadman_.read(input);
  stop_pressed_ = stops_.take(input);
  note_activity(input, now_ms);
  if (enabled && enable_ == mapping::DeadmanState::kFreshHold && timed_out(now_ms)) {
    deadman_.time_out(input);
    enable_ = mapping::DeadmanState::kTimedOut;
  }
  return mapping::InputFacts{enable_, stop_pressed_};
}

void DriveGuard::decided(bool motion_allowed, std::int64_t now_ms) {
  if (motion_allowed && !was_enabled_) last_activity_ms_ = now_ms;  // enabling is the first change
  was_enabled_ = motion_allowed;
}

mapping::StopPresses DriveGuard::take_stop(const input::InputState& input) {
  // A guard read before its first driving tick (a reload's, at the rebase): the presses so far are history.
  if (!started_) {
    rebase(input);
    stops_.forget(input);
  }
  return stops_.take(input);
}

StoppedTick DriveGuard::stopped(const input::InputState& input, std::int64_t now_ms) {
  if (!started_) {
    rebase(input);
    stops_.forget(input);
  }
  return stops_.stopped(input, deadman_.touched(input), now_ms);
}

void DriveGuard::note_activity(const input::InputState& input, std::int64_t now_ms) {
  bool changed = false;
  for (const auto key : inputs_.buttons) {
    const auto b = input.button(key);
    auto& was = activity_buttons_[key];
    if (b.down != was.down || b.presses != was.presses) changed = true;
    was = b;
  }
  for (const auto key : inputs_.axes) {
    const int v = input.axis(key);
    auto [it, fresh] = activity_axes_.emplace(key, static_cast<std::int16_t>(v));
    if (!fresh && std::abs(v - it->second) > kActivityBand) {
      changed = true;
      it->second = static_cast<std::int16_t>(v);
    }
  }
  if (changed) last_activity_ms_ = now_ms;
}

bool DriveGuard::timed_out(std::int64_t now_ms) const {
  return enable_timeout_ && now_ms - last_activity_ms_ >= *enable_timeout_;
}

void DriveGuard::report(const input::InputState& input, mapping::EngineStatus& status) const {
  status.deadman = enable_;
  status.stop_pressed = stop_pressed_;
  stops_.held(input, status);
}

}  // namespace andros::run

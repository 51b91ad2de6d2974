#pragma once
/// The engine's state after a step, as a plain value: what the run loop
/// reports and the operator's view and log show.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/input_state.hpp"

namespace andros::mapping {

/// What the deadman is doing, a fact the loop's guard reports
/// (run/drive_guard.hpp): the operating-state machine decides on it
/// (OpState::kEnabled is its decision, never this), and the operator's
/// status view and logs say it (describe()).
enum class DeadmanState : std::uint8_t {
  kFreshHold,     ///< held, and pressed afresh (after connect, a rebase, the last release)
  kNoPad,         ///< no controller connected (or the mapping names no deadman)
  kReleased,      ///< not held (or let go and pressed again within the tick)
  kHeldNotFresh,  ///< held since connect or start-up: release and press again
  kPastPanic,     ///< the trigger deadman squeezed past `deadman_panic`: off until fully released
  kTimedOut,      ///< `enable_timeout` passed with no input change: release and press again
};

std::string_view describe(DeadmanState state);

/// The speed level in force (the mapping's `scale:`): drive and pivot move
/// `value` times their distance from rest.
struct SpeedLevel {
  std::size_t index = 0;  ///< 0 = the slowest
  std::size_t count = 1;  ///< the mapping's levels (1 without `scale:`)
  double value = 1.0;     ///< the fraction of full speed

  bool operator==(const SpeedLevel&) const = default;
};

/// The supervisor's weapons consent (the mapping's `supervisor: weapons_consent:`).
enum class ConsentState : std::uint8_t {
  kNotAsked,  ///< the mapping asks for none: weapons need no consent
  kReleased,  ///< not held (or no supervisor's controller connected): no weapon fires
  kHeldBack,  ///< held since before it became meaningful: counts once released and pressed again
  kGiven,     ///< held and counting: an armed fire input fires
};

/// The stop buttons pressed (or held): whose controller each was on.
struct StopPresses {
  bool by_operator = false;    ///< the operator's `estop`
  bool by_supervisor = false;  ///< the supervisor's `stop`

  [[nodiscard]] bool any() const { return by_operator || by_supervisor; }
  explicit operator bool() const { return any(); }
  bool operator==(const StopPresses&) const = default;
};

/// A reset gesture held, not yet complete: whose, and how far.
struct ResetHold {
  input::Pad pad = input::Pad::kOperator;
  std::int64_t held_ms = 0;  ///< held so far
  std::int64_t hold_ms = 0;  ///< needed (`stop_reset_hold`)

  bool operator==(const ResetHold&) const = default;
};

/// One tick's facts, before its step: what the deadman and the stop buttons
/// did. They decide nothing: the run loop's operating-state machine does.
struct InputFacts {
  /// kFreshHold: held, and pressed afresh (a fresh press where not enabled);
  /// otherwise why it is not: released (or let go and pressed again within
  /// the tick), held since connect or a rebase, the panic, the enable timeout.
  DeadmanState deadman = DeadmanState::kNoPad;
  StopPresses stops;  ///< a stop button pressed since the last tick, or held

  bool operator==(const InputFacts&) const = default;
};

struct EngineStatus {
  DeadmanState deadman = DeadmanState::kNoPad;  ///< the loop's guard's fact at the last driving tick
  std::string layer;                            ///< the active layer's name ("" for the base layer)
  std::vector<input::InputKey> held_back;       ///< inputs that act again once seen at rest (RestRule)
  /// Enabled, weapons enabled for the run, and the active layer has weapon
  /// bindings: an armed fire input fires (what the banner and the pad announce).
  bool weapons_mode = false;
  /// A stop button was pressed or is held this tick (the operator's `estop`,
  /// the supervisor's `stop`): the run loop latches the stop.
  StopPresses stop_pressed;
  /// One is held now: the latched stop cannot clear yet (the status board
  /// says so in place of how to reset: view/status_board.cpp, stopped_text).
  bool stop_held = false;
  /// The supervisor's `stop` is held (for the view: whose stop it is).
  bool supervisor_stop = false;
  /// Stopped: a reset gesture under way (the view shows its progress).
  std::optional<ResetHold> reset_hold;
  /// The reset gestures, as the operator reads them ("back+start"; "" when the mapping has none).
  std::string operator_reset;
  std::string supervisor_reset;
  std::int64_t reset_hold_ms = 0;  ///< how long one is held (`stop_reset_hold`)
  ConsentState consent = ConsentState::kNotAsked;
  SpeedLevel speed;
  /// In a weapons mode with an arming input held: a fire button pressed now fires.
  bool armed = false;
  /// In a weapons mode, a fire input pressed with its arming input held but
  /// without the supervisor's consent: it did not fire (the trainer's score counts it).
  bool fire_refused = false;

  bool operator==(const EngineStatus&) const = default;
};

}  // namespace andros::mapping

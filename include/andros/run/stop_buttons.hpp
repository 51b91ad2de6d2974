#pragma once
/// The stop buttons and the reset gestures, as facts (docs/mapping.md, "Stop
/// buttons"). A stop button (the operator's `estop`, the supervisor's `stop`)
/// only ever stops: pressed or held, at any time, it is a stop, and while one
/// is held on any pad no reset completes. The reset is a gesture of its own
/// (`stop_reset:` on the operator's pad, `supervisor: reset:` on the
/// supervisor's): one button or a chord, made afresh while stopped and held
/// `stop_reset_hold` with the deadman and every stop button released
/// throughout. A stop pressed meanwhile, the deadman touched, or a button of
/// the chord let go ends the hold, and the chord must be let go and made
/// again. Who may reset whose stop is the operating state's to decide, not this.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"

namespace andros::run {

/// While stopped, one tick of the stop buttons and the reset gestures.
struct StoppedTick {
  mapping::StopPresses pressed;            ///< stop buttons pressed since the last read (not merely held)
  std::optional<input::Pad> reset;         ///< the pad whose reset gesture completed at this tick
  std::optional<mapping::ResetHold> hold;  ///< a reset gesture under way (the longest held)
};

/// A reset gesture as the operator reads it: "back+start" ("" for none).
std::string gesture_text(const std::vector<input::InputKey>& keys);

class StopButtons {
 public:
  explicit StopButtons(const mapping::Mapping& mapping);

  /// A new session of the operator's controller (at_start_up: or the start,
  /// or a restart: the presses so far are history; a button held still stops).
  void start(const input::InputState& input, bool at_start_up);
  /// Every press so far is history, on both pads (an engine that takes over
  /// from another, a reload's, read before its first step).
  void forget(const input::InputState& input);
  /// A stop button pressed since the last read, or held now: a stop. Takes
  /// the presses and ends any reset gesture (the loop is not stopped, or starts afresh).
  mapping::StopPresses take(const input::InputState& input);
  /// Stopped, once per tick at now_ms: the stop presses since the last read,
  /// and the reset gestures. deadman_touched: held now, or pressed since the last tick.
  StoppedTick stopped(const input::InputState& input, bool deadman_touched, std::int64_t now_ms);
  /// Which are held now, into status (stop_held, supervisor_stop).
  void held(const input::InputState& input, mapping::EngineStatus& status) const;

  bool operator==(const StopButtons&) const = default;

 private:
  /// One controller's stop button, counted per controller session.
  struct Button {
    std::optional<input::InputKey> key;
    std::uint32_t connection = 0;
    std::uint32_t presses = 0;  ///< presses already read

    bool operator==(const Button&) const = default;
  };
  /// One controller's reset gesture.
  struct Reset {
    std::vector<input::InputKey> keys;  ///< empty: this pad resets nothing
    std::uint32_t connection = 0;
    std::vector<std::uint32_t> releases;     ///< each key's releases already read
    bool open = false;                       ///< seen not made since the stop (or the last hold ended)
    std::optional<std::int64_t> hold_since;  ///< the gesture made at this tick, held since

    bool operator==(const Reset&) const = default;
  };
  static bool take(const input::PadState& pad, Button& b);
  static bool pressed(const input::PadState& pad, Button& b);
  static bool down(const input::PadState& pad, const Button& b);
  /// One tick of a reset gesture; true: it completed. blocked: a stop or the deadman.
  [[nodiscard]] bool tick(const input::PadState& pad, Reset& r, bool blocked, std::int64_t now_ms) const;
  static void end(const input::PadState& pad, Reset& r);

  Button operator_;
  Button supervisor_;
  Reset operator_reset_;
  Reset supervisor_reset_;
  std::string operator_gesture_;  ///< gesture_text() of each, said in every status
  std::string supervisor_gesture_;
  std::int64_t hold_ms_;
};

}  // namespace andros::run

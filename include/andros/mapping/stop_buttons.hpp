#pragma once
/// The stop buttons, as facts: which controller pressed its stop (the
/// operator's `estop`, the supervisor's `stop`), and, while stopped, which
/// completed a reset hold (docs/mapping.md, "Stop buttons"): its stop button
/// released after the stop, then pressed and held for `stop_reset_hold` with
/// the deadman released throughout. A button held from the stop itself never
/// starts one; letting it go, or the deadman held or pressed, ends one; held
/// on after the reset, it stops nothing until let go. Who
/// may reset whose stop is the operating state's to decide, not this.

#include <cstdint>
#include <optional>

#include "andros/input/input_state.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/model.hpp"

namespace andros::mapping {

/// While stopped, one tick of the stop buttons.
struct StoppedTick {
  StopPresses pressed;              ///< pressed since the last read (not merely held)
  std::optional<input::Pad> reset;  ///< the pad whose reset hold completed at this tick
};

class StopButtons {
 public:
  explicit StopButtons(const Mapping& mapping);

  /// A new session of the operator's controller (at_start_up: or the start,
  /// or a restart: the presses so far are history).
  void start(const input::InputState& input, bool at_start_up);
  /// Every press so far is history, on both pads (an engine that takes over
  /// from another, a reload's, read before its first step).
  void forget(const input::InputState& input);
  /// A stop button pressed since the last read, or held; takes the presses
  /// and ends any reset hold (the loop is not stopped, or starts afresh).
  StopPresses take(const input::InputState& input);
  /// Stopped, once per tick at now_ms: the presses since the last read, and
  /// a reset hold completed. deadman_touched: held now, or pressed since the last tick.
  StoppedTick stopped(const input::InputState& input, bool deadman_touched, std::int64_t now_ms);
  /// Which are held now, into status (stop_held, supervisor_stop).
  void held(const input::InputState& input, EngineStatus& status) const;

  bool operator==(const StopButtons&) const = default;

 private:
  /// One controller's stop button, counted per controller session.
  struct Button {
    std::optional<input::InputKey> key;
    std::uint32_t connection = 0;
    std::uint32_t presses = 0;               ///< presses already read
    std::uint32_t releases = 0;              ///< releases already read
    std::optional<std::int64_t> hold_since;  ///< a reset hold under way since this tick
    bool held_from_reset = false;            ///< held since its reset hold completed: no stop until let go

    bool operator==(const Button&) const = default;
  };
  static bool take(const input::PadState& pad, Button& b);
  [[nodiscard]] bool tick(const input::PadState& pad, Button& b, bool deadman_touched, std::int64_t now_ms,
                          bool& pressed) const;

  Button operator_;
  Button supervisor_;
  std::int64_t hold_ms_;
};

}  // namespace andros::mapping

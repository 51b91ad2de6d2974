#pragma once
// The controllers as the fault simulation's oracle (safety_oracle.hpp) reads
// them off the script: the operator's buttons and axes, the supervisor's
// buttons, and when each connected (an input stamped with its connect's time
// is the state the pad had when it appeared, not a press).

#include <cstdint>
#include <map>
#include <optional>

#include "andros/input/events.hpp"

namespace andros::test {

struct OraclePads {
  static constexpr int kTriggerPressed = 16384;  ///< 0.5 of 32767, as the engine rounds it

  bool connected = false;
  std::int64_t connect_t = -1;
  std::map<input::InputKey, bool> buttons;
  std::map<input::InputKey, int> axes;
  bool sup_connected = false;
  std::int64_t sup_connect_t = -1;
  std::map<input::InputKey, bool> sup_buttons;

  /// The operator's pad connected (up) or lost at t: nothing held.
  void connect(bool up, std::int64_t t) {
    connected = up;
    if (up) connect_t = t;
    buttons.clear();
    axes.clear();
  }
  void connect_supervisor(bool up, std::int64_t t) {
    sup_connected = up;
    if (up) sup_connect_t = t;
    sup_buttons.clear();
  }

  [[nodiscard]] int axis(input::InputKey key) const {
    const auto it = axes.find(key);
    return it == axes.end() ? 0 : it->second;
  }
  // Held: a button down, an axis one step below half its travel (16383, to stay on the permissive side).
  [[nodiscard]] bool held(input::InputKey key) const {
    if (!key.is_button()) return axis(key) >= kTriggerPressed - 1;
    const auto it = buttons.find(key);
    return it != buttons.end() && it->second;
  }
  // A deadman down as the engine reads it: a button held, a trigger at half its travel or past.
  [[nodiscard]] bool down(input::InputKey key) const {
    return key.is_button() ? held(key) : axis(key) >= kTriggerPressed;
  }
  [[nodiscard]] bool sup_held(std::optional<input::InputKey> key) const {
    if (!key) return false;
    const auto it = sup_buttons.find(*key);
    return it != sup_buttons.end() && it->second;
  }
};

}  // namespace andros::test

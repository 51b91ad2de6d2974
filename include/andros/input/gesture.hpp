#pragma once
/// Deliberate inputs, for `learn`: a button or hat direction pressed, or an
/// axis pushed past most of its travel and let go. A stick resting off centre,
/// a button held when the controller appeared, a release: none of them count.

#include <cstdint>
#include <map>
#include <optional>

#include "andros/input/input_state.hpp"

namespace andros::input {

/// |value| at or below which an axis is at rest (a quarter of its travel).
inline constexpr int kGestureRest = 8192;
/// |value| an axis must reach to count as pushed (three quarters of its travel).
inline constexpr int kGesturePushed = 24576;

/// One deliberate input. For an axis, negative says it was pushed towards
/// -32768 (stick up or left); a button's is false.
struct Gesture {
  InputKey key{};
  bool negative = false;

  bool operator==(const Gesture&) const = default;
};

/// Turns a controller's events into gestures.
class GestureDetector {
 public:
  /// Feeds one event; returns the gesture it completes, if any. Events
  /// stamped with the connect's time are the controller's state when it
  /// appeared: never a gesture. An axis counts once it was seen at rest,
  /// then pushed, then back at rest; after any gesture, every axis starts over.
  std::optional<Gesture> feed(const InputEvent& event);

  /// Forgets every push under way: an axis off rest now must come back first.
  void reset();

 private:
  struct Axis {
    int value = 0;
    bool ready = true;  ///< seen at rest since the last gesture or reset
    int peak = 0;       ///< the furthest push while ready (0: not pushed)
  };

  std::int64_t connect_t_ = -1;
  std::map<InputKey, bool> buttons_;
  std::map<int, int> hats_;
  std::map<InputKey, Axis> axes_;
};

}  // namespace andros::input

#pragma once
// Plays a feedback pattern on an SDL joystick without ever waiting: each
// pulse is one SDL_JoystickRumble call (SDL times its end), started from the
// input's poll when due.

#include <SDL.h>

#include <cstdint>
#include <optional>

#include "andros/input/feedback.hpp"

namespace andros::input {

class FeedbackPlayer {
 public:
  /// Sets the light and starts the first pulse now (now_ms: the last poll's
  /// time); replaces a pattern still playing.
  void play(SDL_Joystick* joystick, const FeedbackPattern& pattern, std::int64_t now_ms);
  /// Starts the pulse that is due by now_ms, if any. Call on every poll.
  void update(SDL_Joystick* joystick, std::int64_t now_ms);
  /// Forgets the pattern (its controller went away).
  void cancel() { pattern_.reset(); }

 private:
  void pulse(SDL_Joystick* joystick) const;

  std::optional<FeedbackPattern> pattern_;
  std::int64_t start_ms_ = 0;
  int started_ = 0;  ///< pulses started so far
};

}  // namespace andros::input

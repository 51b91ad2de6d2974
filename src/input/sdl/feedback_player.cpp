#include "feedback_player.hpp"

#include <algorithm>
#include <cmath>

namespace andros::input {
namespace {

Uint16 strength(double fraction) { return static_cast<Uint16>(std::lround(std::clamp(fraction, 0.0, 1.0) * 0xFFFF)); }

}  // namespace

void FeedbackPlayer::play(SDL_Joystick* joystick, const FeedbackPattern& pattern, std::int64_t now_ms) {
  pattern_ = pattern;
  start_ms_ = now_ms;
  started_ = 0;
  // Where the controller has no light or no motors, SDL would only say so.
  if (pattern.led && SDL_JoystickHasLED(joystick) == SDL_TRUE) {
    const auto& rgb = *pattern.led;
    SDL_JoystickSetLED(joystick, rgb[0], rgb[1], rgb[2]);
  }
  update(joystick, now_ms);
}

void FeedbackPlayer::update(SDL_Joystick* joystick, std::int64_t now_ms) {
  if (!pattern_) return;
  // Pulse k starts at 2k pulse lengths: on for one, off for one. After a
  // stall only the latest pulse due is played, never a burst.
  const std::int64_t period = 2 * std::int64_t{pattern_->ms};
  const int due = static_cast<int>(std::min<std::int64_t>(pattern_->pulses, (now_ms - start_ms_) / period + 1));
  if (due > started_) {
    started_ = due;
    pulse(joystick);
  }
  if (started_ >= pattern_->pulses) pattern_.reset();
}

void FeedbackPlayer::pulse(SDL_Joystick* joystick) const {
  if ((pattern_->low <= 0.0 && pattern_->high <= 0.0) || SDL_JoystickHasRumble(joystick) != SDL_TRUE) return;
  SDL_JoystickRumble(joystick, strength(pattern_->low), strength(pattern_->high), static_cast<Uint32>(pattern_->ms));
}

}  // namespace andros::input

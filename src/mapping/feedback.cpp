#include "andros/mapping/feedback.hpp"

namespace andros::mapping {

std::string_view feedback_event_name(FeedbackEvent event) {
  switch (event) {
    case FeedbackEvent::kStopped: return "stopped";
    case FeedbackEvent::kStopReset: return "stop_reset";
    case FeedbackEvent::kDeadmanRefused: return "deadman_refused";
    case FeedbackEvent::kLinkLost: return "link_lost";
    case FeedbackEvent::kTimedOut: return "enable_timeout";
    case FeedbackEvent::kDisabled: return "disabled";
    case FeedbackEvent::kWeaponsOn: return "weapons_on";
    case FeedbackEvent::kWeaponsOff: return "weapons_off";
    case FeedbackEvent::kEnabled: return "enabled";
    case FeedbackEvent::kControllerBack: return "controller_back";
    case FeedbackEvent::kSpeedLevel: return "speed_level";
  }
  return "?";
}

// Told apart by feel as well as by the light: one long hard rumble of both
// motors and red for "stopped", three hard knocks and red-orange for "no", one
// long heavy rumble for the link, one light buzz up for enabled and one heavy
// one down for disabled, two soft taps for "the controller is here"; two long
// hard pulses and yellow for "weapons live", three quick light taps for
// "weapons off" (a green of its own: enabled, nothing to fire); two soft
// pulses and amber for "timed out"; quick firm pulses, one per level (five
// in 540 ms), and no change of light for a speed level (the light still says enabled).
input::FeedbackPattern default_feedback_pattern(FeedbackEvent event) {
  using Rgb = std::array<std::uint8_t, 3>;
  switch (event) {
    case FeedbackEvent::kStopped: return {1.0, 1.0, 550, 1, Rgb{255, 0, 0}};
    case FeedbackEvent::kStopReset: return {0.6, 0.6, 150, 2, Rgb{255, 255, 255}};
    case FeedbackEvent::kDeadmanRefused: return {1.0, 1.0, 80, 3, Rgb{255, 60, 0}};
    case FeedbackEvent::kLinkLost: return {1.0, 0.4, 600, 1, Rgb{255, 0, 255}};
    case FeedbackEvent::kTimedOut: return {0.5, 0.5, 200, 2, Rgb{255, 200, 0}};
    case FeedbackEvent::kDisabled: return {0.7, 0.0, 200, 1, Rgb{255, 140, 0}};
    case FeedbackEvent::kWeaponsOn: return {1.0, 1.0, 150, 2, Rgb{255, 255, 0}};
    case FeedbackEvent::kWeaponsOff: return {0.0, 1.0, 60, 3, Rgb{0, 255, 160}};
    case FeedbackEvent::kEnabled: return {0.0, 0.7, 200, 1, Rgb{0, 255, 0}};
    case FeedbackEvent::kControllerBack: return {0.3, 0.3, 60, 2, Rgb{0, 0, 255}};
    case FeedbackEvent::kSpeedLevel: return {0.5, 1.0, 60, 1, std::nullopt};
  }
  return {};
}

input::FeedbackPattern feedback_pattern(FeedbackEvent event, const input::FeedbackPattern& pattern,
                                        std::size_t speed_level) {
  auto out = pattern;
  if (event == FeedbackEvent::kSpeedLevel) out.pulses = static_cast<int>(speed_level) + 1;
  return out;
}

FeedbackTable default_feedback() {
  FeedbackTable table;
  for (std::size_t i = 0; i < kFeedbackEventCount; ++i) {
    table.patterns[i] = default_feedback_pattern(static_cast<FeedbackEvent>(i));
  }
  return table;
}

}  // namespace andros::mapping

#include "andros/run/feedback.hpp"

#include <algorithm>

namespace andros::run {

using mapping::DeadmanState;
using mapping::FeedbackEvent;

FeedbackStatus feedback_status(const TickReport& report) {
  // Enabled as the state machine says, never as the engine alone sees it: the
  // pad's light cannot say "enabled" while nothing reaches the vehicle.
  // A weapons mode only while enabled, too.
  return {report.connected, report.engine.deadman, report.enabled(), report.enabled() && report.engine.weapons_mode,
          report.engine.speed.index};
}

std::vector<FeedbackEvent> feedback_events(const FeedbackStatus& before, const FeedbackStatus& after,
                                           const std::vector<ReportedTransition>& transitions) {
  const auto any = [&transitions](auto&& what) {
    return std::any_of(transitions.begin(), transitions.end(), [&what](const auto& r) { return what(r.transition); });
  };
  const auto entered = [](OpState state) {
    return [state](const Transition& t) { return t.to == state && t.from != state; };
  };
  const auto left = [](OpState state) {
    return [state](const Transition& t) { return t.from == state && t.to != state; };
  };
  std::vector<FeedbackEvent> events;
  if (any(entered(OpState::kStopped))) events.push_back(FeedbackEvent::kStopped);
  if (any([](const Transition& t) {
        return t.event == OpEvent::kOperatorReset || t.event == OpEvent::kSupervisorReset;
      })) {
    events.push_back(FeedbackEvent::kStopReset);
  }
  if (after.deadman == DeadmanState::kHeldNotFresh && before.deadman != DeadmanState::kHeldNotFresh) {
    events.push_back(FeedbackEvent::kDeadmanRefused);
  }
  // Published only when the link was up (the machine's condition changed).
  if (any([](const Transition& t) { return t.event == OpEvent::kLinkDown || t.event == OpEvent::kLinkTaken; })) {
    events.push_back(FeedbackEvent::kLinkLost);
  }
  if (any([](const Transition& t) { return t.from == OpState::kEnabled && t.event == OpEvent::kEnableTimeout; })) {
    events.push_back(FeedbackEvent::kTimedOut);
  }
  // A lost controller cannot be told anything: no "disabled" with it.
  if (any(left(OpState::kEnabled)) && after.connected) events.push_back(FeedbackEvent::kDisabled);
  if (after.weapons_mode && !before.weapons_mode) events.push_back(FeedbackEvent::kWeaponsOn);
  if (before.weapons_mode && !after.weapons_mode && after.connected) events.push_back(FeedbackEvent::kWeaponsOff);
  if (any(entered(OpState::kEnabled))) events.push_back(FeedbackEvent::kEnabled);
  if (after.connected && !before.connected) events.push_back(FeedbackEvent::kControllerBack);
  // A press of a speed button, or a restart or a new pad back at the initial level.
  if (before.connected && after.connected && before.speed_level != after.speed_level) {
    events.push_back(FeedbackEvent::kSpeedLevel);
  }
  return events;
}

std::optional<FeedbackEvent> FeedbackNotifier::observe(const FeedbackStatus& status,
                                                       const std::vector<ReportedTransition>& transitions) {
  const auto events = feedback_events(last_, status, transitions);
  last_ = status;
  const auto it = std::find_if(events.begin(), events.end(), [this](FeedbackEvent e) { return table_[e].has_value(); });
  std::optional<FeedbackEvent> played;
  std::optional<input::FeedbackPattern> pattern;
  if (it != events.end()) {
    played = *it;
    pattern = mapping::feedback_pattern(*it, *table_[*it], status.speed_level);
    // An enabled colour (weapons_off's green too) is for an enabled bridge only.
    const bool enabled_colour =
        *it == FeedbackEvent::kEnabled || *it == FeedbackEvent::kWeaponsOn || *it == FeedbackEvent::kWeaponsOff;
    if (enabled_colour && !status.enabled) pattern->led.reset();
  }
  // The light keeps the last colour set. Green (or a weapons colour) left on
  // after a stop would tell the operator the robot still follows the pad: the
  // stop sets a colour, whatever the table says of the event that ends it
  // (switched off, `led: off`, one more important without a colour).
  if (enabled_light_ && !status.enabled && status.connected && !(pattern && pattern->led)) {
    if (!pattern) pattern = input::FeedbackPattern{.low = 0.0, .high = 0.0, .ms = 1, .pulses = 1, .led = std::nullopt};
    const auto& disabled = table_[FeedbackEvent::kDisabled];
    pattern->led =
        disabled && disabled->led ? disabled->led : mapping::default_feedback_pattern(FeedbackEvent::kDisabled).led;
  }
  if (!pattern) return played;
  if (pattern->led) enabled_light_ = status.enabled;
  input_.feedback(*pattern);
  return played;
}

}  // namespace andros::run

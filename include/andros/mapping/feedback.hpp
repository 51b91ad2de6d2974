#pragma once
/// Which pattern (rumble, light) each feedback event plays: the defaults,
/// changed or switched off by a mapping's `feedback:` section (docs/mapping.md).

#include <array>
#include <cstdint>
#include <optional>
#include <string_view>

#include "andros/input/feedback.hpp"

namespace andros::mapping {

/// What the operator is told through the controller, most important first:
/// when several happen in one tick, the first with a pattern plays.
enum class FeedbackEvent : std::uint8_t {
  kStopped,         ///< stopped by a stop button
  kStopReset,       ///< a stop was reset (a reset hold): press the deadman afresh
  kDeadmanRefused,  ///< the deadman is held but not fresh (held at connect or start-up, or stuck)
  kLinkLost,        ///< the link to the vehicle went down
  kTimedOut,        ///< the enable timeout ended "enabled"
  kDisabled,        ///< was enabled, no longer is (controller still connected)
  kWeaponsOn,       ///< a weapons mode began (EngineStatus::weapons_mode)
  kWeaponsOff,      ///< a weapons mode ended, the bridge still enabled
  kEnabled,         ///< became enabled
  kControllerBack,  ///< the controller connected (at start-up or again)
  kSpeedLevel,      ///< the speed level changed: as many pulses as the new level's number
};

inline constexpr std::size_t kFeedbackEventCount = 11;

/// The event's key in a mapping's `feedback:` section ("deadman_refused", ...).
std::string_view feedback_event_name(FeedbackEvent event);

/// The pattern per event (by FeedbackEvent value); none: that event is off.
struct FeedbackTable {
  std::array<std::optional<input::FeedbackPattern>, kFeedbackEventCount> patterns;

  [[nodiscard]] const std::optional<input::FeedbackPattern>& operator[](FeedbackEvent event) const {
    return patterns[static_cast<std::size_t>(event)];
  }
  std::optional<input::FeedbackPattern>& operator[](FeedbackEvent event) {
    return patterns[static_cast<std::size_t>(event)];
  }
};

/// The pattern an event plays now: its table pattern, except that
/// kSpeedLevel pulses once per level up to `speed_level` (0 = the slowest).
input::FeedbackPattern feedback_pattern(FeedbackEvent event, const input::FeedbackPattern& pattern,
                                        std::size_t speed_level);

/// The built-in pattern of an event (what a mapping without `feedback:` plays).
input::FeedbackPattern default_feedback_pattern(FeedbackEvent event);
/// Every event on, with its built-in pattern.
FeedbackTable default_feedback();

}  // namespace andros::mapping

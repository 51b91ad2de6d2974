#pragma once
/// Rumble and light for the operator: which events two successive statuses
/// show, and the pattern of the most important one played on the controller.

#include <optional>
#include <vector>

#include "andros/input/input_source.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// What the events are read from, once per tick.
struct FeedbackStatus {
  bool connected = false;                                         ///< a controller is connected
  mapping::DeadmanState deadman = mapping::DeadmanState::kNoPad;  ///< the guard's fact of the deadman
  bool enabled = false;         ///< the operating state is "enabled": frames follow the controller
  bool link_up = false;         ///< the link is up and frames follow the controller
  bool weapons_mode = false;    ///< EngineStatus::weapons_mode
  bool stopped = false;         ///< the operating state is "stopped" (a stop button)
  bool reset = false;           ///< the last stop was reset, not yet enabled since (TickReport::reset_by)
  std::size_t speed_level = 0;  ///< EngineStatus::speed's index

  bool operator==(const FeedbackStatus&) const = default;
};

/// A tick's report as the feedback reads it.
FeedbackStatus feedback_status(const TickReport& report);

/// The events between two statuses, most important first (FeedbackEvent
/// order); none for equal statuses. Pure.
std::vector<mapping::FeedbackEvent> feedback_events(const FeedbackStatus& before, const FeedbackStatus& after);

/// Feeds each tick's status through feedback_events() and plays the first
/// event that has a pattern in the table on the input's controller. A light
/// set while enabled never outlives it: leaving the enabled state sets the
/// `disabled` colour (the built-in orange when the table gives none) when
/// the event played sets no colour of its own.
class FeedbackNotifier {
 public:
  FeedbackNotifier(mapping::FeedbackTable table, input::InputSource& input) : table_(table), input_(input) {}

  /// After a reload: the new mapping's patterns.
  void set_table(mapping::FeedbackTable table) { table_ = table; }
  /// Call on the thread that pumps the input. Returns the event played, if any.
  std::optional<mapping::FeedbackEvent> observe(const FeedbackStatus& status);

 private:
  mapping::FeedbackTable table_;
  input::InputSource& input_;
  FeedbackStatus last_;         ///< before the first tick: nothing connected, not enabled, link down
  bool enabled_light_ = false;  ///< the last colour set was set while enabled (green, the weapons colours)
};

}  // namespace andros::run

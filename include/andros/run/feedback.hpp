#pragma once
/// Rumble and light for the operator: which events a tick brings (the
/// machine's transitions, and the pad's and the engine's facts that
/// changed), and the pattern of the most important one played on the controller.

#include <optional>
#include <vector>

#include "andros/input/input_source.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/feedback.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// The pad's and the engine's facts the events are read from, once per tick
/// (what the machine decided comes as its transitions).
struct FeedbackStatus {
  bool connected = false;                                         ///< a controller is connected
  mapping::DeadmanState deadman = mapping::DeadmanState::kNoPad;  ///< the guard's fact of the deadman
  bool enabled = false;         ///< the operating state is "enabled": frames follow the controller
  bool weapons_mode = false;    ///< EngineStatus::weapons_mode, while enabled
  std::size_t speed_level = 0;  ///< EngineStatus::speed's index

  bool operator==(const FeedbackStatus&) const = default;
};

/// A tick's report as the feedback reads it.
FeedbackStatus feedback_status(const TickReport& report);

/// The events of a tick, most important first (FeedbackEvent order): the
/// machine's transitions (stopped, a stop reset, the link lost, the enable
/// timeout, disabled, enabled), and the facts that changed from `before` to
/// `after` (the deadman refused, a weapons mode on or off, a controller
/// back, a speed level). None for no transition and equal statuses. Pure.
std::vector<mapping::FeedbackEvent> feedback_events(const FeedbackStatus& before, const FeedbackStatus& after,
                                                    const std::vector<ReportedTransition>& transitions = {});

/// Feeds each tick through feedback_events() and plays the first
/// event that has a pattern in the table on the input's controller. A light
/// set while enabled never outlives it: leaving the enabled state sets the
/// `disabled` colour (the built-in orange when the table gives none) when
/// the event played sets no colour of its own.
class FeedbackNotifier {
 public:
  FeedbackNotifier(mapping::FeedbackTable table, input::InputSource& input) : table_(table), input_(input) {}

  /// After a reload: the new mapping's patterns.
  void set_table(mapping::FeedbackTable table) { table_ = table; }
  /// A tick: its facts and the machine's transitions since the last. Call on
  /// the thread that pumps the input. Returns the event played, if any.
  std::optional<mapping::FeedbackEvent> observe(const FeedbackStatus& status,
                                                const std::vector<ReportedTransition>& transitions);
  /// A tick's report.
  std::optional<mapping::FeedbackEvent> observe(const TickReport& report) {
    return observe(feedback_status(report), report.transitions);
  }

 private:
  mapping::FeedbackTable table_;
  input::InputSource& input_;
  FeedbackStatus last_;         ///< before the first tick: nothing connected, not enabled
  bool enabled_light_ = false;  ///< the last colour set was set while enabled (green, the weapons colours)
};

}  // namespace andros::run

#pragma once
/// Plays an event script into a TickInput (the controllers' events to its
/// state, the fault events apart) against a clock it is told, not
/// one it reads: replay drives it with a virtual clock, `run --input` with
/// the scheduler's tick times. The frame timing of docs/event-scripts.md (the
/// frame at t reflects every event with a time <= t) lives here once.

#include <cstdint>
#include <optional>
#include <string>

#include "andros/input/events.hpp"
#include "andros/input/input_state.hpp"

namespace andros::input {

class ScriptPlayer {
 public:
  /// Plays text, which must outlive the player. Text that can rewind is
  /// read once first, for supervised().
  explicit ScriptPlayer(TextReader& text);

  /// Applies every event with a time <= t_ms (the state the frame at t_ms
  /// reflects). Parse errors surface here as InputError.
  void advance_to(std::int64_t t_ms, TickInput& input);

  /// True once the frame at t_ms is the script's last: the first frame time
  /// >= the `end` time (or the last event's time, for a script with no `end`).
  [[nodiscard]] bool finished_at(std::int64_t t_ms) const;

  /// The script addresses the supervisor's controller somewhere: a
  /// supervisor is configured for the whole run (InputSource::supervised).
  [[nodiscard]] bool supervised() const { return supervised_; }

 private:
  EventReader reader_;
  std::optional<InputEvent> pending_;  ///< read but not yet due
  bool exhausted_ = false;
  std::int64_t last_t_ = 0;
  bool supervised_ = false;
};

}  // namespace andros::input

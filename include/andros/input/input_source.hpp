#pragma once
/// Where controller events come from: SDL (live) or an event script played in
/// real time. The run loop calls pump() once per tick, right after the tick's
/// time is reached, so the state a frame uses is never older than its tick and
/// nothing polls between ticks.

#include <cstdint>
#include <optional>
#include <string>

#include "andros/input/device_layout.hpp"
#include "andros/input/feedback.hpp"
#include "andros/input/input_state.hpp"

namespace andros::input {

class InputSource {
 public:
  virtual ~InputSource() = default;

  /// Applies to input every event that happened up to now_ms (ms since the
  /// run started): the controllers' to its state, a script's fault events
  /// apart. Never blocks for long and never throws at run time: a source
  /// that loses its device reports a disconnect event instead.
  virtual void pump(TickInput& input, std::int64_t now_ms) = 0;

  /// True when the source has nothing more to give (the end of a script).
  /// A live controller source never finishes.
  [[nodiscard]] virtual bool finished(std::int64_t now_ms) const = 0;

  /// A supervisor's controller is configured (`run --supervisor`, a script
  /// that addresses one): driving needs it connected as well as the operator's.
  [[nodiscard]] virtual bool supervised() const { return false; }

  /// Plays a pattern on the controller, if it has rumble or a light; never
  /// blocks. Called on the thread that calls pump(). A script has no
  /// controller: nothing happens.
  virtual void feedback(const FeedbackPattern& /*pattern*/) {}

  /// The live controller's inputs (whether SDL knows it as a game
  /// controller); none while none is connected, and never for a script.
  [[nodiscard]] virtual std::optional<DeviceLayout> device() const { return std::nullopt; }

  /// Why a role has no controller although one is attached: a pad refused
  /// (two pads SDL cannot tell apart, docs/controllers.md), and what to do,
  /// in words for the screen; "" while no role waits on a refusal. A script
  /// refuses nothing.
  [[nodiscard]] virtual std::string refusal() const { return {}; }
};

}  // namespace andros::input

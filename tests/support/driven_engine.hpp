#pragma once
// The engine driven as the run loop drives it, reduced to not enabled and
// enabled: for the engine's tests and the engine's fuzz target.

#include <utility>

#include "andros/mapping/engine.hpp"
#include "andros/run/drive_guard.hpp"

namespace andros::testing {

/// The engine as the engine's own tests drive it, with the run loop's
/// guards (run/drive_guard.hpp): each step the guards' facts, then the step
/// with motion allowed while the deadman reports a fresh hold and no stop
/// button is pressed in the tick. That is the operating-state machine's
/// decision reduced to not enabled and enabled, with no latch, no link and no
/// rebase: tests/run/test_driven_engine.cpp holds it to the run loop itself
/// (the real machine and guards) on random input, tick by tick, up to the
/// first stop the loop latches. The latch, the link and the rebases are
/// tested with the loop (tests/run), not here. Everything else is the engine's own.
class DrivenEngine {
 public:
  DrivenEngine(mapping::ValidMapping mapping, mapping::EngineOptions options)
      : engine_(std::move(mapping), options), guard_(engine_.mapping()) {}

  /// One tick: the facts, the decision, the step.
  protocol::DataBytes step(const input::InputState& input, std::int64_t now_ms) {
    const auto facts = guard_.facts(input, now_ms, enabled_);
    enabled_ = facts.deadman == mapping::DeadmanState::kFreshHold && !facts.stops;
    guard_.decided(enabled_, now_ms);
    const auto data = engine_.step(input, now_ms, enabled_).data;
    status_ = engine_.status();
    guard_.report(input, status_);
    return data;
  }
  /// Whether the last step allowed motion.
  [[nodiscard]] bool enabled() const { return enabled_; }

  void restart(const input::InputState& now) {
    enabled_ = false;
    guard_.rebase(now);
    engine_.rebase(now);
    status_ = engine_.status();
    guard_.report(now, status_);
  }
  mapping::StopPresses take_stop(const input::InputState& input) { return guard_.take_stop(input); }
  run::StoppedTick stopped(const input::InputState& input, std::int64_t now_ms) {
    return guard_.stopped(input, now_ms);
  }
  [[nodiscard]] protocol::DataBytes neutral() const { return engine_.neutral(); }
  /// The engine's status after the last step, with the guards' part (the deadman, the stop buttons).
  [[nodiscard]] const mapping::EngineStatus& status() const { return status_; }
  [[nodiscard]] const mapping::Mapping& mapping() const { return engine_.mapping(); }
  [[nodiscard]] bool settled() const { return engine_.settled(); }
  mapping::Engine& engine() { return engine_; }

 private:
  mapping::Engine engine_;
  run::DriveGuard guard_;
  mapping::EngineStatus status_;
  bool enabled_ = false;
};

}  // namespace andros::testing

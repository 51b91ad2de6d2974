#pragma once
// Driving an Engine tick by tick from event-script lines, for the engine tests.

#include <string>

#include "andros/input/events.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/drive_guard.hpp"
#include "support/temp_dir.hpp"

namespace andros::testing {

/// The engine as the engine's own tests drive it, with the run loop's
/// guards (run/drive_guard.hpp): each step the guards' facts, then the step
/// with motion allowed while the deadman reports a fresh hold and no stop
/// button is pressed in the tick. That is the operating-state machine's
/// decision reduced to not enabled and enabled, with no latch, no link and no
/// rebase: the machine itself, its latch and the loop are tested with the
/// loop (tests/run), not here. Everything else is the engine's own.
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

/// The shipped HD1 mapping (deadman leftshoulder, drive on lefty).
inline mapping::ValidMapping hd1_mapping() {
  return mapping::load_mapping(std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml");
}

/// A mapping file's text, loaded and validated.
inline mapping::ValidMapping mapping_from_yaml(const std::string& text) {
  const TempDir dir;
  return mapping::load_mapping(dir.write("m.yaml", text));
}

/// Applies event-script lines ("T connect", "T button NAME 0|1", ...) to the
/// input state, as the run loop's pump does: the tick's events, after its
/// begin_tick (an axis's span starts again from its value now).
inline void apply_script(input::InputState& state, const std::string& text) {
  state.begin_tick();
  for (const auto& e : input::parse_event_script(text, "t.events")) state.apply(e);
}

/// The usual start: the start-up tick at 0, a pad connected and the deadman
/// (leftshoulder) pressed afresh, with `also` in the same frame, and the
/// enabling tick at 40.
inline void start_enabled(DrivenEngine& engine, input::InputState& state, const std::string& also = "") {
  engine.step(state, 0);
  apply_script(state, "0 connect\n10 button leftshoulder 1\n" + also);
  engine.step(state, 40);
}

}  // namespace andros::testing

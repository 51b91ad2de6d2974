#pragma once
// Driving an Engine tick by tick from event-script lines, for the engine tests.

#include <string>

#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "support/driven_engine.hpp"
#include "support/temp_dir.hpp"

namespace andros::testing {

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

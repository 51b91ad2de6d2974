#pragma once
/// The engine's state after a step, as a plain value: what the run loop
/// reports and the operator's view and log show.

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/snapshot.hpp"

namespace andros::mapping {

/// Why the engine is (not) enabled, for the operator's status view and logs.
enum class EnableState : std::uint8_t {
  kEnabled,
  kNoController,     ///< no controller connected
  kDeadmanReleased,  ///< the deadman is not held
  kDeadmanNotFresh,  ///< held since connect or start-up: release and press again
};

std::string_view describe(EnableState state);

struct EngineStatus {
  EnableState enable = EnableState::kNoController;
  std::string layer;  ///< the active layer's name ("" for the base layer)
  std::vector<input::InputKey> held_back;  ///< inputs that act again once seen at rest (RestRule)
  /// Enabled, weapons enabled for the run, and the active layer has weapon
  /// bindings: an armed fire input fires (what the banner and the pad announce).
  bool weapons_mode = false;
  /// In a weapons mode with an arming input held: a fire button pressed now fires.
  bool armed = false;
};

}  // namespace andros::mapping

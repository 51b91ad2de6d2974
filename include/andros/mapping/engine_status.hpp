#pragma once
/// The engine's state after a step, as a plain value: what the run loop
/// reports and the operator's view and log show.

#include <cstddef>
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
  kPanic,            ///< the trigger deadman squeezed past `deadman_panic`: off until fully released
  kTimedOut,         ///< `enable_timeout` passed with no input change: release and press again
};

std::string_view describe(EnableState state);

/// The speed level in force (the mapping's `scale:`): drive and pivot move
/// `value` times their distance from rest.
struct SpeedLevel {
  std::size_t index = 0;  ///< 0 = the slowest
  std::size_t count = 1;  ///< the mapping's levels (1 without `scale:`)
  double value = 1.0;     ///< the fraction of full speed

  bool operator==(const SpeedLevel&) const = default;
};

struct EngineStatus {
  EnableState enable = EnableState::kNoController;
  std::string layer;  ///< the active layer's name ("" for the base layer)
  std::vector<input::InputKey> held_back;  ///< inputs that act again once seen at rest (RestRule)
  /// Enabled, weapons enabled for the run, and the active layer has weapon
  /// bindings: an armed fire input fires (what the banner and the pad announce).
  bool weapons_mode = false;
  /// A stop button (the mapping's `estop`) was pressed since the last step or
  /// is held: the run loop latches "stopped by the operator".
  bool stop_pressed = false;
  SpeedLevel speed;
};

}  // namespace andros::mapping

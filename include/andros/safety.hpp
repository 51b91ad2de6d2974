#pragma once
/// The safety rules of contract section 5, in one place. The engine passes
/// every frame through apply_safety() after the bindings, so no mapping can
/// bypass them.

#include <bitset>

#include "andros/frame.hpp"
#include "andros/mapping.hpp"

namespace andros {

struct SafetyContext {
  bool enabled = false;   ///< connected + deadman held + pressed fresh
  bool weapons = false;   ///< weapons enabled for the run
  std::bitset<kSignalCount> armed;  ///< weapon signals whose arming input is held
  int center = kDefaultCenter;
  BrakeMode brake = BrakeMode::kEnabled;
};

/// Not enabled: motion and weapon bits 0, drive/pivot at centre, selectors,
/// levels and constants unchanged. Enabled: safety = 1, drive_brake = 1 (or
/// only while moving), weapons only when enabled for the run and armed.
/// Always: an opposing pair asked for both ways sends neither.
ControlState apply_safety(ControlState state, const SafetyContext& context);

}  // namespace andros

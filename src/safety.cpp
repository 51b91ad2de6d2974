#include "andros/safety.hpp"

namespace andros {

ControlState apply_safety(ControlState state, const SafetyContext& ctx) {
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    auto& v = state.values[i];
    switch (kSignals[i].kind) {
      case SignalKind::kMotion:
        if (!ctx.enabled) v = 0;
        break;
      case SignalKind::kWeapon:
        if (!ctx.enabled || !ctx.weapons || !ctx.armed[i]) v = 0;
        break;
      case SignalKind::kCentred:
        if (!ctx.enabled) v = static_cast<std::uint8_t>(ctx.center);
        break;
      case SignalKind::kInterlock:
      case SignalKind::kSelector:
      case SignalKind::kLevel:
      case SignalKind::kConstant: break;
    }
  }
  const bool moving = state[signal_id("drive")] != ctx.center || state[signal_id("pivot")] != ctx.center;
  state[signal_id("safety")] = ctx.enabled ? 1 : 0;
  state[signal_id("drive_brake")] = ctx.enabled && (ctx.brake == BrakeMode::kEnabled || moving) ? 1 : 0;

  const ControlState asked = state;
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    const auto partner = partner_of(static_cast<SignalId>(i));
    if (partner && asked.values[i] != 0 && asked[*partner] != 0) state.values[i] = 0;
  }
  return state;
}

}  // namespace andros

#include "andros/mapping/safety.hpp"

#include <algorithm>
#include <cmath>

#include "andros/mapping/axis.hpp"
#include "overload.hpp"

namespace andros::mapping {

protocol::ControlState apply_safety(protocol::ControlState state, const SafetyContext& ctx) {
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    auto& v = state.values[i];
    switch (protocol::kSignals[i].kind) {
      case protocol::SignalKind::kMotion:
        if (!ctx.enabled) v = 0;
        break;
      case protocol::SignalKind::kWeapon:
        if (!ctx.enabled || !ctx.weapons || !ctx.armed[i]) v = 0;
        break;
      case protocol::SignalKind::kCentred:
        if (!ctx.enabled) v = protocol::kNeutralCentre;  // never the mapping's trim
        break;
      case protocol::SignalKind::kInterlock:
      case protocol::SignalKind::kSelector:
      case protocol::SignalKind::kLevel:
      case protocol::SignalKind::kConstant: break;
    }
  }
  const bool moving = state[protocol::signal_id("drive")] != ctx.center || state[protocol::signal_id("pivot")] != ctx.center;
  state[protocol::signal_id("safety")] = ctx.enabled ? 1 : 0;
  state[protocol::signal_id("drive_brake")] = ctx.enabled && (ctx.brake == BrakeMode::kEnabled || moving) ? 1 : 0;

  const protocol::ControlState asked = state;
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto partner = protocol::partner_of(static_cast<protocol::SignalId>(i));
    if (partner && asked.values[i] != 0 && asked[*partner] != 0) state.values[i] = 0;
  }
  return state;
}

RestRule::RestRule(const Mapping& mapping) {
  for (int layer = -1; layer < static_cast<int>(mapping.layers.size()); ++layer) {
    Readers& readers = readers_.emplace_back();
    for (const auto ref : effective_bindings(mapping, layer)) {
      const auto& b = binding_at(mapping, ref);
      // A button rests released whoever reads it; an axis rests where its binding sends nothing.
      Reader r{{ref.layer, ref.index}, Reader::Rest::kReleased, false, 0.0};
      std::visit(Overload{
                     [&](const ButtonBinding& x) { r = {r.binding, Reader::Rest::kBelow, x.invert, x.threshold}; },
                     [&](const PairBinding& x) { r = {r.binding, Reader::Rest::kInsideBand, false, x.threshold}; },
                     [&](const AxisBinding& x) {
                       const bool centred = protocol::info(x.analog).kind == protocol::SignalKind::kCentred;
                       r = {r.binding, centred ? Reader::Rest::kInsideDeadzone : Reader::Rest::kNotPositive,
                            x.shape.invert, x.shape.deadzone};
                     },
                     [](const auto&) {},
                 },
                 b.rule);
      for (const auto& u : b.inputs) {
        readers[u.key].push_back(u.key.is_button() ? Reader{r.binding, Reader::Rest::kReleased, false, 0.0} : r);
      }
      // An arming trigger counts as held past half way.
      if (b.arm) {
        readers[b.arm->key].push_back(b.arm->key.is_button()
                                          ? Reader{r.binding, Reader::Rest::kReleased, false, 0.0}
                                          : Reader{r.binding, Reader::Rest::kBelow, false, kDefaultThreshold});
      }
    }
  }
}

bool RestRule::at_rest(const input::InputState& input, input::InputKey key, const std::vector<Reader>& readers) {
  if (key.is_button()) return !input.button(key).down;
  const double x = normalise_axis(input.axis(key));
  return std::all_of(readers.begin(), readers.end(), [x](const Reader& r) {
    const double v = r.invert ? -x : x;
    switch (r.rest) {
      case Reader::Rest::kReleased: return true;
      case Reader::Rest::kBelow: return v < r.limit;
      case Reader::Rest::kInsideBand: return std::abs(v) < r.limit;
      case Reader::Rest::kInsideDeadzone: return std::abs(v) <= r.limit;
      case Reader::Rest::kNotPositive: return v <= r.limit;
    }
    return false;
  });
}

void RestRule::update(const input::InputState& input, int layer, bool enabled, std::map<input::InputKey, std::uint32_t>& seen) {
  if (!enabled) {
    enabled_ = false;
    held_.clear();
    return;
  }
  // Becoming enabled, also with a new controller between two frames, changes every input's meaning.
  const bool edge = !enabled_ || input.connection() != connection_;
  const auto& now = readers_[static_cast<std::size_t>(layer + 1)];
  const auto& before = readers_[static_cast<std::size_t>(layer_ + 1)];
  const auto same_bindings = [](const std::vector<Reader>& a, const std::vector<Reader>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end(),
                      [](const Reader& x, const Reader& y) { return x.binding == y.binding; });
  };
  // An input nothing reads cannot act; if a binding reads it again, that is a change of meaning.
  std::erase_if(held_, [&](const auto& h) { return !now.contains(h.first); });
  for (const auto& [key, readers] : now) {
    const auto was = before.find(key);
    const bool changed = edge || was == before.end() || !same_bindings(was->second, readers);
    const std::uint32_t presses = key.is_button() ? input.button(key).presses : 0;
    const bool rest = at_rest(input, key, readers);
    if (changed) {
      if (key.is_button()) seen[key] = presses;  // presses up to this frame meant something else
      if (rest) held_.erase(key);
      else held_[key] = presses;
    } else if (const auto h = held_.find(key); h != held_.end() && (rest || presses > h->second)) {
      held_.erase(h);  // released, or released and pressed again since it was held back
    }
  }
  enabled_ = true;
  connection_ = input.connection();
  layer_ = layer;
}

std::vector<input::InputKey> RestRule::held_back_inputs() const {
  std::vector<input::InputKey> keys;
  for (const auto& h : held_) keys.push_back(h.first);
  return keys;
}

}  // namespace andros::mapping

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
        if (!ctx.enabled || !ctx.weapons || !ctx.armed[i] || !ctx.consent) v = 0;
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
  const bool moving =
      state[protocol::signal_id("drive")] != ctx.center || state[protocol::signal_id("pivot")] != ctx.center;
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
  if (mapping.supervisor && mapping.supervisor->weapons_consent) {
    consent_key_ = mapping.supervisor->weapons_consent->key;
    consent_ = ConsentState::kReleased;
  }
  for (int layer = -1; layer < static_cast<int>(mapping.layers.size()); ++layer) {
    Readers& readers = readers_.emplace_back();
    Arms& arms = arms_.emplace_back();
    auto& weapons = weapons_.emplace_back();
    for (const auto ref : effective_bindings(mapping, layer)) {
      const auto& b = binding_at(mapping, ref);
      // A button rests released whoever reads it; an axis rests where its binding sends nothing.
      Reader r{{ref.layer, ref.index}, Reader::Rest::kReleased, false, 0.0};
      std::visit(Overload{
                     [&](const ButtonBinding& x) {
                       r = {r.binding, Reader::Rest::kBelow, x.invert, x.threshold};
                     },
                     [&](const PairBinding& x) {
                       r = {r.binding, Reader::Rest::kInsideBand, false, x.threshold};
                     },
                     [&](const AxisBinding& x) {
                       const bool centred = protocol::info(x.analog).kind == protocol::SignalKind::kCentred;
                       r = {r.binding, centred ? Reader::Rest::kInsideDeadzone : Reader::Rest::kNotPositive,
                            x.shape.invert, x.shape.deadzone};
                     },
                     [](const auto&) {},
                 },
                 b.rule);
      if (std::holds_alternative<WeaponBinding>(b.rule)) weapons.push_back(r.binding);
      for (const auto& u : b.inputs) {
        readers[u.key].push_back(u.key.is_button() ? Reader{r.binding, Reader::Rest::kReleased, false, 0.0} : r);
      }
      // An arming trigger counts as held past half way.
      if (b.arm) {
        const auto arm = b.arm->key.is_button() ? Reader{r.binding, Reader::Rest::kReleased, false, 0.0}
                                                : Reader{r.binding, Reader::Rest::kBelow, false, kDefaultThreshold};
        readers[b.arm->key].push_back(arm);
        arm_readers_.try_emplace(b.arm->key, std::vector{arm});
        for (const auto& u : b.inputs) arms[b.arm->key].push_back(u.key);
      }
    }
    // The speed buttons mean the same in every layer (no binding: layer -2).
    std::size_t n = 0;
    for (const auto& key : {mapping.scale.up, mapping.scale.down}) {
      if (key) readers[key->key].push_back(Reader{{-2, n}, Reader::Rest::kReleased, false, 0.0});
      ++n;
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

void RestRule::update(const input::InputState& input, int layer, bool enabled,
                      std::map<input::InputKey, std::uint32_t>& seen) {
  update_consent(input, layer, enabled);  // before hold_back: it reads the last frame's enabled_, connection_, layer_
  if (enabled) {
    hold_back(input, layer, seen);
  } else {
    enabled_ = false;
    held_.clear();
    armed_.clear();
  }
  arms_down_.clear();
  for (const auto& [key, readers] : arm_readers_) {
    if (key.is_button()) arm_presses_[key] = input.button(key).presses;
    else if (!at_rest(input, key, readers)) arms_down_.insert(key);
  }
  arms_connection_ = input.connection();
}

void RestRule::hold_back(const input::InputState& input, int layer, std::map<input::InputKey, std::uint32_t>& seen) {
  // Becoming enabled, also with a new controller between two frames, changes every input's meaning.
  const bool edge = !enabled_ || input.connection() != connection_;
  const auto& now = readers_[static_cast<std::size_t>(layer + 1)];
  const auto& before = readers_[static_cast<std::size_t>(layer_ + 1)];
  const auto& arms = arms_[static_cast<std::size_t>(layer + 1)];
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
      // An arming input pressed in this very frame counts, as the deadman does: it arms, it fires nothing.
      hold(input, key, rest || (arms.contains(key) && pressed_this_frame(input, key)));
    } else if (const auto h = held_.find(key); h != held_.end() && (rest || presses > h->second)) {
      held_.erase(h);  // released, or released and pressed again since it was held back
    }
  }
  hold_back_fire_inputs(input, layer, seen);
  enabled_ = true;
  connection_ = input.connection();
  layer_ = layer;
}

// Arming changes what a fire input means: one held (or pressed) by the frame its
// weapon becomes armed fired nothing then, and waits until it is released.
void RestRule::hold_back_fire_inputs(const input::InputState& input, int layer,
                                     std::map<input::InputKey, std::uint32_t>& seen) {
  const auto& readers = readers_[static_cast<std::size_t>(layer + 1)];
  std::set<input::InputKey> armed;
  for (const auto& [arm, fires] : arms_[static_cast<std::size_t>(layer + 1)]) {
    // The supervisor's consent is part of arming: a fire input held when it comes waits too.
    if (!consent() || held_.contains(arm) || at_rest(input, arm, readers.at(arm))) continue;
    armed.insert(arm);
    if (armed_.contains(arm)) continue;
    for (const auto fire : fires) {
      if (fire.is_button()) seen[fire] = input.button(fire).presses;
      hold(input, fire, at_rest(input, fire, readers.at(fire)));
    }
  }
  armed_ = std::move(armed);
}

void RestRule::rescale(const input::InputState& input, int layer) {
  for (const auto& [key, readers] : readers_[static_cast<std::size_t>(layer + 1)]) {
    const bool drives = std::any_of(readers.begin(), readers.end(),
                                    [](const Reader& r) { return r.rest == Reader::Rest::kInsideDeadzone; });
    if (drives) hold(input, key, at_rest(input, key, readers));
  }
}

void RestRule::update_consent(const input::InputState& input, int layer, bool enabled) {
  if (!consent_key_) return;
  const auto& pad = input.supervisor();
  const auto now = pad.button(*consent_key_);  // released, no presses, while it is not connected
  const bool same_pad = pad.connection() == consent_connection_;
  const auto& weapons = weapons_[static_cast<std::size_t>(layer + 1)];
  const bool meant = enabled && !weapons.empty();
  bool held_back = consent_ == ConsentState::kHeldBack;
  if (meant && (!consent_meant_ || !same_pad || input.connection() != connection_ ||
                weapons != weapons_[static_cast<std::size_t>(layer_ + 1)])) {
    // A new meaning: pressed in this very frame it counts, held since before it waits.
    const bool pressed_now = now.presses > (same_pad ? consent_presses_ : 0U);
    held_back = now.down && !pressed_now;
    consent_hold_presses_ = now.presses;
  } else if (!meant || (held_back && (!now.down || now.presses > consent_hold_presses_))) {
    held_back = false;  // nothing to consent to; or released, or released and pressed again since
  }
  consent_ = held_back ? ConsentState::kHeldBack : now.down ? ConsentState::kGiven : ConsentState::kReleased;
  consent_meant_ = meant;
  consent_presses_ = now.presses;
  consent_connection_ = pad.connection();
}

void RestRule::hold(const input::InputState& input, input::InputKey key, bool rest) {
  if (rest) held_.erase(key);
  else held_[key] = key.is_button() ? input.button(key).presses : 0;
}

// A button counts its presses (not one held when the controller appeared); a
// trigger must have been below half way at the last frame, on the same controller.
bool RestRule::pressed_this_frame(const input::InputState& input, input::InputKey arm) const {
  const bool same_pad = input.connection() == arms_connection_;
  if (!arm.is_button()) return same_pad && !arms_down_.contains(arm);
  const auto last = arm_presses_.find(arm);
  return input.button(arm).presses > (same_pad && last != arm_presses_.end() ? last->second : 0U);
}

std::vector<input::InputKey> RestRule::held_back_inputs() const {
  std::vector<input::InputKey> keys;
  for (const auto& h : held_) keys.push_back(h.first);
  return keys;
}

}  // namespace andros::mapping

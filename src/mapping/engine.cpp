#include "andros/mapping/engine.hpp"

#include <algorithm>
#include <optional>

#include "andros/mapping/axis.hpp"

namespace andros::mapping {

Engine::Engine(ValidMapping mapping, EngineOptions options)
    : mapping_(std::move(mapping)),
      options_(options),
      builder_(options.code),
      buttons_(read_inputs(*mapping_).buttons),
      c_(*mapping_) {
  set_speed(mapping_->scale.initial);
  std::size_t slots = 0;
  slot_base_.push_back(0);
  for (int layer = -1; layer < static_cast<int>(mapping_->layers.size()); ++layer) {
    effective_.push_back(effective_bindings(*mapping_, layer));
    weapons_layer_.push_back(std::any_of(effective_.back().begin(), effective_.back().end(), [this](BindingRef ref) {
      return std::holds_alternative<WeaponBinding>(binding_at(*mapping_, ref).rule);
    }));
    slots += layer < 0 ? mapping_->bindings.size() : mapping_->layers[static_cast<std::size_t>(layer)].bindings.size();
    slot_base_.push_back(slots);
  }
  all_ = all_bindings(*mapping_);
  c_.selector.assign(slots, 0);
  for (const auto ref : all_) {
    const auto& b = binding_at(*mapping_, ref);
    if (const auto* s = std::get_if<SelectorBinding>(&b.rule)) c_.selector[slot(ref)] = s->initial;
    const auto* knob = std::get_if<KnobBinding>(&b.rule);
    if (knob != nullptr && knob->initial && c_.level_milli[knob->analog] == 0) {
      c_.level_milli[knob->analog] = *knob->initial * kMilli;
    }
  }
}

const EngineStatus& Engine::status() const { return c_.status; }
const Mapping& Engine::mapping() const { return *mapping_; }

std::size_t Engine::slot(BindingRef ref) const {
  return slot_base_[static_cast<std::size_t>(ref.layer + 1)] + ref.index;
}

void Engine::clear_toggles() { c_.toggled.reset(); }

void Engine::start_session(const input::InputState& input, bool at_start_up) {
  c_.connection = input.connection();
  c_.supervisor_connection = input.supervisor().connection();
  c_.seen_presses.clear();
  c_.toggled_layer = -1;
  clear_toggles();
  // A new pad (another operator, perhaps) and a rebase begin at the initial
  // level, never at one chosen before; a deadman release keeps it.
  set_speed(mapping_->scale.initial);
  if (at_start_up) {
    // Presses made before start-up are history: they neither act nor enable.
    for (const auto key : buttons_) c_.seen_presses[key] = input.button(key).presses;
  }
}

void Engine::rebase(const input::InputState& now) {
  settled_ = false;
  neutral_.reset();
  c_.started = true;
  c_.rest.restart();  // enabled again after this is a change of meaning, however the steps before it went
  start_session(now, true);
}

// An input the rest rule holds back neither holds nor presses (the deadman and
// layer buttons are never held back).
bool Engine::held(const input::InputState& input, input::InputKey key, bool invert, double threshold) const {
  if (c_.rest.held_back(key)) return false;
  if (key.is_button()) return input.button(key).down;
  return shape_axis(normalise_axis(input.axis(key)), AxisShape{invert, 0.0, 0.0}) >= threshold;
}

std::uint32_t Engine::new_presses(const input::InputState& input, input::InputKey key) const {
  if (!key.is_button() || c_.rest.held_back(key)) return 0;
  const auto it = c_.seen_presses.find(key);
  const auto seen = it == c_.seen_presses.end() ? 0U : it->second;
  const auto now = input.button(key).presses;
  return now > seen ? now - seen : 0U;
}

void Engine::follow_sessions(const input::InputState& input, std::int64_t now_ms) {
  if (!c_.started) {
    c_.started = true;
    start_session(input, true);
    last_ms_ = now_ms;
  } else if (input.connection() != c_.connection) {
    start_session(input, false);  // a new controller session: toggles start cleared
  } else if (input.supervisor().connection() != c_.supervisor_connection) {
    // The supervisor's controller new or back: afresh, as after any stop.
    start_session(input, true);
  }
}

// A step is a function of the input, motion_allowed, the state it carries
// (c_) and the time. The time counts in one place only: a knob's ramp, whose
// level a step that changed nothing left where it was (at its end stop, or
// not ramping), as any later step from the same input leaves it. So once a
// step from an unchanged input (and a later time) has left c_ as it found
// it, each further step from that input would do the same and give the same
// frame and status: it is skipped until the input or motion_allowed change,
// or rebase() changes the state. tests/mapping/test_engine_settled.cpp and
// tests/run/test_properties.cpp hold the frames and statuses to those of
// steps computed afresh.
Step Engine::step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) {
  follow_sessions(input, now_ms);
  const bool same_input = stepped_ && motion_allowed == stepped_motion_ && input.operator_pad() == stepped_operator_ &&
                          input.supervisor() == stepped_supervisor_;
  if (same_input && settled_) {
    last_ms_ = now_ms;
    return Step{stepped_frame_, c_.status};
  }
  std::optional<Carried> before;
  if (same_input && options_.reuse_settled && now_ms > last_ms_) before = c_;
  stepped_frame_ = compute(input, now_ms, motion_allowed);
  settled_ = before && *before == c_;
  if (!same_input) {
    stepped_operator_ = input.operator_pad();
    stepped_supervisor_ = input.supervisor();
    stepped_motion_ = motion_allowed;
    stepped_ = true;
  }
  return Step{stepped_frame_, c_.status};
}

protocol::DataBytes Engine::compute(const input::InputState& input, std::int64_t now_ms, bool enabled) {
  neutral_.reset();  // levels and selectors may move
  // Nothing is latched past the deadman: a toggled layer (a weapons layer above
  // all) ends with it, as the toggles do below.
  if (!enabled) c_.toggled_layer = -1;
  update_layer(input, enabled);
  c_.status.weapons_mode = enabled && options_.weapons && weapons_layer_[static_cast<std::size_t>(c_.layer + 1)];
  c_.rest.update(input, c_.layer, enabled, c_.seen_presses);
  if (enabled) update_speed(input);
  c_.status.held_back = c_.rest.held_back_inputs();

  protocol::ControlState state = resting_state();
  c_.status.consent = c_.rest.consent_state();
  SafetyContext ctx{enabled, options_.weapons, {}, mapping_->center, mapping_->brake, c_.rest.consent()};
  c_.status.fire_refused = false;
  if (enabled) {
    for (const auto& ref : effective_[static_cast<std::size_t>(c_.layer + 1)]) {
      apply(input, ref, std::max<std::int64_t>(now_ms - last_ms_, 0), state, ctx.armed);
    }
    // A toggle stays on in every layer until pressed again or the deadman is released.
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      if (c_.toggled[i]) state.values[i] = 1;
    }
  } else {
    clear_toggles();  // releasing the deadman stops everything a toggle started
  }
  c_.status.armed = c_.status.weapons_mode && ctx.armed.any();
  c_.status.fire_refused = c_.status.fire_refused && c_.status.weapons_mode;
  // Presses made while not enabled are consumed here, never replayed later.
  for (const auto key : buttons_) c_.seen_presses[key] = input.button(key).presses;
  last_ms_ = now_ms;
  return builder_.build(apply_safety(state, ctx));
}

protocol::DataBytes Engine::neutral() const {
  if (!neutral_) {
    SafetyContext ctx;  // not enabled: drive and pivot at 128, whatever the trim
    ctx.center = mapping_->center;
    ctx.brake = mapping_->brake;
    neutral_ = builder_.build(apply_safety(resting_state(), ctx));
  }
  return *neutral_;
}

}  // namespace andros::mapping

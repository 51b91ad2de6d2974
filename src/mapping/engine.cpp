#include "andros/mapping/engine.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>

#include "andros/mapping/axis.hpp"

namespace andros::mapping {
namespace {

/// For the enable timeout an axis has changed once it has moved this far
/// (of -32768..32767) from where it was at the last change: a pad's noise
/// does not keep the bridge enabled, a hand does.
constexpr int kActivityBand = 1024;

}  // namespace

Engine::Engine(ValidMapping mapping, EngineOptions options)
    : mapping_(std::move(mapping)),
      options_(options),
      builder_(options.code),
      c_(*mapping_),
      deadman_(*mapping_),
      stops_(*mapping_) {
  const auto note_button = [this](input::InputKey key) {
    if (key.is_button() && std::find(buttons_.begin(), buttons_.end(), key) == buttons_.end()) buttons_.push_back(key);
  };
  const auto note_axis = [this](input::InputKey key) {
    if (!key.is_button() && std::find(axes_.begin(), axes_.end(), key) == axes_.end()) axes_.push_back(key);
  };
  if (mapping_->deadman) {
    note_button(mapping_->deadman->key);
    note_axis(mapping_->deadman->key);
  }
  if (mapping_->estop) note_button(mapping_->estop->key);
  for (const auto& layer : mapping_->layers) {
    note_button(layer.input.key);
    note_axis(layer.input.key);
  }
  if (mapping_->scale.up) note_button(mapping_->scale.up->key);
  if (mapping_->scale.down) note_button(mapping_->scale.down->key);
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
    for (const auto& u : b.inputs) {
      note_button(u.key);
      note_axis(u.key);
    }
    if (b.arm) {
      note_button(b.arm->key);
      note_axis(b.arm->key);
    }
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
  deadman_.start(input, at_start_up);
  c_.toggled_layer = -1;
  clear_toggles();
  c_.was_enabled = false;
  // A stop pressed in a new session counts from its connect; at start-up the presses so far are history.
  stops_.start(input, at_start_up);
  // A new pad (another operator, perhaps) and a restart begin at the initial
  // level, never at one chosen before; a deadman release keeps it.
  set_speed(mapping_->scale.initial);
  if (at_start_up) {
    // Presses made before start-up are history: they neither act nor enable.
    for (const auto key : buttons_) c_.seen_presses[key] = input.button(key).presses;
  }
}

void Engine::restart(const input::InputState& now) {
  settled_ = false;
  neutral_.reset();
  c_.started = true;
  c_.rest.restart();  // enabled again after this is a change of meaning, however the steps before it went
  start_session(now, true);
}

StopPresses Engine::take_stop(const input::InputState& input) {
  // An engine read before its first step (a reload's, at the rebase): the presses so far are history.
  if (!c_.started) {
    restart(input);
    stops_.forget(input);
  }
  settled_ = false;  // it takes presses
  return stops_.take(input);
}

StoppedTick Engine::stopped(const input::InputState& input, std::int64_t now_ms) {
  if (!c_.started) {
    restart(input);
    stops_.forget(input);
  }
  settled_ = false;  // it takes presses
  return stops_.stopped(input, deadman_.touched(input), now_ms);
}

void Engine::note_activity(const input::InputState& input, std::int64_t now_ms) {
  bool changed = false;
  for (const auto key : buttons_) {
    const auto b = input.button(key);
    auto& was = activity_buttons_[key];
    if (b.down != was.down || b.presses != was.presses) changed = true;
    was = b;
  }
  for (const auto key : axes_) {
    const int v = input.axis(key);
    auto [it, fresh] = activity_axes_.emplace(key, static_cast<std::int16_t>(v));
    if (!fresh && std::abs(v - it->second) > kActivityBand) {
      changed = true;
      it->second = static_cast<std::int16_t>(v);
    }
  }
  if (changed) last_activity_ms_ = now_ms;
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

void Engine::held_stops(const input::InputState& input, EngineStatus& status) const { stops_.held(input, status); }

void Engine::read_stops(const input::InputState& input) {
  held_stops(input, c_.status);
  c_.status.stop_pressed = stops_.take(input);
}

bool Engine::timed_out(std::int64_t now_ms) const {
  return mapping_->enable_timeout_ms && now_ms - last_activity_ms_ >= *mapping_->enable_timeout_ms;
}

void Engine::follow_sessions(const input::InputState& input, std::int64_t now_ms) {
  if (!c_.started) {
    c_.started = true;
    start_session(input, true);
    last_ms_ = now_ms;
  } else if (input.connection() != c_.connection) {
    start_session(input, false);  // a new controller session: toggles start cleared
  } else if (input.supervisor().connection() != c_.supervisor_connection) {
    // The supervisor's controller new or back: afresh, as after any stop (the
    // deadman held through it is history); a stop tapped meanwhile is still a stop.
    const auto stops = stops_;
    start_session(input, true);
    stops_ = stops;
  }
}

InputFacts Engine::facts(const input::InputState& input, std::int64_t now_ms, bool enabled) {
  follow_sessions(input, now_ms);
  c_.status.enable = deadman_.read(input);
  read_stops(input);
  note_activity(input, now_ms);
  if (enabled && c_.status.enable == EnableState::kEnabled && timed_out(now_ms)) {
    deadman_.time_out(input);
    c_.status.enable = EnableState::kTimedOut;
  }
  return InputFacts{c_.status.enable, c_.status.stop_pressed};
}

// A step is a function of the input, motion_allowed, the state it carries
// (c_) and the time. The time counts in one place only: a knob's ramp, whose
// level a step that changed nothing left where it was (at its end stop, or
// not ramping), as any later step from the same input leaves it. So once a
// step from an unchanged input (and a later time) has left c_ as it found
// it, each further step from that input would do the same and give the same
// frame and status: it is skipped until the input or motion_allowed change,
// or restart() changes the state. tests/mapping/test_engine_settled.cpp and
// tests/run/test_properties.cpp hold the frames and statuses to those of
// steps computed afresh.
protocol::DataBytes Engine::step(const input::InputState& input, std::int64_t now_ms, bool motion_allowed) {
  const bool same_input = stepped_ && motion_allowed == stepped_motion_ && input.operator_pad() == stepped_operator_ &&
                          input.supervisor() == stepped_supervisor_;
  if (same_input && settled_) {
    last_ms_ = now_ms;
    return stepped_frame_;
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
  return stepped_frame_;
}

protocol::DataBytes Engine::compute(const input::InputState& input, std::int64_t now_ms, bool enabled) {
  neutral_.reset();                                            // levels and selectors may move
  if (enabled && !c_.was_enabled) last_activity_ms_ = now_ms;  // enabling is the first change
  c_.was_enabled = enabled;
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

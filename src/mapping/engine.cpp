#include "andros/mapping/engine.hpp"

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <tuple>
#include <type_traits>

#include "andros/mapping/axis.hpp"
#include "overload.hpp"

namespace andros::mapping {
namespace {

constexpr std::int64_t kMilli = 1000;
constexpr std::int64_t kLevelMax = protocol::kWholeByteMax * kMilli;
/// For the enable timeout an axis has changed once it has moved this far
/// (of -32768..32767) from where it was at the last change: a pad's noise
/// does not keep the bridge enabled, a hand does.
constexpr int kActivityBand = 1024;

/// The values a tuple of references refers to, copied.
template <typename... T>
std::tuple<std::remove_cvref_t<T>...> copy_of(const std::tuple<T...>& refs) {
  return refs;
}

}  // namespace

std::string_view describe(EnableState state) {
  switch (state) {
    case EnableState::kEnabled: return "enabled";
    case EnableState::kNoController: return "no controller";
    case EnableState::kDeadmanReleased: return "deadman released";
    case EnableState::kDeadmanNotFresh: return "deadman held since connect or start-up: release and press it again";
    case EnableState::kPanic:
      return "deadman squeezed past its panic point: release the trigger fully, then press it again";
    case EnableState::kTimedOut: return "enable timeout (no input changed): release the deadman and press it again";
  }
  return "?";
}

Engine::Engine(ValidMapping mapping, EngineOptions options)
    : mapping_(std::move(mapping)), options_(options), builder_(options.code), rest_(*mapping_) {
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
  selector_.assign(slots, 0);
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
    if (const auto* s = std::get_if<SelectorBinding>(&b.rule)) selector_[slot(ref)] = s->initial;
    const auto* knob = std::get_if<KnobBinding>(&b.rule);
    if (knob != nullptr && knob->initial && level_milli_[knob->analog] == 0) {
      level_milli_[knob->analog] = *knob->initial * kMilli;
    }
  }
}

const EngineStatus& Engine::status() const { return status_; }
const Mapping& Engine::mapping() const { return *mapping_; }

std::size_t Engine::slot(BindingRef ref) const {
  return slot_base_[static_cast<std::size_t>(ref.layer + 1)] + ref.index;
}

void Engine::clear_toggles() { toggled_.reset(); }

void Engine::start_session(const input::InputState& input, bool at_start_up) {
  connection_ = input.connection();
  supervisor_connection_ = input.supervisor().connection();
  seen_presses_.clear();
  deadman_released_seen_ = false;
  deadman_base_ = 0;
  toggled_layer_ = -1;
  clear_toggles();
  panic_latched_ = false;
  timed_out_ = false;
  was_enabled_ = false;
  // A stop pressed in a new session counts from its connect; at start-up the presses so far are history.
  estop_seen_ = at_start_up && mapping_->estop ? input.button(mapping_->estop->key).presses : 0;
  // A new pad (another operator, perhaps) and a restart begin at the initial
  // level, never at one chosen before; a deadman release keeps it.
  set_speed(mapping_->scale.initial);
  if (at_start_up) {
    // Presses made before start-up are history: they neither act nor enable.
    for (const auto key : buttons_) seen_presses_[key] = input.button(key).presses;
    if (mapping_->deadman) deadman_base_ = input.button(mapping_->deadman->key).presses;
    // A trigger released now may be squeezed afresh.
    deadman_released_seen_ = !deadman_held(input);
  }
}

void Engine::restart(const input::InputState& now) {
  settled_ = false;
  neutral_.reset();
  started_ = true;
  rest_.restart();  // enabled again after this is a change of meaning, however the steps before it went
  start_session(now, true);
}

bool Engine::take_stop(const input::InputState& input) {
  settled_ = false;  // it takes presses
  bool stop = false;
  if (mapping_->estop && input.connected()) {
    const auto b = input.button(mapping_->estop->key);
    const auto seen = input.connection() == connection_ ? estop_seen_ : 0U;
    if (input.connection() == connection_) estop_seen_ = b.presses;
    stop = b.down || b.presses > seen;
  }
  if (mapping_->supervisor && input.supervisor().connected()) {
    // The supervisor's presses are counted per its controller's session.
    const auto& pad = input.supervisor();
    if (pad.connection() != stop_connection_) {
      stop_connection_ = pad.connection();
      stop_presses_ = 0;
    }
    const auto b = pad.button(mapping_->supervisor->stop.key);
    stop = stop || b.down || b.presses > stop_presses_;
    stop_presses_ = b.presses;
  }
  return stop;
}

bool Engine::stop_let_go(const input::InputState& input) const {
  EngineStatus held;
  held_stops(input, held);
  return input.connected() && !held.stop_held && !deadman_held(input);
}

bool Engine::panic(const input::InputState& input) {
  if (!mapping_->deadman_panic || !mapping_->deadman || mapping_->deadman->key.is_button()) return false;
  const double travel = normalise_axis(input.axis(mapping_->deadman->key));
  if (travel >= *mapping_->deadman_panic) {
    panic_latched_ = true;  // off at once; released and squeezed again to enable
    deadman_released_seen_ = false;
  } else if (panic_latched_ && travel < kDeadmanFullyReleased) {
    panic_latched_ = false;  // fully released: the next squeeze to the middle is fresh
    deadman_released_seen_ = true;
  }
  return panic_latched_;
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

void Engine::time_out(const input::InputState& input) {
  timed_out_ = true;
  // A press or squeeze that began before it is history: the next one enables.
  if (mapping_->deadman) deadman_base_ = input.button(mapping_->deadman->key).presses;
  deadman_released_seen_ = false;
}

// An input the rest rule holds back neither holds nor presses (the deadman and
// layer buttons are never held back).
bool Engine::held(const input::InputState& input, input::InputKey key, bool invert, double threshold) const {
  if (rest_.held_back(key)) return false;
  if (key.is_button()) return input.button(key).down;
  return shape_axis(normalise_axis(input.axis(key)), AxisShape{invert, 0.0, 0.0}) >= threshold;
}

std::uint32_t Engine::new_presses(const input::InputState& input, input::InputKey key) const {
  if (!key.is_button() || rest_.held_back(key)) return 0;
  const auto it = seen_presses_.find(key);
  const auto seen = it == seen_presses_.end() ? 0U : it->second;
  const auto now = input.button(key).presses;
  return now > seen ? now - seen : 0U;
}

bool Engine::deadman_held(const input::InputState& input) const {
  return mapping_->deadman && input.connected() && held(input, mapping_->deadman->key);
}

EnableState Engine::enable_state(const input::InputState& input) {
  if (!input.connected() || !mapping_->deadman) return EnableState::kNoController;
  const auto key = mapping_->deadman->key;
  const bool down = deadman_held(input);
  if (panic(input)) return EnableState::kPanic;
  if (!down) {
    deadman_released_seen_ = true;
    timed_out_ = false;
    return EnableState::kDeadmanReleased;
  }
  if (timed_out_) return EnableState::kTimedOut;
  // A button counts presses itself; a trigger must have been seen released.
  const bool fresh = key.is_button() ? input.button(key).presses > deadman_base_ : deadman_released_seen_;
  return fresh ? EnableState::kEnabled : EnableState::kDeadmanNotFresh;
}

void Engine::update_layer(const input::InputState& input, bool enabled) {
  if (enabled) {
    for (std::size_t i = 0; i < mapping_->layers.size(); ++i) {
      const auto& layer = mapping_->layers[i];
      if (!layer.toggle) continue;
      // Each press switches this layer on, or back off to the base layer.
      for (auto n = new_presses(input, layer.input.key); n > 0; --n) {
        toggled_layer_ = toggled_layer_ == static_cast<int>(i) ? -1 : static_cast<int>(i);
      }
    }
  }
  layer_ = toggled_layer_;
  for (std::size_t i = 0; i < mapping_->layers.size(); ++i) {
    const auto& layer = mapping_->layers[i];
    if (!layer.toggle && input.connected() && held(input, layer.input.key)) {
      layer_ = static_cast<int>(i);  // a held layer wins over a toggled one; the first held wins
      break;
    }
  }
  status_.layer = layer_ < 0 ? "" : mapping_->layers[static_cast<std::size_t>(layer_)].name;
}

void Engine::set_speed(std::size_t index) {
  status_.speed = {index, mapping_->scale.levels.size(), mapping_->scale.levels[index]};
}

void Engine::update_speed(const input::InputState& input) {
  const auto& scale = mapping_->scale;
  const auto count = scale.levels.size();
  auto level = status_.speed.index;
  // Up wraps from the fastest to the slowest (a wrap only ever slows); down stops at the slowest.
  if (scale.up) level = (level + new_presses(input, scale.up->key)) % count;
  if (scale.down) level -= std::min<std::size_t>(level, new_presses(input, scale.down->key));
  if (level == status_.speed.index) return;
  set_speed(level);
  // A change of level is a change of meaning: a stick off rest waits until seen at rest.
  rest_.rescale(input, layer_);
}

protocol::ControlState Engine::resting_state() const {
  protocol::ControlState s;
  s[protocol::signal_id("pivot")] = static_cast<std::uint8_t>(mapping_->center);
  s[protocol::signal_id("drive")] = static_cast<std::uint8_t>(mapping_->center);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::kSignals[i].kind == protocol::SignalKind::kLevel) {
      s.values[i] = static_cast<std::uint8_t>((level_milli_[i] + kMilli / 2) / kMilli);
    }
  }
  s[protocol::signal_id("byte12")] = mapping_->byte12;
  s[protocol::signal_id("battery")] = mapping_->battery;
  s[protocol::signal_id("code")] = options_.code;
  // Selectors keep their position whatever the layer or enable state.
  for (const auto ref : all_) {
    if (const auto* sel = std::get_if<SelectorBinding>(&binding_at(*mapping_, ref).rule)) {
      for (const auto id : sel->positions[static_cast<std::size_t>(selector_[slot(ref)])]) s[id] = 1;
    }
  }
  return s;
}

void Engine::apply(const input::InputState& input, BindingRef ref, std::int64_t dt_ms, protocol::ControlState& out,
                   std::bitset<protocol::kSignalCount>& armed) {
  const auto& binding = binding_at(*mapping_, ref);
  const auto k = slot(ref);
  // Down now, or pressed and released since the last tick: a short tap is not lost.
  const auto active = [&](input::InputKey key) { return held(input, key) || new_presses(input, key) > 0; };
  std::visit(Overload{
                 [&](const ButtonBinding& b) {
                   if (b.toggle) {
                     if (new_presses(input, b.input) % 2 == 1) toggled_.flip(b.signal);
                   } else if (b.input.is_button() ? active(b.input) : held(input, b.input, b.invert, b.threshold)) {
                     out[b.signal] = 1;
                   }
                 },
                 [&](const WeaponBinding& b) {
                   // Two people: the operator's arming input and the supervisor's consent, if asked for.
                   const bool arm = b.arm && held(input, *b.arm) && rest_.consent();
                   if (arm) armed.set(b.signal);
                   if (arm && active(b.input)) out[b.signal] = 1;
                 },
                 [&](const PairBinding& b) {
                   if (rest_.held_back(b.axis)) return;
                   const double x = shape_axis(normalise_axis(input.axis(b.axis)), AxisShape{b.invert, 0.0, 0.0});
                   if (x <= -b.threshold) out[b.signals[0]] = 1;
                   if (x >= b.threshold) out[b.signals[1]] = 1;
                 },
                 [&](const AxisBinding& b) {
                   if (rest_.held_back(b.axis)) return;  // drive/pivot stay at centre, a level keeps its value
                   const double z = shape_axis(normalise_axis(input.axis(b.axis)), b.shape);
                   if (protocol::info(b.analog).kind == protocol::SignalKind::kCentred) {
                     out[b.analog] = centred_byte(z * status_.speed.value, mapping_->center);
                   } else {
                     out[b.analog] = level_byte(z);
                     level_milli_[b.analog] = out[b.analog] * kMilli;
                   }
                 },
                 [&](const KnobBinding& b) {
                   const bool up = held(input, b.increase);
                   const bool down = held(input, b.decrease);
                   auto& v = level_milli_[b.analog];
                   if (up && !down) v += b.rate * dt_ms;
                   if (down && !up) v -= b.rate * dt_ms;
                   // A tap between two ticks nudges by one unit.
                   if (!up && !down)
                     v += (new_presses(input, b.increase) > 0 ? kMilli : 0) -
                          (new_presses(input, b.decrease) > 0 ? kMilli : 0);
                   v = std::clamp<std::int64_t>(v, 0, kLevelMax);
                   out[b.analog] = static_cast<std::uint8_t>((v + kMilli / 2) / kMilli);
                 },
                 [&](const SelectorBinding& b) {
                   const int n = static_cast<int>(b.positions.size());
                   const int steps =
                       static_cast<int>(new_presses(input, b.next) % static_cast<std::uint32_t>(n)) -
                       (b.prev ? static_cast<int>(new_presses(input, *b.prev) % static_cast<std::uint32_t>(n)) : 0);
                   auto& pos = selector_[k];
                   const auto& old_bits = b.positions[static_cast<std::size_t>(pos)];
                   for (const auto id : old_bits) out[id] = 0;
                   pos = ((pos + steps) % n + n) % n;
                   for (const auto id : b.positions[static_cast<std::size_t>(pos)]) out[id] = 1;
                 },
             },
             binding.rule);
}

void Engine::held_stops(const input::InputState& input, EngineStatus& status) const {
  status.supervisor_stop = mapping_->supervisor && input.supervisor().button(mapping_->supervisor->stop.key).down;
  status.stop_held =
      status.supervisor_stop || (mapping_->estop && input.connected() && input.button(mapping_->estop->key).down);
}

void Engine::read_stops(const input::InputState& input) {
  held_stops(input, status_);
  status_.stop_pressed = take_stop(input);
}

auto Engine::carried() const {
  return std::tie(started_, connection_, supervisor_connection_, stop_connection_, stop_presses_, seen_presses_,
                  deadman_base_, deadman_released_seen_, panic_latched_, timed_out_, was_enabled_, estop_seen_,
                  last_activity_ms_, activity_buttons_, activity_axes_, layer_, toggled_layer_, toggled_, rest_,
                  selector_, level_milli_, status_);
}

bool Engine::timeout_due(std::int64_t now_ms) const {
  return status_.enable == EnableState::kEnabled && mapping_->enable_timeout_ms &&
         now_ms - last_activity_ms_ >= *mapping_->enable_timeout_ms;
}

// A step is a function of the input, the state carried() and the time. The
// time counts in two places only: the enable timeout (timeout_due()) and a
// knob's ramp, whose level a step that changed nothing left where it was
// (at its end stop, or not ramping), as any later step from the same input
// leaves it. So once a step from an unchanged input (and a later time) has
// left every member carried() as it found it, each further step from that
// input would do the same and give the same frame and status: it is skipped
// until the input changes, the timeout falls due, or restart() or
// take_stop() change the state. tests/mapping/test_engine.cpp and
// tests/run/test_properties.cpp hold the frames and statuses to those of
// steps computed afresh.
protocol::DataBytes Engine::step(const input::InputState& input, std::int64_t now_ms) {
  const bool same_input =
      stepped_ && input.operator_pad() == stepped_operator_ && input.supervisor() == stepped_supervisor_;
  if (same_input && settled_ && !timeout_due(now_ms)) {
    last_ms_ = now_ms;
    return stepped_frame_;
  }
  using Carried = decltype(copy_of(carried()));
  std::optional<Carried> before;
  if (same_input && options_.reuse_settled && now_ms > last_ms_) before = copy_of(carried());
  stepped_frame_ = compute(input, now_ms);
  settled_ = before && *before == carried();
  if (!same_input) {
    stepped_operator_ = input.operator_pad();
    stepped_supervisor_ = input.supervisor();
    stepped_ = true;
  }
  return stepped_frame_;
}

protocol::DataBytes Engine::compute(const input::InputState& input, std::int64_t now_ms) {
  neutral_.reset();  // levels and selectors may move
  if (!started_) {
    started_ = true;
    start_session(input, true);
    last_ms_ = now_ms;
  } else if (input.connection() != connection_) {
    start_session(input, false);  // a new controller session: toggles start cleared
  } else if (input.supervisor().connection() != supervisor_connection_) {
    // The supervisor's controller new or back: afresh, as after any stop (the deadman held through it is history).
    start_session(input, true);
  }
  status_.enable = enable_state(input);
  read_stops(input);
  note_activity(input, now_ms);
  if (status_.enable == EnableState::kEnabled) {
    if (!was_enabled_) last_activity_ms_ = now_ms;  // enabling is the first change
    if (mapping_->enable_timeout_ms && now_ms - last_activity_ms_ >= *mapping_->enable_timeout_ms) {
      time_out(input);
      status_.enable = EnableState::kTimedOut;
    }
  }
  // A stop button pressed in this step: nothing acts in it (the loop latches the stop).
  const bool enabled = status_.enable == EnableState::kEnabled && !status_.stop_pressed;
  was_enabled_ = enabled;
  // Nothing is latched past the deadman: a toggled layer (a weapons layer above
  // all) ends with it, as the toggles do below.
  if (!enabled) toggled_layer_ = -1;
  update_layer(input, enabled);
  status_.weapons_mode = enabled && options_.weapons && weapons_layer_[static_cast<std::size_t>(layer_ + 1)];
  rest_.update(input, layer_, enabled, seen_presses_);
  if (enabled) update_speed(input);
  status_.held_back = rest_.held_back_inputs();

  protocol::ControlState state = resting_state();
  status_.consent = rest_.consent_state();
  SafetyContext ctx{enabled, options_.weapons, {}, mapping_->center, mapping_->brake, rest_.consent()};
  if (enabled) {
    for (const auto& ref : effective_[static_cast<std::size_t>(layer_ + 1)]) {
      apply(input, ref, std::max<std::int64_t>(now_ms - last_ms_, 0), state, ctx.armed);
    }
    // A toggle stays on in every layer until pressed again or the deadman is released.
    for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
      if (toggled_[i]) state.values[i] = 1;
    }
  } else {
    clear_toggles();  // releasing the deadman stops everything a toggle started
  }
  status_.armed = status_.weapons_mode && ctx.armed.any();
  // Presses made while not enabled are consumed here, never replayed later.
  for (const auto key : buttons_) seen_presses_[key] = input.button(key).presses;
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

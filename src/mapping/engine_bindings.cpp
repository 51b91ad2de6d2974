// The engine's bindings: the layer and speed level in force, how each
// binding rule turns the input into signals (Engine::apply), and the state
// they start from (Engine::resting_state).
#include <algorithm>

#include "andros/mapping/axis.hpp"
#include "andros/mapping/engine.hpp"
#include "overload.hpp"

namespace andros::mapping {
namespace {

constexpr std::int64_t kLevelMax = protocol::kWholeByteMax * Engine::kMilli;

}  // namespace

void Engine::update_layer(const input::InputState& input, bool enabled) {
  if (enabled) {
    for (std::size_t i = 0; i < mapping_->layers.size(); ++i) {
      const auto& layer = mapping_->layers[i];
      if (!layer.toggle) continue;
      // Each press switches this layer on, or back off to the base layer.
      for (auto n = new_presses(input, layer.input.key); n > 0; --n) {
        c_.toggled_layer = c_.toggled_layer == static_cast<int>(i) ? -1 : static_cast<int>(i);
      }
    }
  }
  c_.layer = c_.toggled_layer;
  for (std::size_t i = 0; i < mapping_->layers.size(); ++i) {
    const auto& layer = mapping_->layers[i];
    if (!layer.toggle && input.connected() && held(input, layer.input.key)) {
      c_.layer = static_cast<int>(i);  // a held layer wins over a toggled one; the first held wins
      break;
    }
  }
  c_.status.layer = c_.layer < 0 ? "" : mapping_->layers[static_cast<std::size_t>(c_.layer)].name;
}

void Engine::set_speed(std::size_t index) {
  c_.status.speed = {index, mapping_->scale.levels.size(), mapping_->scale.levels[index]};
}

void Engine::update_speed(const input::InputState& input) {
  const auto& scale = mapping_->scale;
  const auto count = scale.levels.size();
  auto level = c_.status.speed.index;
  // Up wraps from the fastest to the slowest (a wrap only ever slows); down stops at the slowest.
  if (scale.up) level = (level + new_presses(input, scale.up->key)) % count;
  if (scale.down) level -= std::min<std::size_t>(level, new_presses(input, scale.down->key));
  if (level == c_.status.speed.index) return;
  set_speed(level);
  // A change of level is a change of meaning: a stick off rest waits until seen at rest.
  c_.rest.rescale(input, c_.layer);
}

protocol::ControlState Engine::resting_state() const {
  protocol::ControlState s;
  s[protocol::signal_id("pivot")] = static_cast<std::uint8_t>(mapping_->center);
  s[protocol::signal_id("drive")] = static_cast<std::uint8_t>(mapping_->center);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::kSignals[i].kind == protocol::SignalKind::kLevel) {
      s.values[i] = static_cast<std::uint8_t>((c_.level_milli[i] + kMilli / 2) / kMilli);
    }
  }
  s[protocol::signal_id("byte12")] = mapping_->byte12;
  s[protocol::signal_id("battery")] = mapping_->battery;
  s[protocol::signal_id("code")] = options_.code;
  // Selectors keep their position whatever the layer or enable state.
  for (const auto ref : all_) {
    if (const auto* sel = std::get_if<SelectorBinding>(&binding_at(*mapping_, ref).rule)) {
      for (const auto id : sel->positions[static_cast<std::size_t>(c_.selector[slot(ref)])]) s[id] = 1;
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
                     if (new_presses(input, b.input) % 2 == 1) c_.toggled.flip(b.signal);
                   } else if (b.input.is_button() ? active(b.input) : held(input, b.input, b.invert, b.threshold)) {
                     out[b.signal] = 1;
                   }
                 },
                 [&](const WeaponBinding& b) {
                   // Two people: the operator's arming input and the supervisor's consent, if asked for.
                   const bool arm = b.arm && held(input, *b.arm) && c_.rest.consent();
                   if (arm) armed.set(b.signal);
                   if (b.arm && held(input, *b.arm) && !c_.rest.consent() && active(b.input)) {
                     c_.status.fire_refused = true;
                   }
                   if (arm && active(b.input)) out[b.signal] = 1;
                 },
                 [&](const PairBinding& b) {
                   if (c_.rest.held_back(b.axis)) return;
                   const double x = shape_axis(normalise_axis(input.axis(b.axis)), AxisShape{b.invert, 0.0, 0.0});
                   if (x <= -b.threshold) out[b.signals[0]] = 1;
                   if (x >= b.threshold) out[b.signals[1]] = 1;
                 },
                 [&](const AxisBinding& b) {
                   if (c_.rest.held_back(b.axis)) return;  // drive/pivot stay at centre, a level keeps its value
                   const double z = shape_axis(normalise_axis(input.axis(b.axis)), b.shape);
                   if (protocol::info(b.analog).kind == protocol::SignalKind::kCentred) {
                     out[b.analog] = centred_byte(z * c_.status.speed.value, mapping_->center);
                   } else {
                     out[b.analog] = level_byte(z);
                     c_.level_milli[b.analog] = out[b.analog] * kMilli;
                   }
                 },
                 [&](const KnobBinding& b) {
                   const bool up = held(input, b.increase);
                   const bool down = held(input, b.decrease);
                   auto& v = c_.level_milli[b.analog];
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
                   auto& pos = c_.selector[k];
                   const auto& old_bits = b.positions[static_cast<std::size_t>(pos)];
                   for (const auto id : old_bits) out[id] = 0;
                   pos = ((pos + steps) % n + n) % n;
                   for (const auto id : b.positions[static_cast<std::size_t>(pos)]) out[id] = 1;
                 },
             },
             binding.rule);
}

}  // namespace andros::mapping

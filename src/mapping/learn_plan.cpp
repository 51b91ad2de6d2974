#include <algorithm>

#include "andros/base/text.hpp"
#include "andros/mapping/learn.hpp"
#include "andros/protocol/words.hpp"
#include "overload.hpp"

namespace andros::mapping {
namespace {

using input::Gesture;
using input::InputKey;
using Role = LearnStep::Role;

std::string name_of(protocol::SignalId id) { return std::string(protocol::info(id).name); }

/// What a signal does, in the operator's words (protocol/words.hpp): "zoom out".
std::string words_of(protocol::SignalId id) { return std::string(protocol::words(id).words); }

/// The way an analog byte grows, as the operator says it: "drive forward", "light brighter".
std::string growing(protocol::SignalId id) {
  const auto& w = protocol::words(id);
  return std::string(w.words) + " " + std::string(w.more);
}

bool is_pad_trigger(InputKey key) {
  return key.kind == input::InputKind::kPadAxis &&
         (input::input_name(key) == "lefttrigger" || input::input_name(key) == "righttrigger");
}

Binding& binding_of(Mapping& m, const LearnStep& s) {
  return s.layer < 0 ? m.bindings.at(s.binding) : m.layers.at(static_cast<std::size_t>(s.layer)).bindings.at(s.binding);
}
const Binding& binding_of(const Mapping& m, const LearnStep& s) {
  return binding_at(m, BindingRef{s.layer, s.binding});
}

int slot_count(const Binding& b) {
  if (std::holds_alternative<WeaponBinding>(b.rule) || std::holds_alternative<KnobBinding>(b.rule)) return 2;
  if (const auto* s = std::get_if<SelectorBinding>(&b.rule)) return s->prev ? 2 : 1;
  return 1;
}

// A slot's input, with the way an axis is pushed to set the first signal
// (pair), to raise the byte (analog) or to set the signal (axis as button).
Gesture slot_value(const Mapping& m, const LearnStep& s) {
  if (s.role == Role::kDeadman) return {m.deadman->key, false};
  if (s.role == Role::kLayerKey) return {m.layers.at(static_cast<std::size_t>(s.layer)).input.key, false};
  const auto& b = binding_of(m, s);
  return std::visit(Overload{
                        [&](const ButtonBinding& r) {
                          return Gesture{r.input, !r.input.is_button() && r.invert};
                        },
                        [&](const WeaponBinding& r) {
                          return Gesture{s.slot == 0 ? r.input : *r.arm, false};
                        },
                        [&](const PairBinding& r) {
                          return Gesture{r.axis, !r.invert};
                        },
                        [&](const AxisBinding& r) {
                          return Gesture{r.axis, r.shape.invert};
                        },
                        [&](const KnobBinding& r) {
                          return Gesture{s.slot == 0 ? r.increase : r.decrease, false};
                        },
                        [&](const SelectorBinding& r) {
                          return Gesture{s.slot == 0 ? r.next : *r.prev, false};
                        },
                    },
                    b.rule);
}

void set_slot(Mapping& m, const LearnStep& s, const Gesture& g) {
  if (s.role == Role::kDeadman) {
    m.deadman->key = g.key;
    return;
  }
  if (s.role == Role::kLayerKey) {
    m.layers.at(static_cast<std::size_t>(s.layer)).input.key = g.key;
    return;
  }
  auto& b = binding_of(m, s);
  const bool arm = std::holds_alternative<WeaponBinding>(b.rule) && s.slot == 1;
  (arm ? b.arm->key : b.inputs.at(static_cast<std::size_t>(s.slot)).key) = g.key;
  std::visit(Overload{
                 [&](ButtonBinding& r) {
                   r.input = g.key;
                   r.invert = !g.key.is_button() && g.negative;
                 },
                 [&](WeaponBinding& r) { (s.slot == 0 ? r.input : *r.arm) = g.key; },
                 [&](PairBinding& r) {
                   r.axis = g.key;
                   r.invert = !g.negative;
                 },
                 [&](AxisBinding& r) {
                   r.axis = g.key;
                   r.shape.invert = g.negative;
                 },
                 [&](KnobBinding& r) { (s.slot == 0 ? r.increase : r.decrease) = g.key; },
                 [&](SelectorBinding& r) { (s.slot == 0 ? r.next : *r.prev) = g.key; },
             },
             b.rule);
}

std::string target(const Mapping& m, const LearnStep& s) {
  if (s.role == Role::kDeadman) return "the deadman";
  if (s.role == Role::kLayerKey) {
    const auto& layer = m.layers.at(static_cast<std::size_t>(s.layer));
    return "the key of layer " + quote_name(layer.name) + (layer.toggle ? " (toggle)" : " (hold)");
  }
  const auto& b = binding_of(m, s);
  return std::visit(
      Overload{
          [&](const ButtonBinding& r) { return name_of(r.signal) + (r.toggle ? " (toggle)" : ""); },
          [&](const WeaponBinding& r) { return name_of(r.signal) + (s.slot == 0 ? "" : " arming input"); },
          [&](const PairBinding& r) { return name_of(r.signals[0]) + " / " + name_of(r.signals[1]); },
          [&](const AxisBinding& r) { return name_of(r.analog); },
          [&](const KnobBinding& r) { return name_of(r.analog) + (s.slot == 0 ? " up" : " down"); },
          [&](const SelectorBinding& r) {
            return "selector " + printable_text(r.name) + (s.slot == 0 ? " next" : " prev");
          },
      },
      b.rule);
}

/// What the step's target does in the operator's words, " (front articulators
/// up)", when they say more than its name; "" otherwise.
std::string words_note(const Mapping& m, const LearnStep& s) {
  if (s.role != Role::kBinding) return {};
  const auto note =
      std::visit(Overload{
                     [&](const ButtonBinding& r) { return words_of(r.signal); },
                     [&](const WeaponBinding& r) { return s.slot == 0 ? "fire " + words_of(r.signal) : std::string(); },
                     [&](const PairBinding& r) { return words_of(r.signals[0]) + " / " + words_of(r.signals[1]); },
                     [&](const AxisBinding& r) {
                       const auto& w = protocol::words(r.analog);
                       return std::string(w.words) + " " + std::string(w.more) + "/" + std::string(w.less);
                     },
                     [&](const KnobBinding& r) {
                       const auto& w = protocol::words(r.analog);
                       return std::string(w.words) + " " + std::string(s.slot == 0 ? w.more : w.less);
                     },
                     [&](const SelectorBinding&) { return std::string(); },
                 },
                 binding_of(m, s).rule);
  return note.empty() || note == target(m, s) ? std::string() : " (" + note + ")";
}

std::string layer_name(const Mapping& m, int layer) {
  return layer < 0 ? "base layer" : "layer " + quote_name(m.layers.at(static_cast<std::size_t>(layer)).name);
}

// "lefty up", "rightx left", "lefttrigger", "axis 2 -"; a button's name.
std::string describe(const Gesture& g) {
  auto name = input::input_name(g.key);
  if (g.key.is_button()) return name;
  if (g.key.kind == input::InputKind::kJoyAxis) return "axis " + name + (g.negative ? " -" : " +");
  if (is_pad_trigger(g.key)) return g.negative ? name + " (released side)" : name;
  const bool x = name.back() == 'x';
  return name + " " + (x ? (g.negative ? "left" : "right") : (g.negative ? "up" : "down"));
}

// Who else reads key: another binding of the same layer (a weapon's arm shared
// by weapons is no clash), the deadman, a layer key; for the deadman and layer
// keys, any binding at all.
std::optional<std::string> used_by(const Mapping& m, const std::vector<LearnStep>& steps, const LearnStep& step,
                                   InputKey key) {
  const auto is_arm = [&](const LearnStep& s) {
    return s.role == Role::kBinding && s.slot == 1 && std::holds_alternative<WeaponBinding>(binding_of(m, s).rule);
  };
  for (const auto& other : steps) {
    if (other.role == step.role && other.layer == step.layer && other.binding == step.binding &&
        other.slot == step.slot)
      continue;
    if (slot_value(m, other).key != key) continue;
    if (step.role == Role::kBinding && other.role == Role::kBinding &&
        (other.layer != step.layer || (is_arm(step) && is_arm(other)))) {
      continue;
    }
    const auto name = "'" + input::input_name(key) + "' is ";
    if (other.role != Role::kBinding) return name + target(m, other);
    return name + "already used for " + target(m, other) + " in the " + layer_name(m, other.layer);
  }
  return std::nullopt;
}

}  // namespace

LearnPlan::LearnPlan(Mapping base) : base_(std::move(base)), learned_(base_) {
  if (base_.deadman) steps_.push_back({Role::kDeadman, -1, 0, 0});
  const auto add_list = [&](int layer, const std::vector<Binding>& list) {
    for (std::size_t i = 0; i < list.size(); ++i) {
      for (int slot = 0; slot < slot_count(list[i]); ++slot) steps_.push_back({Role::kBinding, layer, i, slot});
    }
  };
  add_list(-1, base_.bindings);
  for (std::size_t l = 0; l < base_.layers.size(); ++l) {
    steps_.push_back({Role::kLayerKey, static_cast<int>(l), 0, 0});
    add_list(static_cast<int>(l), base_.layers[l].bindings);
  }
}

LearnAccepts LearnPlan::accepts(std::size_t i) const {
  const auto& s = steps_.at(i);
  if (s.role == Role::kDeadman) return LearnAccepts::kButtonOrTrigger;
  if (s.role == Role::kLayerKey) return LearnAccepts::kButton;
  return std::visit(
      Overload{
          [](const ButtonBinding& r) { return r.toggle ? LearnAccepts::kButton : LearnAccepts::kButtonOrAxis; },
          [&](const WeaponBinding&) { return s.slot == 0 ? LearnAccepts::kButton : LearnAccepts::kButtonOrTrigger; },
          [](const PairBinding&) { return LearnAccepts::kAxis; },
          [](const AxisBinding&) { return LearnAccepts::kAxis; },
          [](const auto&) { return LearnAccepts::kButton; },
      },
      binding_of(learned_, s).rule);
}

std::string LearnPlan::current(std::size_t i) const { return describe(slot_value(learned_, steps_.at(i))); }

std::string LearnPlan::prompt(std::size_t i) const {
  const auto& s = steps_.at(i);
  std::string ask;
  switch (accepts(i)) {
    case LearnAccepts::kButton: ask = "press a button"; break;
    case LearnAccepts::kButtonOrTrigger: ask = "press a button or pull a trigger"; break;
    case LearnAccepts::kButtonOrAxis:
      ask = "press a button, or push a stick or trigger the way that sets it and let go";
      break;
    case LearnAccepts::kAxis: {
      const auto& rule = binding_of(learned_, s).rule;
      if (const auto* p = std::get_if<PairBinding>(&rule)) {
        ask = "push a stick the way for " + std::string(protocol::words(p->signals[0]).words) + " and let go";
      } else {
        ask = "push a stick or trigger the way for " + growing(std::get<AxisBinding>(rule).analog) + " and let go";
      }
    }
  }
  return "[" + std::to_string(i + 1) + "/" + std::to_string(steps_.size()) + "] " + layer_name(learned_, s.layer) +
         ", " + target(learned_, s) + words_note(learned_, s) + ": " + ask + " (Enter keeps " + current(i) + ")";
}

std::size_t LearnPlan::next_layer(std::size_t i) const {
  const int layer = steps_.at(i).layer;
  while (i < steps_.size() && (steps_[i].layer == layer || steps_[i].role == Role::kDeadman)) ++i;
  return i;
}

LearnResult LearnPlan::assign(std::size_t i, const Gesture& gesture) {
  const auto& s = steps_.at(i);
  const auto refuse = [](std::string why) { return LearnResult{LearnResult::Kind::kRefused, std::move(why)}; };
  Gesture g = gesture;
  if (g.key.is_button()) g.negative = false;
  const auto what = target(learned_, s);
  switch (accepts(i)) {
    case LearnAccepts::kButton:
      if (!g.key.is_button()) return refuse(what + " takes a button, not " + describe(g));
      break;
    case LearnAccepts::kButtonOrTrigger:
      if (!g.key.is_button() && (!is_pad_trigger(g.key) || g.negative)) {
        return refuse(what + " takes a button or a trigger, not " + describe(g));
      }
      break;
    case LearnAccepts::kButtonOrAxis: break;
    case LearnAccepts::kAxis:
      if (g.key.is_button()) return refuse(what + " takes a stick or trigger, not the button " + describe(g));
      if (std::holds_alternative<PairBinding>(binding_of(learned_, s).rule) && is_pad_trigger(g.key)) {
        return refuse(what + " needs a stick: a trigger moves one way only");
      }
  }
  const auto before = slot_value(learned_, s);
  if (before == g) return {LearnResult::Kind::kKept, "kept " + describe(g)};
  if (const auto clash = used_by(learned_, steps_, s, g.key)) return refuse(*clash);
  Mapping candidate = learned_;
  set_slot(candidate, s, g);
  try {
    validate(candidate, true);
  } catch (const InputError& e) {
    return refuse(e.message());
  }
  learned_ = std::move(candidate);
  return {LearnResult::Kind::kChanged, what + ": " + describe(before) + " -> " + describe(g)};
}

bool LearnPlan::changed() const {
  return std::any_of(steps_.begin(), steps_.end(),
                     [&](const LearnStep& s) { return !(slot_value(base_, s) == slot_value(learned_, s)); });
}

}  // namespace andros::mapping

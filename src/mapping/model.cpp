#include "andros/mapping/model.hpp"

#include <algorithm>

namespace andros::mapping {

std::string center_out_of_band(std::string_view value) {
  return "center " + std::string(value) + " is out of range " + std::to_string(kCenterTrimMin) + ".." +
         std::to_string(kCenterTrimMax) +
         " (it only trims drive and pivot's rest while enabled; neutral frames carry " +
         std::to_string(kDefaultCenter) + ")";
}

std::string center_effect(int center) {
  if (center == kDefaultCenter) return "";
  const auto c = std::to_string(center);
  return "center " + c + ": drive and pivot rest at " + c + " while enabled; neutral frames carry " +
         std::to_string(kDefaultCenter);
}

const Binding& binding_at(const Mapping& mapping, BindingRef ref) {
  return ref.layer < 0 ? mapping.bindings.at(ref.index)
                       : mapping.layers.at(static_cast<std::size_t>(ref.layer)).bindings.at(ref.index);
}

std::vector<BindingRef> all_bindings(const Mapping& mapping) {
  std::vector<BindingRef> refs;
  for (std::size_t i = 0; i < mapping.bindings.size(); ++i) refs.push_back({-1, i});
  for (std::size_t l = 0; l < mapping.layers.size(); ++l) {
    for (std::size_t i = 0; i < mapping.layers[l].bindings.size(); ++i) refs.push_back({static_cast<int>(l), i});
  }
  return refs;
}

ReadInputs read_inputs(const Mapping& mapping) {
  ReadInputs out;
  const auto note_button = [&out](input::InputKey key) {
    if (key.is_button() && std::find(out.buttons.begin(), out.buttons.end(), key) == out.buttons.end()) {
      out.buttons.push_back(key);
    }
  };
  const auto note = [&](input::InputKey key) {
    note_button(key);
    if (!key.is_button() && std::find(out.axes.begin(), out.axes.end(), key) == out.axes.end()) out.axes.push_back(key);
  };
  if (mapping.deadman) note(mapping.deadman->key);
  if (mapping.estop) note_button(mapping.estop->key);
  for (const auto& layer : mapping.layers) note(layer.input.key);
  if (mapping.scale.up) note_button(mapping.scale.up->key);
  if (mapping.scale.down) note_button(mapping.scale.down->key);
  for (const auto ref : all_bindings(mapping)) {
    const auto& b = binding_at(mapping, ref);
    for (const auto& u : b.inputs) note(u.key);
    if (b.arm) note(b.arm->key);
  }
  return out;
}

std::optional<protocol::SignalId> analog_target(const Binding& binding) {
  if (const auto* a = std::get_if<AxisBinding>(&binding.rule)) return a->analog;
  if (const auto* k = std::get_if<KnobBinding>(&binding.rule)) return k->analog;
  return std::nullopt;
}

bool bindings_conflict(const Binding& a, const Binding& b) {
  // An arming input shared by two weapons is no conflict; one that fires something else is.
  const auto uses = [](const Binding& x, input::InputKey key, bool with_arm) {
    return std::any_of(x.inputs.begin(), x.inputs.end(), [&](const InputUse& u) { return u.key == key; }) ||
           (with_arm && x.arm && x.arm->key == key);
  };
  for (const auto& u : a.inputs) {
    if (uses(b, u.key, true)) return true;
  }
  if (a.arm && uses(b, a.arm->key, false)) return true;
  const auto ta = analog_target(a);
  return ta && ta == analog_target(b);
}

std::vector<BindingRef> effective_bindings(const Mapping& mapping, int layer) {
  std::vector<BindingRef> refs;
  const std::vector<Binding>* own = nullptr;
  if (layer >= 0) {
    own = &mapping.layers.at(static_cast<std::size_t>(layer)).bindings;
    for (std::size_t i = 0; i < own->size(); ++i) refs.push_back({layer, i});
  }
  for (std::size_t i = 0; i < mapping.bindings.size(); ++i) {
    const auto& b = mapping.bindings[i];
    const bool replaced = own != nullptr && std::any_of(own->begin(), own->end(),
                                                        [&](const Binding& o) { return bindings_conflict(b, o); });
    if (!replaced) refs.push_back({-1, i});
  }
  return refs;
}

}  // namespace andros::mapping

// The file `learn` writes: the base it extends and only what changed.
#include <algorithm>
#include <charconv>
#include <set>

#include "andros/mapping/learn.hpp"
#include "merge.hpp"
#include "overload.hpp"

namespace andros::mapping {
namespace {

std::string name_of(protocol::SignalId id) { return std::string(protocol::info(id).name); }

// The shortest decimal that reads back as the same double (no exponent: the loader reads plain decimals).
std::string number(double value) {
  char text[64];
  const auto [end, ec] = std::to_chars(text, text + sizeof text, value, std::chars_format::fixed);
  return ec == std::errc() ? std::string(text, end) : std::to_string(value);
}

// A YAML double-quoted scalar: safe for any path or name.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') out += '\\';
    out += c;
  }
  return out + "\"";
}

std::string axis_extras(bool invert, std::optional<double> threshold) {
  std::string out;
  if (threshold && *threshold != kDefaultThreshold) out += "\nthreshold: " + number(*threshold);
  if (invert) out += "\ninvert: true";
  return out;
}

// The binding's keys, one per line, no indent.
std::string binding_lines(const Binding& b) {
  const auto in = [](input::InputKey k) { return input::input_name(k); };
  return std::visit(
      Overload{
          [&](const ButtonBinding& r) {
            const std::string head = "signal: " + name_of(r.signal);
            if (!r.input.is_button()) return head + "\naxis: " + in(r.input) + axis_extras(r.invert, r.threshold);
            return head + "\nbutton: " + in(r.input) + (r.toggle ? "\ntoggle: true" : "");
          },
          [&](const WeaponBinding& r) {
            return "signal: " + name_of(r.signal) + "\nbutton: " + in(r.input) + (r.arm ? "\narm: " + in(*r.arm) : "");
          },
          [&](const PairBinding& r) {
            return "signal: [" + name_of(r.signals[0]) + ", " + name_of(r.signals[1]) + "]\naxis: " + in(r.axis) +
                   axis_extras(r.invert, r.threshold);
          },
          [&](const AxisBinding& r) {
            return "analog: " + name_of(r.analog) + "\naxis: " + in(r.axis) + axis_extras(r.shape.invert, std::nullopt) +
                   (r.shape.deadzone != 0 ? "\ndeadzone: " + number(r.shape.deadzone) : "") +
                   (r.shape.expo != 0 ? "\nexpo: " + number(r.shape.expo) : "");
          },
          [&](const KnobBinding& r) {
            return "analog: " + name_of(r.analog) + "\nincrease: " + in(r.increase) + "\ndecrease: " + in(r.decrease) +
                   "\nrate: " + std::to_string(r.rate) + (r.initial ? "\ninitial: " + std::to_string(*r.initial) : "");
          },
          [&](const SelectorBinding& r) {
            std::string positions;
            for (const auto& p : r.positions) {
              std::string names;
              for (const auto id : p) names += (names.empty() ? "" : ", ") + name_of(id);
              positions += (positions.empty() ? "[" : ", [") + names + "]";
            }
            return "selector: " + quoted(r.name) + "\nnext: " + in(r.next) + (r.prev ? "\nprev: " + in(*r.prev) : "") +
                   "\npositions: [" + positions + "]" + (r.initial != 0 ? "\ninitial: " + std::to_string(r.initial) : "");
          },
      },
      b.rule);
}

std::string inputs_of(const Binding& b) {
  std::string out;
  for (const auto& u : b.inputs) out += (out.empty() ? "" : ", ") + input::input_name(u.key);
  if (b.arm) out += " (arm " + input::input_name(b.arm->key) + ")";
  return out;
}

// One layer's list in the extending file: the changed bindings, and an
// unbind for each old binding that no new one replaces by the loader's rule.
std::string list_yaml(const std::vector<Binding>& base, const std::vector<Binding>& learned, std::string_view indent) {
  std::set<std::size_t> emitted;
  std::vector<Binding> news;
  for (std::size_t i = 0; i < base.size(); ++i) {
    if (binding_yaml(base[i], "") != binding_yaml(learned[i], "")) emitted.insert(i);
  }
  for (const auto i : emitted) news.push_back(learned[i]);
  std::vector<Unbind> unbinds;
  for (const auto i : emitted) {
    const bool replaced = std::any_of(news.begin(), news.end(), [&](const Binding& b) { return bindings_conflict(base[i], b); });
    if (!replaced) unbinds.push_back(Unbind{input::input_name(base[i].inputs.at(0).key), {}});
  }
  // An unbind of a number drops the joystick button and axis of that number:
  // a binding it drops by the way is written again, unchanged.
  for (std::size_t i = 0; i < base.size(); ++i) {
    if (std::any_of(unbinds.begin(), unbinds.end(), [&](const Unbind& u) { return unbind_matches(u, base[i]); })) {
      emitted.insert(i);
    }
  }
  std::string out;
  for (const auto& u : unbinds) out += std::string(indent) + "- unbind: " + u.name + "\n";
  for (const auto i : emitted) {
    auto item = binding_yaml(learned[i], indent);
    const auto eol = item.find('\n');
    const bool same = binding_yaml(base[i], "") == binding_yaml(learned[i], "");
    item.insert(eol, same ? "    # unchanged" : "    # was " + inputs_of(base[i]));
    out += item;
  }
  return out;
}

std::string was(const std::string& before, const std::string& now) {
  return before == now ? "" : "    # was " + before;
}

}  // namespace

std::string binding_yaml(const Binding& binding, std::string_view indent) {
  std::string out;
  std::string_view lead = "- ";
  const auto lines = binding_lines(binding);
  std::size_t start = 0;
  while (start <= lines.size()) {
    auto end = lines.find('\n', start);
    if (end == std::string::npos) end = lines.size();
    out += std::string(indent) + std::string(lead) + lines.substr(start, end - start) + "\n";
    lead = "  ";
    start = end + 1;
  }
  return out;
}

std::string LearnPlan::extending_yaml(std::string_view extends) const {
  std::string out = "# Written by andros-bridge learn: only what changed from the mapping it extends.\n";
  out += "robot: " + learned_.robot.value_or("") + "\n";
  out += "extends: " + quoted(extends) + "\n";
  if (learned_.deadman && base_.deadman) {
    const auto before = input::input_name(base_.deadman->key);
    const auto now = input::input_name(learned_.deadman->key);
    if (before != now) out += "deadman: " + now + was(before, now) + "\n";
  }
  const auto base_list = list_yaml(base_.bindings, learned_.bindings, "  ");
  if (!base_list.empty()) out += "bindings:\n" + base_list;
  std::string layers;
  for (std::size_t l = 0; l < learned_.layers.size(); ++l) {
    const auto& before = base_.layers[l];
    const auto& now = learned_.layers[l];
    const auto list = list_yaml(before.bindings, now.bindings, "      ");
    const auto key_before = input::input_name(before.input.key);
    const auto key_now = input::input_name(now.input.key);
    if (list.empty() && key_before == key_now) continue;
    layers += "  " + quoted(now.name) + ":\n    " + (now.toggle ? "toggle: " : "hold: ") + key_now + was(key_before, key_now) + "\n";
    layers += list.empty() ? "    bindings: []\n" : "    bindings:\n" + list;
  }
  if (!layers.empty()) out += "layers:\n" + layers;
  return out;
}

bool LearnPlan::matches(const Mapping& loaded) const {
  const auto list_text = [](const std::vector<Binding>& list) {
    std::multiset<std::string> out;
    for (const auto& b : list) out.insert(binding_yaml(b, ""));
    return out;
  };
  if (!loaded.deadman || !learned_.deadman || loaded.deadman->key != learned_.deadman->key) return false;
  if (list_text(loaded.bindings) != list_text(learned_.bindings)) return false;
  if (loaded.layers.size() != learned_.layers.size()) return false;
  for (std::size_t l = 0; l < loaded.layers.size(); ++l) {
    const auto& a = loaded.layers[l];
    const auto& b = learned_.layers[l];
    if (a.name != b.name || a.toggle != b.toggle || a.input.key != b.input.key) return false;
    if (list_text(a.bindings) != list_text(b.bindings)) return false;
  }
  return loaded.center == learned_.center && loaded.brake == learned_.brake && loaded.robot == learned_.robot;
}

}  // namespace andros::mapping

// The file `learn` writes: the base it extends and only what changed.
#include <algorithm>
#include <charconv>
#include <set>

#include "andros/base/text.hpp"
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

// A YAML double-quoted scalar that reads back as the same bytes, whatever a
// name or path holds: a quote and a backslash escaped, a control character (a
// newline in a layer's name, ESC, DEL, a C1 control) as \xNN or \u00NN, which
// YAML may not hold raw; the rest as it is.
std::string quoted(std::string_view text) {
  std::string out = "\"";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    const auto next = i + 1 < text.size() ? static_cast<unsigned char>(text[i + 1]) : 0U;
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7F) {
      out += "\\x" + hex_byte(c);
    } else if (c == 0xC2 && next >= 0x80 && next <= 0x9F) {
      out += "\\u00" + hex_byte(static_cast<std::uint8_t>(next));
      ++i;
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

// The binding's first line ("signal: front_art_up", "analog: drive"): what it does.
std::string what_of(const Binding& b) {
  const auto text = binding_yaml(b, "");
  return text.substr(0, text.find('\n'));
}

bool same_target(const Binding& a, const Binding& b) { return what_of(a) == what_of(b); }

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
            return "analog: " + name_of(r.analog) + "\naxis: " + in(r.axis) +
                   axis_extras(r.shape.invert, std::nullopt) +
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
                   "\npositions: [" + positions + "]" +
                   (r.initial != 0 ? "\ninitial: " + std::to_string(r.initial) : "");
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

// One layer's list in the extending file: what makes base's list the
// learned one under the loader's rule (merge_bindings). The two are compared
// as sets of bindings, not by position: base may be another file than the one
// learned from (learn writing over its own output extends what that extended).
// A binding not in learned is replaced by a new one it conflicts with, or
// dropped by an unbind of its input; a kept binding that a new binding or an
// unbind would drop by the way is written again, unchanged.
std::string list_yaml(const std::vector<Binding>& base, const std::vector<Binding>& learned, std::string_view indent) {
  const auto text = [](const Binding& b) { return binding_yaml(b, ""); };
  std::multiset<std::string> base_texts;
  std::multiset<std::string> learned_texts;
  for (const auto& b : base) base_texts.insert(text(b));
  for (const auto& b : learned) learned_texts.insert(text(b));
  const auto take = [&](std::multiset<std::string>& set, const std::string& t) {
    const auto it = set.find(t);
    if (it == set.end()) return false;
    set.erase(it);
    return true;
  };
  std::vector<bool> emit(learned.size(), false);  // new, or written again
  std::vector<bool> kept(base.size(), false);     // base bindings learned has unchanged
  {
    auto remaining = base_texts;
    for (std::size_t i = 0; i < learned.size(); ++i) emit[i] = !take(remaining, text(learned[i]));
    auto unmatched = learned_texts;
    for (std::size_t i = 0; i < base.size(); ++i) kept[i] = take(unmatched, text(base[i]));
  }
  std::vector<Unbind> unbinds;
  const auto emitted_conflict = [&](const Binding& old) {
    for (std::size_t i = 0; i < learned.size(); ++i) {
      if (emit[i] && bindings_conflict(old, learned[i])) return true;
    }
    return false;
  };
  for (std::size_t i = 0; i < base.size(); ++i) {
    if (kept[i] || emitted_conflict(base[i])) continue;
    const auto name = input::input_name(base[i].inputs.at(0).key);
    if (std::none_of(unbinds.begin(), unbinds.end(), [&](const Unbind& u) { return u.name == name; })) {
      unbinds.push_back(Unbind{name, {}});
    }
  }
  // A kept binding dropped by an unbind or a written binding is written again,
  // which may drop another: until nothing changes.
  for (bool again = true; again;) {
    again = false;
    for (std::size_t i = 0; i < base.size(); ++i) {
      if (!kept[i]) continue;
      const bool dropped =
          emitted_conflict(base[i]) ||
          std::any_of(unbinds.begin(), unbinds.end(), [&](const Unbind& u) { return unbind_matches(u, base[i]); });
      if (!dropped) continue;
      for (std::size_t j = 0; j < learned.size(); ++j) {
        if (!emit[j] && text(learned[j]) == text(base[i])) {
          emit[j] = true;
          again = true;
          break;
        }
      }
    }
  }
  std::string out;
  for (const auto& u : unbinds) out += std::string(indent) + "- unbind: " + u.name + "\n";
  for (std::size_t i = 0; i < learned.size(); ++i) {
    if (!emit[i]) continue;
    auto item = binding_yaml(learned[i], indent);
    const auto eol = item.find('\n');
    std::string note = "    # new";
    if (base_texts.count(text(learned[i])) > 0) note = "    # unchanged";
    for (std::size_t j = 0; j < base.size() && note == "    # new"; ++j) {
      if (!kept[j] && same_target(base[j], learned[i])) note = "    # was " + inputs_of(base[j]);
    }
    item.insert(eol, note);
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

std::string LearnPlan::extending_yaml(std::string_view extends) const { return extending_yaml(extends, base_); }

std::string LearnPlan::extending_yaml(std::string_view extends, const Mapping& over) const {
  std::string out = "# Written by andros-bridge learn: only what changed from the mapping it extends.\n";
  out += "robot: " + learned_.robot.value_or("") + "\n";
  out += "extends: " + quoted(extends) + "\n";
  if (learned_.center != over.center) out += "center: " + std::to_string(learned_.center) + "\n";
  if (learned_.brake != over.brake)
    out += std::string("brake: ") + (learned_.brake == BrakeMode::kMoving ? "moving" : "enabled") + "\n";
  if (learned_.deadman && over.deadman) {
    const auto before = input::input_name(over.deadman->key);
    const auto now = input::input_name(learned_.deadman->key);
    if (before != now) out += "deadman: " + now + was(before, now) + "\n";
  }
  const auto base_list = list_yaml(over.bindings, learned_.bindings, "  ");
  if (!base_list.empty()) out += "bindings:\n" + base_list;
  std::string layers;
  for (const auto& now : learned_.layers) {
    const auto it =
        std::find_if(over.layers.begin(), over.layers.end(), [&](const Layer& l) { return l.name == now.name; });
    static const std::vector<Binding> kNone;
    const auto& before_list = it == over.layers.end() ? kNone : it->bindings;
    const auto list = list_yaml(before_list, now.bindings, "      ");
    const auto key_now = input::input_name(now.input.key);
    const auto key_before = it == over.layers.end() ? std::string() : input::input_name(it->input.key);
    const bool same_kind = it != over.layers.end() && it->toggle == now.toggle;
    if (list.empty() && key_before == key_now && same_kind) continue;
    layers += "  " + quoted(now.name) + ":\n    " + (now.toggle ? "toggle: " : "hold: ") + key_now +
              (key_before.empty() ? "" : was(key_before, key_now)) + "\n";
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

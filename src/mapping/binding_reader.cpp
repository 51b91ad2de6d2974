#include "binding_reader.hpp"

#include <algorithm>
#include <set>
#include <string>

#include "andros/base/text.hpp"
#include "merge.hpp"

namespace andros::mapping {
namespace {

using yaml::Reader;

void read_axis_extras(const Reader& r, const YAML::Node& n, bool& invert, double* threshold) {
  if (n["invert"]) invert = r.boolean(n["invert"], "invert");
  if (threshold != nullptr && n["threshold"]) *threshold = r.number(n["threshold"], 0.0, 1.0, false, "threshold");
  if (threshold != nullptr && *threshold <= 0.0) r.fail(n["threshold"], "threshold must be above 0");
}

Binding read_signal_binding(const Reader& r, const YAML::Node& n, Binding b) {
  const auto target = n["signal"];
  if (target.IsSequence()) {
    r.expect_keys(n, {"signal", "axis", "threshold", "invert"}, "an axis-to-pair binding");
    if (target.size() != 2) r.fail(target, "an opposing pair is a list of two signals");
    if (!n["axis"]) r.fail(n, "an opposing pair needs 'axis'");
    PairBinding p;
    p.signals = {r.signal(target[0]), r.signal(target[1])};
    p.axis = r.axis(n["axis"]);
    read_axis_extras(r, n, p.invert, &p.threshold);
    b.inputs.push_back(input_use(r, n["axis"], p.axis));
    b.rule = p;
    return b;
  }
  const protocol::SignalId id = r.signal(target);
  if (n["arm"] || protocol::info(id).kind == protocol::SignalKind::kWeapon) {
    r.expect_keys(n, {"signal", "button", "arm"}, "a weapon binding");
    if (!n["button"]) r.fail(n, "a weapon binding needs 'button' (and 'arm')");
    WeaponBinding w{id, r.button(n["button"]), std::nullopt};
    b.inputs.push_back(input_use(r, n["button"], w.input));
    if (n["arm"]) {
      w.arm = r.button_or_trigger(n["arm"], "arm");
      b.arm = input_use(r, n["arm"], *w.arm);
    }
    b.rule = w;
    return b;
  }
  ButtonBinding m;
  m.signal = id;
  if (n["axis"]) {
    r.expect_keys(n, {"signal", "axis", "threshold", "invert"}, "an axis-as-button binding");
    m.input = r.axis(n["axis"]);
    read_axis_extras(r, n, m.invert, &m.threshold);
    b.inputs.push_back(input_use(r, n["axis"], m.input));
  } else {
    r.expect_keys(n, {"signal", "button", "toggle"}, "a button binding");
    if (!n["button"]) r.fail(n, "a signal binding needs 'button' or 'axis'");
    m.input = r.button(n["button"]);
    b.inputs.push_back(input_use(r, n["button"], m.input));
    if (n["toggle"]) m.toggle = r.boolean(n["toggle"], "toggle");
  }
  b.rule = m;
  return b;
}

Binding read_analog_binding(const Reader& r, const YAML::Node& n, Binding b) {
  const protocol::SignalId id = r.signal(n["analog"]);
  if (n["increase"] || n["decrease"]) {
    r.expect_keys(n, {"analog", "increase", "decrease", "rate", "initial"}, "a knob binding");
    for (const char* key : {"increase", "decrease", "rate"}) {
      if (!n[key]) r.fail(n, std::string("a knob binding needs '") + key + "'");
    }
    KnobBinding k;
    k.analog = id;
    k.increase = r.button(n["increase"]);
    k.decrease = r.button(n["decrease"]);
    k.rate = static_cast<int>(r.integer(n["rate"], 1, kMaxKnobRate, "rate (units per second)"));
    if (n["initial"]) k.initial = static_cast<int>(r.integer(n["initial"], 0, protocol::kWholeByteMax, "initial"));
    b.inputs.push_back(input_use(r, n["increase"], k.increase));
    b.inputs.push_back(input_use(r, n["decrease"], k.decrease));
    b.rule = k;
    return b;
  }
  r.expect_keys(n, {"analog", "axis", "invert", "deadzone", "expo"}, "an analog binding");
  if (!n["axis"]) r.fail(n, "an analog binding needs 'axis' (or 'increase' and 'decrease' for a knob)");
  AxisBinding a;
  a.analog = id;
  a.axis = r.axis(n["axis"]);
  read_axis_extras(r, n, a.shape.invert, nullptr);
  if (n["deadzone"]) a.shape.deadzone = r.number(n["deadzone"], 0.0, 1.0, true, "deadzone");
  if (n["expo"]) a.shape.expo = r.number(n["expo"], 0.0, 1.0, false, "expo");
  b.inputs.push_back(input_use(r, n["axis"], a.axis));
  b.rule = a;
  return b;
}

Binding read_selector_binding(const Reader& r, const YAML::Node& n, Binding b) {
  r.expect_keys(n, {"selector", "next", "prev", "positions", "initial"}, "a selector binding");
  for (const char* key : {"next", "positions"}) {
    if (!n[key]) r.fail(n, std::string("a selector binding needs '") + key + "'");
  }
  SelectorBinding s;
  s.name = r.text(n["selector"], "selector name");
  s.next = r.button(n["next"]);
  b.inputs.push_back(input_use(r, n["next"], s.next));
  if (n["prev"]) {
    s.prev = r.button(n["prev"]);
    b.inputs.push_back(input_use(r, n["prev"], *s.prev));
  }
  const auto positions = n["positions"];
  r.expect_list(positions, "positions");
  if (positions.size() < 2) r.fail(positions, "a selector needs at least two positions");
  for (const auto& p : positions) {
    r.expect_list(p, "a position (a list of the signals it sets, [] for none)");
    std::vector<protocol::SignalId> bits;
    for (const auto& sig : p) {
      const protocol::SignalId id = r.signal(sig);
      if (std::find(bits.begin(), bits.end(), id) != bits.end()) {
        r.fail(sig, "'" + std::string(protocol::info(id).name) + "' is given twice in this position");
      }
      bits.push_back(id);
    }
    s.positions.push_back(std::move(bits));
  }
  b.target_pos = r.pos(positions);
  if (n["initial"]) {
    s.initial = static_cast<int>(
        r.integer(n["initial"], 0, static_cast<long long>(s.positions.size()) - 1, "initial position"));
  }
  b.rule = s;
  return b;
}

Binding read_binding(const Reader& r, const YAML::Node& n) {
  r.expect_map(n, "a binding");
  Binding b;
  b.pos = r.pos(n);
  const int kinds = (n["signal"] ? 1 : 0) + (n["analog"] ? 1 : 0) + (n["selector"] ? 1 : 0);
  if (kinds != 1) r.fail(n, "a binding names exactly one of 'signal', 'analog' or 'selector'");
  if (n["signal"]) {
    b.target_pos = r.pos(n["signal"]);
    return read_signal_binding(r, n, b);
  }
  if (n["analog"]) {
    b.target_pos = r.pos(n["analog"]);
    return read_analog_binding(r, n, b);
  }
  return read_selector_binding(r, n, b);
}

/// A list of bindings, and the `unbind:` items that drop bindings of the file it extends.
struct BindingList {
  std::vector<Binding> bindings;
  std::vector<Unbind> unbinds;
};

/// A bad item is added to errors and left out; reading goes on with the next.
BindingList read_list(const Reader& r, const YAML::Node& list, ErrorList& errors) {
  r.expect_list(list, "bindings");
  BindingList out;
  for (const auto& n : list) {
    errors.attempt([&] {
      if (n.IsMap() && n["unbind"]) out.unbinds.push_back(read_unbind(r, n));
      else out.bindings.push_back(read_binding(r, n));
    });
  }
  return out;
}

Layer read_layer(const Reader& r, const YAML::Node& name, const YAML::Node& n, BindingList& list, ErrorList& errors) {
  r.expect_keys(n, {"hold", "toggle", "bindings"}, "a layer");
  Layer layer;
  layer.name = r.text(name, "layer name");
  layer.pos = r.pos(name);
  if ((n["hold"] ? 1 : 0) + (n["toggle"] ? 1 : 0) != 1) {
    r.fail(n, "layer " + quote(layer.name) + " needs exactly one of 'hold: BUTTON' or 'toggle: BUTTON'");
  }
  layer.toggle = static_cast<bool>(n["toggle"]);
  const auto button = layer.toggle ? n["toggle"] : n["hold"];
  layer.input = input_use(r, button, r.button(button));
  if (!n["bindings"]) r.fail(n, "layer " + quote(layer.name) + " needs 'bindings'");
  list = read_list(r, n["bindings"], errors);
  return layer;
}

}  // namespace

InputUse input_use(const Reader& r, const YAML::Node& node, input::InputKey key) { return InputUse{key, r.pos(node)}; }

void read_bindings(const Reader& r, const YAML::Node& list, std::vector<Binding>& base, ErrorList& errors) {
  auto read = read_list(r, list, errors);
  merge_bindings(base, std::move(read.bindings), read.unbinds);
}

void read_layers(const Reader& r, const YAML::Node& layers, std::vector<Layer>& base, ErrorList& errors) {
  r.expect_map(layers, "layers");
  std::set<std::string> seen;
  for (const auto& kv : layers) {
    errors.attempt([&] {
      BindingList list;
      auto layer = read_layer(r, kv.first, kv.second, list, errors);
      check_layer_name(seen, layer);  // within this file; a base's layer of the same name is merged below
      const auto it = std::find_if(base.begin(), base.end(), [&](const Layer& l) { return l.name == layer.name; });
      if (it == base.end()) {
        merge_bindings(layer.bindings, std::move(list.bindings), list.unbinds);
        base.push_back(std::move(layer));
      } else {
        merge_bindings(it->bindings, std::move(list.bindings), list.unbinds);
        it->input = layer.input;
        it->toggle = layer.toggle;
        it->pos = layer.pos;
      }
    });
  }
}

}  // namespace andros::mapping

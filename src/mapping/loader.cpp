#include "andros/mapping/loader.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <set>

#include "andros/base/error_list.hpp"
#include "andros/base/text.hpp"
#include "andros/protocol/robots.hpp"
#include "feedback_reader.hpp"
#include "merge.hpp"
#include "yaml_reader.hpp"

namespace andros::mapping {
namespace {

namespace fs = std::filesystem;
using yaml::Reader;

/// The most files in an `extends` chain (the one loaded and its bases). Each
/// is read by a nested call, so the bound also bounds the stack.
constexpr std::size_t kMaxExtendsChain = 16;

/// A trim of drive and pivot's rest while enabled, within the band of model.hpp.
int read_center(const Reader& r, const YAML::Node& node) {
  const auto value =
      r.integer(node, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max(), "center");
  if (value < kCenterTrimMin || value > kCenterTrimMax) r.fail(node, center_out_of_band(r.text(node, "center")));
  return static_cast<int>(value);
}

InputUse use(const Reader& r, const YAML::Node& node, input::InputKey key) { return InputUse{key, r.pos(node)}; }

/// `scale: {button: B, down: B, levels: [...], initial: L}` (docs/mapping.md, `scale`).
SpeedScale read_scale(const Reader& r, const YAML::Node& n) {
  r.expect_keys(n, {"button", "down", "levels", "initial"}, "scale");
  if (!n["levels"]) r.fail(n, "scale needs 'levels': a list of fractions of full speed, such as [0.25, 0.5, 1.0]");
  SpeedScale s;
  s.pos = r.pos(n);
  const auto levels = n["levels"];
  r.expect_list(levels, "levels");
  if (levels.size() == 0) r.fail(levels, "levels lists at least one fraction of full speed");
  if (levels.size() > kMaxSpeedLevels) {
    r.fail(levels,
           "at most " + std::to_string(kMaxSpeedLevels) + " levels (a change is counted out in as many rumble pulses)");
  }
  s.levels.clear();
  for (const auto& l : levels) {
    const double v = r.number(l, 0.0, 1.0, false, "a level");
    if (v <= 0.0) r.fail(l, "a level is a fraction of full speed above 0, not " + r.text(l, "a level"));
    if (!s.levels.empty() && v <= s.levels.back()) {
      r.fail(l,
             "levels go from the slowest to the fastest: " + r.text(l, "a level") + " is not above the one before it");
    }
    s.levels.push_back(v);
  }
  if (n["button"]) s.up = use(r, n["button"], r.button(n["button"]));
  if (n["down"]) {
    if (!s.up) r.fail(n, "scale has 'down' but no 'button' to step up");
    s.down = use(r, n["down"], r.button(n["down"]));
  }
  if (s.levels.size() > 1 && !s.up)
    r.fail(n, "scale with more than one level needs 'button': the button that steps through them");
  if (s.levels.size() == 1 && s.up)
    r.fail(n["button"], "scale has one level: there is nothing for 'button' to step to");
  if (const auto i = n["initial"]) {
    const double v = r.number(i, 0.0, 1.0, false, "initial");
    const auto it = std::find(s.levels.begin(), s.levels.end(), v);
    if (it == s.levels.end()) r.fail(i, "initial " + r.text(i, "initial") + " is not one of the levels");
    s.initial = static_cast<std::size_t>(it - s.levels.begin());
  }
  return s;
}

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
    b.inputs.push_back(use(r, n["axis"], p.axis));
    b.rule = p;
    return b;
  }
  const protocol::SignalId id = r.signal(target);
  if (n["arm"] || protocol::info(id).kind == protocol::SignalKind::kWeapon) {
    r.expect_keys(n, {"signal", "button", "arm"}, "a weapon binding");
    if (!n["button"]) r.fail(n, "a weapon binding needs 'button' (and 'arm')");
    WeaponBinding w{id, r.button(n["button"]), std::nullopt};
    b.inputs.push_back(use(r, n["button"], w.input));
    if (n["arm"]) {
      w.arm = r.button_or_trigger(n["arm"], "arm");
      b.arm = use(r, n["arm"], *w.arm);
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
    b.inputs.push_back(use(r, n["axis"], m.input));
  } else {
    r.expect_keys(n, {"signal", "button", "toggle"}, "a button binding");
    if (!n["button"]) r.fail(n, "a signal binding needs 'button' or 'axis'");
    m.input = r.button(n["button"]);
    b.inputs.push_back(use(r, n["button"], m.input));
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
    b.inputs.push_back(use(r, n["increase"], k.increase));
    b.inputs.push_back(use(r, n["decrease"], k.decrease));
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
  b.inputs.push_back(use(r, n["axis"], a.axis));
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
  b.inputs.push_back(use(r, n["next"], s.next));
  if (n["prev"]) {
    s.prev = r.button(n["prev"]);
    b.inputs.push_back(use(r, n["prev"], *s.prev));
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
BindingList read_bindings(const Reader& r, const YAML::Node& list, ErrorList& errors) {
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
  layer.input = use(r, button, r.button(button));
  if (!n["bindings"]) r.fail(n, "layer " + quote(layer.name) + " needs 'bindings'");
  list = read_bindings(r, n["bindings"], errors);
  return layer;
}

SupervisorButtons read_supervisor(const Reader& r, const YAML::Node& n) {
  r.expect_map(n, "the supervisor section");
  r.expect_keys(n, {"stop", "weapons_consent"}, "the supervisor section");
  if (!n["stop"]) r.fail(n, "the supervisor section needs 'stop: BUTTON': the supervisor's stop button");
  SupervisorButtons s;
  s.pos = r.pos(n);
  s.stop = use(r, n["stop"], r.button(n["stop"]));
  if (n["weapons_consent"]) s.weapons_consent = use(r, n["weapons_consent"], r.button(n["weapons_consent"]));
  return s;
}

/// The files being read, outermost first, the YAML nodes they may still
/// hold, and the errors found so far in any of them.
struct Chain {
  std::vector<fs::path> files;
  std::size_t node_budget = yaml::kMaxNodes;
  ErrorList errors;
  /// A recorded chain (load_recorded_chain): `extends` takes the next of these, never a file.
  const std::vector<MappingText>* recorded = nullptr;
};

/// Why a mapping file cannot be read, from stat(): missing, not permitted, or
/// not a regular file (a FIFO is never opened: that would wait for a writer).
/// Empty for a regular file.
std::string unreadable(const fs::path& file) {
  struct stat st {};
  if (::stat(file.c_str(), &st) != 0) return std::strerror(errno);
  if (S_ISREG(st.st_mode)) return {};
  if (S_ISDIR(st.st_mode)) return "it is a directory";
  if (S_ISFIFO(st.st_mode)) return "it is a FIFO (a named pipe), not a regular file";
  if (S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode)) return "it is a device, not a regular file";
  if (S_ISSOCK(st.st_mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

Mapping read_file(const fs::path& file, Chain& chain, const SourcePos& from, const std::string* text = nullptr);

/// `extends: ROBOT` (a robot's name, no folder): that robot's mapping as
/// `--robot` finds it, passing over the files of this chain, so that
/// ~/.config/andros-bridge/mappings/hd1.yaml may extend the shipped hd1.yaml.
fs::path robot_base(const Reader& r, const YAML::Node& node, std::string_view robot, const Chain& chain) {
  const auto file = to_lower(*protocol::canonical_robot(robot)) + ".yaml";
  std::string looked;
  for (const auto& dir : mapping_search_path()) {
    std::error_code ec;
    auto candidate = dir / file;
    if (!fs::is_regular_file(candidate, ec)) continue;
    if (std::find(chain.files.begin(), chain.files.end(), fs::weakly_canonical(candidate, ec)) != chain.files.end())
      continue;
    return candidate;
  }
  for (const auto& dir : mapping_search_path()) looked += (looked.empty() ? "" : ", ") + dir.string();
  r.fail(node, "'extends: " + std::string(robot) + "': no " + file +
                   " other than this file on the mapping search path (" + looked + ")");
}

/// The recorded file after the one being read, when its name is the one `extends` gives.
Mapping read_recorded_base(const Reader& r, const YAML::Node& node, const std::string& name, Chain& chain) {
  const auto& files = *chain.recorded;
  const std::size_t next = chain.files.size();
  const auto wanted = fs::path(name).filename();
  if (next >= files.size() || fs::path(files[next].label).filename() != wanted) {
    r.fail(node, "'extends: " + name + "': the session recorded no " + quote_name(wanted.string()) +
                     " next in the mapping's chain");
  }
  return read_file(files[next].label, chain, r.pos(node), &files[next].text);
}

void apply_extends(const Reader& r, const YAML::Node& node, const fs::path& file, Chain& chain, Mapping& out) {
  if (chain.files.size() >= kMaxExtendsChain) {
    r.fail(node, "'extends' chain too long: this base would be file " + std::to_string(chain.files.size() + 1) +
                     " of the chain from '" + chain.files.front().filename().string() + "' (at most " +
                     std::to_string(kMaxExtendsChain) + " files)");
  }
  const auto name = r.text(node, "extends");
  const bool robot = name.find('/') == std::string::npos && protocol::canonical_robot(name).has_value();
  if (chain.recorded != nullptr) {
    out = read_recorded_base(r, node, robot ? to_lower(*protocol::canonical_robot(name)) + ".yaml" : name, chain);
    out.robot.reset();
    return;
  }
  const auto base_path = robot ? robot_base(r, node, name, chain) : file.parent_path() / name;
  // The base's values stand unless this file sets them; its robot does not carry over.
  out = read_file(base_path, chain, r.pos(node));
  out.robot.reset();
}

Mapping read_file(const fs::path& file, Chain& chain, const SourcePos& from, const std::string* text) {
  std::error_code ec;
  // A recorded chain's path is a label: never looked at on this machine.
  const auto canonical = chain.recorded != nullptr ? file : fs::weakly_canonical(file, ec);
  if (text == nullptr) {
    if (const auto why = unreadable(file); !why.empty()) {
      throw InputError(from.file.empty() ? SourcePos{file.string()} : from,
                       "cannot open mapping file " + quote_name(file.string()) + ": " + why);
    }
  }
  if (std::find(chain.files.begin(), chain.files.end(), canonical) != chain.files.end()) {
    std::string loop;
    for (const auto& f : chain.files) loop += f.filename().string() + " -> ";
    throw InputError(from, "'extends' makes a cycle: " + loop + canonical.filename().string());
  }
  chain.files.push_back(canonical);
  const Reader r(file.string(), text);
  const YAML::Node root = r.load_document(chain.node_budget);
  r.expect_keys(root,
                {"robot", "extends", "center", "constants", "deadman", "deadman_panic", "estop", "stop_reset_hold",
                 "enable_timeout", "supervisor", "brake", "scale", "feedback", "bindings", "layers"},
                "a mapping file");
  Mapping m;
  if (root["extends"]) apply_extends(r, root["extends"], file, chain, m);
  m.file = file.string();
  m.chain.insert(m.chain.begin(), canonical.string());
  // Each key and each binding on its own: an error in one is collected and the
  // rest is still read, so that every error is reported at once.
  auto& errors = chain.errors;
  if (root["robot"]) {
    errors.attempt([&] {
      const auto name = r.text(root["robot"], "robot");
      m.robot = protocol::canonical_robot(name);
      if (!m.robot)
        r.fail(root["robot"], "unknown robot " + quote(name) + " (expected " + protocol::robot_list() + ")");
      m.robot_pos = r.pos(root["robot"]);
    });
  }
  if (const auto c = root["center"]) errors.attempt([&] { m.center = read_center(r, c); });
  if (const auto c = root["constants"]) {
    errors.attempt([&] {
      r.expect_keys(c, {"byte12", "battery"}, "constants");
      if (c["byte12"])
        m.byte12 = static_cast<std::uint8_t>(r.integer(c["byte12"], 0, protocol::kWholeByteMax, "byte12"));
      if (c["battery"])
        m.battery = static_cast<std::uint8_t>(r.integer(c["battery"], 0, protocol::kWholeByteMax, "battery"));
    });
  }
  if (root["deadman"]) {
    errors.attempt([&] { m.deadman = use(r, root["deadman"], r.button_or_trigger(root["deadman"], "deadman")); });
  }
  if (const auto p = root["deadman_panic"]) {
    errors.attempt([&] {
      m.deadman_panic = r.number(p, kDeadmanPanicMin, 1.0, true, "deadman_panic");
      if (*m.deadman_panic <= kDeadmanPanicMin) {
        r.fail(p, "deadman_panic must lie above the trigger's press point (0.5) and below full travel (1.0)");
      }
      m.deadman_panic_pos = r.pos(p);
    });
  }
  if (const auto e = root["estop"]) errors.attempt([&] { m.estop = use(r, e, r.button(e)); });
  if (const auto h = root["stop_reset_hold"]) {
    errors.attempt([&] {
      m.stop_reset_hold_ms =
          std::llround(r.number(h, kStopResetHoldMinS, kStopResetHoldMaxS, false, "stop_reset_hold") * 1000.0);
    });
  }
  if (const auto t = root["enable_timeout"]) {
    errors.attempt([&] {
      if (r.text(t, "enable_timeout") == "off") {
        m.enable_timeout_ms.reset();  // a base's timeout switched off
        return;
      }
      const double seconds = r.number(t, kEnableTimeoutMinS, kEnableTimeoutMaxS, false, "enable_timeout");
      m.enable_timeout_ms = std::llround(seconds * 1000.0);
    });
  }
  if (const auto sup = root["supervisor"]) errors.attempt([&] { m.supervisor = read_supervisor(r, sup); });
  if (const auto b = root["brake"]) {
    errors.attempt([&] {
      const auto mode = r.text(b, "brake");
      if (mode == "enabled") m.brake = BrakeMode::kEnabled;
      else if (mode == "moving") m.brake = BrakeMode::kMoving;
      else r.fail(b, "brake must be 'enabled' or 'moving', not " + quote(mode));
    });
  }
  if (const auto s = root["scale"]) errors.attempt([&] { m.scale = read_scale(r, s); });
  if (root["feedback"]) errors.attempt([&] { read_feedback(r, root["feedback"], m.feedback); });
  if (root["bindings"]) {
    errors.attempt([&] {
      auto list = read_bindings(r, root["bindings"], errors);
      merge_bindings(m.bindings, std::move(list.bindings), list.unbinds);
    });
  }
  if (const auto layers = root["layers"]) {
    errors.attempt([&] {
      r.expect_map(layers, "layers");
      std::set<std::string> seen;
      for (const auto& kv : layers) {
        errors.attempt([&] {
          BindingList list;
          auto layer = read_layer(r, kv.first, kv.second, list, errors);
          check_layer_name(seen, layer);  // within this file; a base's layer of the same name is merged below
          const auto it =
              std::find_if(m.layers.begin(), m.layers.end(), [&](const Layer& l) { return l.name == layer.name; });
          if (it == m.layers.end()) {
            merge_bindings(layer.bindings, std::move(list.bindings), list.unbinds);
            m.layers.push_back(std::move(layer));
          } else {
            merge_bindings(it->bindings, std::move(list.bindings), list.unbinds);
            it->input = layer.input;
            it->toggle = layer.toggle;
            it->pos = layer.pos;
          }
        });
      }
    });
  }
  chain.files.pop_back();
  return m;
}

}  // namespace

Mapping load_mapping_file(const fs::path& file) {
  Chain chain;
  std::optional<Mapping> mapping;
  try {
    mapping = read_file(file, chain, SourcePos{});
  } catch (const InputError& e) {
    chain.errors.add(e);  // one that ends the reading (bad YAML, a missing base), after those collected
  }
  chain.errors.throw_if_any();
  return std::move(*mapping);
}

ValidMapping load_mapping(const fs::path& file, NeedsRobot needs) {
  Chain chain;
  std::optional<Mapping> mapping;
  try {
    mapping = read_file(file, chain, SourcePos{});
  } catch (const InputError& e) {
    chain.errors.add(e);
  }
  if (mapping) {
    // After errors in the reading, a key that could not be read would be
    // called missing: the robot and deadman are not asked for then.
    const bool named = needs == NeedsRobot::kYes || mapping->robot.has_value();
    try {
      auto valid = validate(std::move(*mapping), named && chain.errors.empty());
      if (chain.errors.empty()) return valid;
    } catch (const InputError& e) {
      chain.errors.add(e);
    }
  }
  chain.errors.throw_if_any();
  throw InputError(SourcePos{file.string()}, "cannot load the mapping");  // not reached: no mapping came with an error
}

ValidMapping load_recorded_chain(const std::vector<MappingText>& files) {
  if (files.empty()) throw InputError("no mapping file recorded");
  Chain chain;
  chain.recorded = &files;
  return validate(read_file(files.front().label, chain, SourcePos{}, &files.front().text), true);
}

ValidMapping load_mapping_text(const std::string& text, const fs::path& file) {
  Chain chain;
  return validate(read_file(file, chain, SourcePos{}, &text), true);
}

}  // namespace andros::mapping

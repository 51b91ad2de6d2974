#include "andros/mapping/model.hpp"

#include "andros/base/error_list.hpp"
#include "andros/protocol/robots.hpp"
#include "overload.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace andros::mapping {
namespace {

using protocol::kWholeByteMax;

std::string quoted(protocol::SignalId id) { return "'" + std::string(protocol::info(id).name) + "'"; }

// Why a signal cannot be the target of a plain button, pair or analog binding.
std::string not_bindable(protocol::SignalId id) {
  switch (protocol::info(id).kind) {
    case protocol::SignalKind::kInterlock:
      return quoted(id) + " is set by the safety layer (1 only while enabled); it cannot be bound";
    case protocol::SignalKind::kConstant:
      return quoted(id) + " is fixed for the run (byte12 and battery under 'constants:', code with --code)";
    case protocol::SignalKind::kSelector:
      return quoted(id) + " is a selector-like switch: set it from a 'selector:' binding's positions";
    case protocol::SignalKind::kWeapon: return quoted(id) + " is a weapon: it needs 'button' and 'arm'";
    case protocol::SignalKind::kCentred:
    case protocol::SignalKind::kLevel: return quoted(id) + " is a whole byte: bind it with 'analog:'";
    case protocol::SignalKind::kMotion: break;
  }
  return {};
}

void check_motion(protocol::SignalId id, const SourcePos& pos) {
  if (protocol::info(id).kind != protocol::SignalKind::kMotion) throw InputError(pos, not_bindable(id));
}

/// "line 12", or "line 12 of base.yaml" when other is in another file than here.
std::string line_of(const SourcePos& other, const SourcePos& here) {
  return "line " + std::to_string(other.line) + (other.file == here.file ? "" : " of " + other.file);
}

/// Of two places that clash, the one in the file being checked (the other
/// one is named in the message): an extending file's mistake is reported in
/// that file, at its line, not at the line of the base it runs into.
const SourcePos& blame(const std::string& file, const SourcePos& first, const SourcePos& second) {
  return first.file != file && second.file == file ? second : first;
}

void check_range(bool ok, const SourcePos& at, const std::string& what) {
  if (!ok) throw InputError(at, what + " is out of range");
}

// reserved: the deadman and the layer keys; file: the file checked.
void check_rule(const Binding& b, const std::optional<InputUse>& deadman, const std::vector<InputUse>& reserved,
                const std::string& file) {
  const auto& at = b.target_pos;
  const auto check_threshold = [&](double t) { check_range(t > 0.0 && t <= 1.0, b.pos, "threshold"); };
  std::visit(
      Overload{
          [&](const ButtonBinding& r) {
            check_motion(r.signal, at);
            check_threshold(r.threshold);
          },
          [&](const WeaponBinding& r) {
            if (protocol::info(r.signal).kind != protocol::SignalKind::kWeapon) {
              throw InputError(at, "'arm' is only for weapon signals; " + quoted(r.signal) + " is not one");
            }
            if (!r.arm)
              throw InputError(b.pos,
                               "weapon binding for " + quoted(r.signal) + " needs 'arm': a second button held to fire");
            if (*r.arm == r.input) throw InputError(b.arm->pos, "'arm' must be a different button from 'button'");
            if (deadman && *r.arm == deadman->key) {
              const auto& blamed = blame(file, b.arm->pos, deadman->pos);
              throw InputError(blamed, "'arm' must be a second button, not the deadman (" +
                                           line_of(&blamed == &deadman->pos ? b.arm->pos : deadman->pos, blamed) + ")");
            }
            // A layer key that also arms would make one press enter the layer and arm it.
            for (const auto& key : reserved) {
              if (*r.arm == key.key) {
                const auto& blamed = blame(file, b.arm->pos, key.pos);
                throw InputError(blamed, "'arm' must be a second button, not the key of a layer (" +
                                             line_of(&blamed == &key.pos ? b.arm->pos : key.pos, blamed) + ")");
              }
            }
          },
          [&](const PairBinding& r) {
            check_motion(r.signals[0], at);
            check_motion(r.signals[1], at);
            if (r.signals[0] == r.signals[1]) throw InputError(at, "an opposing pair names two different signals");
            check_threshold(r.threshold);
          },
          [&](const AxisBinding& r) {
            const auto kind = protocol::info(r.analog).kind;
            if (kind != protocol::SignalKind::kCentred && kind != protocol::SignalKind::kLevel) {
              throw InputError(at, quoted(r.analog) + " is not an analog byte (drive, pivot, arm_speed, light)");
            }
            check_range(r.shape.deadzone >= 0.0 && r.shape.deadzone < 1.0, b.pos, "deadzone");
            check_range(r.shape.expo >= 0.0 && r.shape.expo <= 1.0, b.pos, "expo");
          },
          [&](const KnobBinding& r) {
            if (protocol::info(r.analog).kind != protocol::SignalKind::kLevel) {
              throw InputError(at, "a knob drives arm_speed or light; " + quoted(r.analog) +
                                       " must return to centre, so bind it to an axis");
            }
            check_range(r.rate > 0 && r.rate <= kMaxKnobRate, b.pos, "rate");
            check_range(!r.initial || (*r.initial >= 0 && *r.initial <= kWholeByteMax), b.pos, "initial");
          },
          [&](const SelectorBinding& r) {
            check_range(r.positions.size() >= 2, at, "the number of positions");
            check_range(r.initial >= 0 && static_cast<std::size_t>(r.initial) < r.positions.size(), b.pos,
                        "initial position");
            for (const auto& position : r.positions) {
              for (const auto id : position) {
                if (protocol::info(id).kind != protocol::SignalKind::kSelector) {
                  throw InputError(at,
                                   "selector positions set selector-like signals only; " + quoted(id) + " is not one");
                }
                const auto partner = protocol::partner_of(id);
                if (partner && std::find(position.begin(), position.end(), *partner) != position.end()) {
                  throw InputError(at, "a position sets both " + quoted(id) + " and its opposite");
                }
              }
            }
          },
      },
      b.rule);
}

// Within one list of bindings: every input once, every analog byte once.
void check_list(const std::vector<Binding>& list, const std::vector<InputUse>& reserved, const std::string& file,
                ErrorList& errors) {
  std::map<input::InputKey, SourcePos> inputs;
  std::map<protocol::SignalId, SourcePos> analogs;
  for (const auto& b : list) {
    for (const auto& u : b.inputs) {
      for (const auto& r : reserved) {
        if (r.key != u.key) continue;
        const auto name = "'" + input::input_name(u.key) + "'";
        if (&blame(file, u.pos, r.pos) == &u.pos) {
          errors.add(InputError(u.pos, name + " is the deadman or switches a layer (" + line_of(r.pos, u.pos) +
                                           "); it cannot also be bound"));
        } else {
          errors.add(InputError(r.pos, name + " is bound at " + line_of(u.pos, r.pos) +
                                           "; it cannot also be the deadman or switch a layer"));
        }
      }
      const auto [it, fresh] = inputs.emplace(u.key, u.pos);
      if (!fresh) {
        errors.add(InputError(u.pos, "'" + input::input_name(u.key) + "' is bound twice in this layer (first at " +
                                         line_of(it->second, u.pos) + ")"));
      }
    }
    if (const auto target = analog_target(b)) {
      const auto [it, fresh] = analogs.emplace(*target, b.target_pos);
      if (!fresh) {
        errors.add(InputError(b.target_pos, quoted(*target) + " is driven by two bindings in this layer (first at " +
                                                line_of(it->second, b.target_pos) + ")"));
      }
    }
  }
}

// A weapon's arming input may not also fire something else in the same layer.
void check_arms(const Mapping& m, int layer, ErrorList& errors) {
  const auto refs = effective_bindings(m, layer);
  for (const auto& ref : refs) {
    const auto& b = binding_at(m, ref);
    if (!b.arm) continue;
    for (const auto& other : refs) {
      for (const auto& u : binding_at(m, other).inputs) {
        if (u.key != b.arm->key) continue;
        const auto name = "'" + input::input_name(u.key) + "'";
        if (&blame(m.file, b.arm->pos, u.pos) == &b.arm->pos) {
          errors.add(InputError(b.arm->pos, "arming input " + name + " is also bound at " + line_of(u.pos, b.arm->pos) +
                                                "; pressing it would do both"));
        } else {
          errors.add(InputError(
              u.pos, name + " is the arming input at " + line_of(b.arm->pos, u.pos) + "; pressing it would do both"));
        }
      }
    }
  }
}

// One signal has one toggle state, flipped by any of its toggle inputs; a
// momentary binding on the same signal would leave "on" with two meanings.
void check_toggles(const Mapping& m, ErrorList& errors) {
  std::map<protocol::SignalId, std::pair<bool, const Binding*>> first;  // signal -> (toggled?, its first binding)
  for (const auto& ref : all_bindings(m)) {
    const auto& b = binding_at(m, ref);
    std::vector<std::pair<protocol::SignalId, bool>> uses;
    if (const auto* x = std::get_if<ButtonBinding>(&b.rule)) uses.emplace_back(x->signal, x->toggle);
    if (const auto* x = std::get_if<PairBinding>(&b.rule)) {
      uses.emplace_back(x->signals[0], false);
      uses.emplace_back(x->signals[1], false);
    }
    for (const auto& [id, toggle] : uses) {
      const auto [it, fresh] = first.emplace(id, std::pair{toggle, &b});
      if (fresh || it->second.first == toggle) continue;
      const auto& other = *it->second.second;
      const bool here = &blame(m.file, b.target_pos, other.target_pos) == &b.target_pos;
      const auto& at = here ? b.target_pos : other.target_pos;
      errors.add(InputError(at, quoted(id) + ((here ? toggle : !toggle) ? " is momentary" : " is a toggle") + " at " +
                                    line_of(here ? other.pos : b.pos, at) +
                                    "; a signal is either toggled or momentary, not both"));
    }
  }
}

// Speed levels: fractions in (0, 1], slowest first; their buttons step the
// level in every layer, so nothing else may read them anywhere.
void check_scale(const Mapping& m, const std::vector<InputUse>& reserved) {
  const auto& s = m.scale;
  if (s.levels.empty() || s.levels.size() > kMaxSpeedLevels) {
    throw InputError(s.pos, "scale has 1.." + std::to_string(kMaxSpeedLevels) + " levels");
  }
  for (std::size_t i = 0; i < s.levels.size(); ++i) {
    check_range(s.levels[i] > 0.0 && s.levels[i] <= 1.0, s.pos, "speed level");
    if (i > 0 && s.levels[i] <= s.levels[i - 1])
      throw InputError(s.pos, "speed levels go from the slowest to the fastest");
  }
  check_range(s.initial < s.levels.size(), s.pos, "initial speed level");
  if ((s.levels.size() > 1) != s.up.has_value()) {
    throw InputError(s.pos, "scale has a 'button' exactly when it has more than one level");
  }
  if (s.down && !s.up) throw InputError(s.down->pos, "scale has 'down' but no 'button' to step up");
  if (s.up && s.down && s.up->key == s.down->key)
    throw InputError(s.down->pos, "'down' must be a different button from 'button'");
  for (const auto& key : {s.up, s.down}) {
    if (!key) continue;
    const auto name = "'" + input::input_name(key->key) + "'";
    if (m.estop && m.estop->key == key->key) {
      throw InputError(key->pos, name + " is the stop button (" + line_of(m.estop->pos, key->pos) +
                                     "); it cannot also step the speed level");
    }
    for (const auto& r : reserved) {
      if (r.key == key->key) {
        throw InputError(key->pos, name + " is the deadman or switches a layer (" + line_of(r.pos, key->pos) +
                                       "); it cannot also step the speed level");
      }
    }
    for (const auto ref : all_bindings(m)) {
      const auto& b = binding_at(m, ref);
      for (const auto& u : b.inputs) {
        if (u.key == key->key) {
          throw InputError(key->pos, name + " steps the speed level in every layer; it is also bound at " +
                                         line_of(u.pos, key->pos));
        }
      }
      if (b.arm && b.arm->key == key->key) {
        throw InputError(key->pos, name + " steps the speed level in every layer; it also arms a weapon at " +
                                       line_of(b.arm->pos, key->pos));
      }
    }
  }
}

}  // namespace

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

namespace {

// The stop button is bound to nothing else: not the deadman, no layer's key,
// no binding's input or arming input in any layer.
void check_estop(const Mapping& m) {
  if (!m.estop) return;
  const auto key = m.estop->key;
  const auto refuse = [&](const SourcePos& other, const std::string& what) {
    throw InputError(m.estop->pos, "the stop button '" + input::input_name(key) + "' is already " + what + " (" +
                                       line_of(other, m.estop->pos) + "): a stop button is bound to nothing else");
  };
  if (!key.is_button()) throw InputError(m.estop->pos, "estop is a button (or a hat direction), not an axis");
  if (m.deadman && m.deadman->key == key) refuse(m.deadman->pos, "the deadman");
  for (const auto& layer : m.layers) {
    if (layer.input.key == key) refuse(layer.input.pos, "the key of layer " + quote(layer.name));
  }
  for (const auto ref : all_bindings(m)) {
    const auto& b = binding_at(m, ref);
    for (const auto& u : b.inputs) {
      if (u.key == key) refuse(u.pos, "bound");
    }
    if (b.arm && b.arm->key == key) refuse(b.arm->pos, "an arming input");
  }
}

/// A stop must be on an input every controller has: no hat past the first
/// (a pad has none, a joystick at least one when it has any).
void check_stop_reachable(const std::optional<InputUse>& stop, std::string_view what) {
  if (!stop || stop->key.kind != input::InputKind::kHat || stop->key.index < 4) return;
  throw InputError(stop->pos, std::string(what) + " '" + input::input_name(stop->key) +
                                  "' is on a hat a controller may not have: put a stop on a button (or hat0)");
}

void check_deadman_panic(const Mapping& m) {
  if (!m.deadman_panic) return;
  if (!m.deadman || m.deadman->key.is_button()) {
    throw InputError(m.deadman_panic_pos,
                     "deadman_panic needs a trigger deadman (lefttrigger, righttrigger)" +
                         (m.deadman ? "; '" + input::input_name(m.deadman->key) + "' is a button" : std::string()));
  }
  if (*m.deadman_panic <= kDeadmanPanicMin || *m.deadman_panic >= 1.0) {
    throw InputError(m.deadman_panic_pos,
                     "deadman_panic must lie above the trigger's press point (0.5) and below full travel (1.0)");
  }
}

}  // namespace

void check_layer_name(std::set<std::string>& names, const Layer& layer) {
  if (!names.insert(layer.name).second) throw InputError(layer.pos, "layer " + quote(layer.name) + " given twice");
}

ValidMapping validate(Mapping m, bool require_robot) {
  // Every error is collected, as a compiler does: the operator fixes them all in one pass.
  ErrorList errors;
  if (require_robot && !m.robot) {
    errors.add(InputError(SourcePos{m.file}, "missing 'robot' (one of " + protocol::robot_list() + ")"));
  }
  if (require_robot && !m.deadman) {
    errors.add(InputError(SourcePos{m.file}, "missing 'deadman': the button that enables motion"));
  }
  if (m.center < kCenterTrimMin || m.center > kCenterTrimMax) {
    errors.add(InputError(SourcePos{m.file}, center_out_of_band(std::to_string(m.center))));
  }
  std::vector<InputUse> reserved;
  if (m.deadman) {
    const auto k = m.deadman->key;
    if (k.kind == input::InputKind::kJoyAxis ||
        (k.kind == input::InputKind::kPadAxis && input::input_name(k) != "lefttrigger" &&
         input::input_name(k) != "righttrigger")) {
      errors.add(InputError(m.deadman->pos, "the deadman is a button or a trigger (lefttrigger, righttrigger)"));
    }
    reserved.push_back(*m.deadman);
  }
  std::set<std::string> names;
  for (const auto& layer : m.layers) {
    for (const auto& r : reserved) {
      if (r.key == layer.input.key) {
        errors.add(InputError(layer.input.pos, "'" + input::input_name(r.key) +
                                                   "' already switches a layer or is the deadman (" +
                                                   line_of(r.pos, layer.input.pos) + ")"));
      }
    }
    errors.attempt([&] { check_layer_name(names, layer); });
    reserved.push_back(layer.input);
  }
  if (m.supervisor && m.supervisor->weapons_consent && m.supervisor->weapons_consent->key == m.supervisor->stop.key) {
    throw InputError(m.supervisor->weapons_consent->pos,
                     "the supervisor's 'weapons_consent' must be a different button "
                     "from its 'stop' (" +
                         line_of(m.supervisor->stop.pos, m.supervisor->weapons_consent->pos) + ")");
  }
  std::map<protocol::SignalId, SourcePos> selector_signals;
  const auto check_bindings = [&](const std::vector<Binding>& list) {
    for (const auto& b : list) {
      errors.attempt([&] { check_rule(b, m.deadman, reserved, m.file); });
      if (const auto* s = std::get_if<SelectorBinding>(&b.rule)) {
        std::set<protocol::SignalId> mine;
        for (const auto& p : s->positions) mine.insert(p.begin(), p.end());
        for (const auto id : mine) {
          const auto [it, fresh] = selector_signals.emplace(id, b.target_pos);
          if (!fresh) {
            const auto& at = blame(m.file, b.target_pos, it->second);
            errors.add(InputError(at, quoted(id) + " is also set by the selector at " +
                                          line_of(&at == &b.target_pos ? it->second : b.target_pos, at)));
          }
        }
      }
    }
    check_list(list, reserved, m.file, errors);
  };
  check_bindings(m.bindings);
  for (const auto& layer : m.layers) check_bindings(layer.bindings);
  check_arms(m, -1, errors);
  for (std::size_t i = 0; i < m.layers.size(); ++i) check_arms(m, static_cast<int>(i), errors);
  check_toggles(m, errors);
  errors.attempt([&] { check_estop(m); });
  errors.attempt([&] { check_deadman_panic(m); });
  errors.attempt([&] { check_stop_reachable(m.estop, "estop"); });
  errors.attempt([&] {
    check_stop_reachable(m.supervisor ? std::optional(m.supervisor->stop) : std::nullopt, "the supervisor's stop");
  });
  errors.attempt([&] { check_scale(m, reserved); });
  errors.throw_if_any();
  return ValidMapping(std::move(m));
}

}  // namespace andros::mapping

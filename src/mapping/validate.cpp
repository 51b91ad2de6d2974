// validate() (andros/mapping/model.hpp): the one check of a mapping, every
// error collected.

#include <initializer_list>
#include <map>
#include <set>
#include <string_view>
#include <utility>

#include "andros/base/error_list.hpp"
#include "andros/mapping/model.hpp"
#include "andros/protocol/robots.hpp"
#include "binding_checks.hpp"
#include "check_words.hpp"

namespace andros::mapping {
namespace {

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

/// A reset gesture is buttons that no stop shares (a stop button only ever
/// stops), nor the deadman (released throughout): `what` is whose. The
/// other buttons of the pad may be bound too (inert while stopped).
/// An input a reset may not share: what it is, and why not.
struct Reserved {
  const std::optional<InputUse>* use;
  std::string_view what;
  std::string_view why;
};
constexpr std::string_view kStopOnlyStops = "a stop button only ever stops, it cannot also reset";
void check_reset(const std::vector<InputUse>& reset, std::initializer_list<Reserved> others,
                 const std::optional<InputUse>& deadman, std::string_view what) {
  for (const auto& use : reset) {
    const auto name = "'" + input::input_name(use.key) + "'";
    if (!use.key.is_button()) {
      throw InputError(use.pos, std::string(what) + " is a button or a chord of buttons; " + name + " is an axis");
    }
    for (const auto& [other, other_what, why] : others) {
      if (*other && (*other)->key == use.key) {
        throw InputError(use.pos, name + " is " + std::string(other_what) + " (" + line_of((*other)->pos, use.pos) +
                                      "): " + std::string(why));
      }
    }
    if (deadman && deadman->key == use.key) {
      throw InputError(use.pos, name + " is the deadman (" + line_of(deadman->pos, use.pos) +
                                    "): a reset is held with the deadman released");
    }
    if (use.key.kind == input::InputKind::kHat && use.key.index >= 4) {
      throw InputError(use.pos, std::string(what) + " " + name +
                                    " is on a hat a controller may not have: put it on buttons (or hat0)");
    }
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
            errors.add(InputError(at, quoted_signal(id) + " is also set by the selector at " +
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
  errors.attempt([&] {
    check_reset(m.stop_reset, {{&m.estop, "the stop button", kStopOnlyStops}}, m.deadman, "stop_reset");
  });
  if (m.supervisor) {
    const std::optional<InputUse> stop = m.supervisor->stop;
    const std::optional<InputUse> none;
    errors.attempt([&] {
      check_reset(m.supervisor->reset,
                  {{&stop, "the supervisor's stop button", kStopOnlyStops},
                   {&m.supervisor->weapons_consent, "the supervisor's weapons consent", "a consent never resets"}},
                  none, "the supervisor's reset");
    });
  }
  errors.throw_if_any();
  return ValidMapping(std::move(m));
}

}  // namespace andros::mapping

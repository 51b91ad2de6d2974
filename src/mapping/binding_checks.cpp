#include "binding_checks.hpp"

#include <algorithm>
#include <map>

#include "check_words.hpp"
#include "overload.hpp"

namespace andros::mapping {
namespace {

using protocol::kWholeByteMax;

// Why a signal cannot be the target of a plain button, pair or analog binding.
std::string not_bindable(protocol::SignalId id) {
  switch (protocol::info(id).kind) {
    case protocol::SignalKind::kInterlock:
      return quoted_signal(id) + " is set by the safety layer (1 only while enabled); it cannot be bound";
    case protocol::SignalKind::kConstant:
      return quoted_signal(id) + " is fixed for the run (byte12 and battery under 'constants:', code with --code)";
    case protocol::SignalKind::kSelector:
      return quoted_signal(id) + " is a selector-like switch: set it from a 'selector:' binding's positions";
    case protocol::SignalKind::kWeapon: return quoted_signal(id) + " is a weapon: it needs 'button' and 'arm'";
    case protocol::SignalKind::kCentred:
    case protocol::SignalKind::kLevel: return quoted_signal(id) + " is a whole byte: bind it with 'analog:'";
    case protocol::SignalKind::kMotion: break;
  }
  return {};
}

void check_motion(protocol::SignalId id, const SourcePos& pos) {
  if (protocol::info(id).kind != protocol::SignalKind::kMotion) throw InputError(pos, not_bindable(id));
}

}  // namespace

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
              throw InputError(at, "'arm' is only for weapon signals; " + quoted_signal(r.signal) + " is not one");
            }
            if (!r.arm)
              throw InputError(b.pos, "weapon binding for " + quoted_signal(r.signal) +
                                          " needs 'arm': a second button held to fire");
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
              throw InputError(at, quoted_signal(r.analog) + " is not an analog byte (drive, pivot, arm_speed, light)");
            }
            check_range(r.shape.deadzone >= 0.0 && r.shape.deadzone < 1.0, b.pos, "deadzone");
            check_range(r.shape.expo >= 0.0 && r.shape.expo <= 1.0, b.pos, "expo");
          },
          [&](const KnobBinding& r) {
            if (protocol::info(r.analog).kind != protocol::SignalKind::kLevel) {
              throw InputError(at, "a knob drives arm_speed or light; " + quoted_signal(r.analog) +
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
                  throw InputError(
                      at, "selector positions set selector-like signals only; " + quoted_signal(id) + " is not one");
                }
                const auto partner = protocol::partner_of(id);
                if (partner && std::find(position.begin(), position.end(), *partner) != position.end()) {
                  throw InputError(at, "a position sets both " + quoted_signal(id) + " and its opposite");
                }
              }
            }
          },
      },
      b.rule);
}

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
        errors.add(InputError(b.target_pos, quoted_signal(*target) +
                                                " is driven by two bindings in this layer (first at " +
                                                line_of(it->second, b.target_pos) + ")"));
      }
    }
  }
}

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
      errors.add(InputError(at, quoted_signal(id) + ((here ? toggle : !toggle) ? " is momentary" : " is a toggle") +
                                    " at " + line_of(here ? other.pos : b.pos, at) +
                                    "; a signal is either toggled or momentary, not both"));
    }
  }
}

}  // namespace andros::mapping

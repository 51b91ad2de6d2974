#include "sheet_notes.hpp"

#include <algorithm>
#include <cstdio>
#include <set>

#include "andros/protocol/words.hpp"
#include "sheet_words.hpp"

namespace andros::view::sheet_detail {
namespace {

using input::InputKind;

/// What a position with no bit means for the selector whose bits these are
/// ("speed medium", "main video 1", "inset off"); "none" for bits of no known switch.
std::string no_bit(const mapping::SelectorBinding& s) {
  for (const auto& p : s.positions) {
    for (const auto id : p) {
      for (const auto& w : protocol::kSelectorWords) {
        if (std::find(w.bits.begin(), w.bits.end(), protocol::info(id).name) != w.bits.end()) {
          return std::string(w.name) + " " + std::string(w.none);
        }
      }
    }
  }
  return "none";
}

std::string position(const mapping::SelectorBinding& s, const std::vector<protocol::SignalId>& signals) {
  std::string out;
  for (const auto id : signals) out += (out.empty() ? "" : "+") + signal_words(id);
  return out.empty() ? no_bit(s) : out;
}

std::string positions(const mapping::SelectorBinding& s) {
  std::string out;
  for (const auto& p : s.positions) out += (out.empty() ? "" : " > ") + position(s, p);
  return out;
}

std::string where(const mapping::Mapping& m, int layer) {
  return layer < 0 ? "" : " (" + m.layers.at(static_cast<std::size_t>(layer)).name + " layer)";
}

std::string speed_levels(const mapping::SpeedScale& scale) {
  std::string out;
  for (const auto level : scale.levels) out += (out.empty() ? "" : " > ") + exact_percent(level);
  return out;
}

/// The speed levels, and how they differ from the vehicle's speed range.
std::string speed_note(const mapping::Mapping& m) {
  const auto& s = m.scale;
  std::string out =
      "Speed levels (drive and pivot), " + label(s.up->key) + " steps up" +
      (s.down ? ", " + label(s.down->key) + " down" : std::string(", after the fastest back to the slowest")) + ": " +
      speed_levels(s) + " of the stick's travel from rest; starts at " + exact_percent(s.levels.at(s.initial)) +
      ", again after the controller is lost or driving was interrupted; kept while the deadman is "
      "released. A stick held when the level changes waits until it is back at rest.";
  const auto refs = mapping::all_bindings(m);
  const bool range = std::any_of(refs.begin(), refs.end(), [&](mapping::BindingRef ref) {
    const auto* sel = std::get_if<mapping::SelectorBinding>(&mapping::binding_at(m, ref).rule);
    if (sel == nullptr) return false;
    return std::any_of(sel->positions.begin(), sel->positions.end(), [](const auto& p) {
      return std::any_of(p.begin(), p.end(), [](protocol::SignalId id) {
        return id == protocol::signal_id("speed_low") || id == protocol::signal_id("speed_high");
      });
    });
  });
  if (range)
    out +=
        " Not the speed_low/speed_high selector: that sets the vehicle's own speed range; the level scales the stick "
        "within it.";
  return out;
}

/// How long a reset is held: "2 s".
std::string reset_hold(const mapping::Mapping& m) {
  return figure(static_cast<double>(m.stop_reset_hold_ms) / 1000) + " s";
}

/// A reset gesture as the sheet says it: "Back and Start held together 2 s"; "" for none.
std::string reset_words(const std::vector<mapping::InputUse>& reset, const mapping::Mapping& m) {
  if (reset.empty()) return {};
  std::string out = label(reset.front().key);
  for (std::size_t i = 1; i < reset.size(); ++i) out += " and " + label(reset[i].key);
  return out + (reset.size() > 1 ? " held together " : " held ") + reset_hold(m);
}

}  // namespace

std::vector<std::string> sheet_notes(const mapping::Mapping& m) {
  std::vector<std::string> out;
  // Said here too: the drawing may leave a long detail off a label.
  if (m.deadman && !deadman_detail(m).empty()) {
    out.push_back("The deadman, " + label(m.deadman->key) + ": held " + deadman_detail(m) + ".");
  }
  std::set<std::string> arms;
  std::string shapes;
  for (const auto ref : mapping::all_bindings(m)) {
    const auto& b = mapping::binding_at(m, ref);
    if (const auto* s = std::get_if<mapping::SelectorBinding>(&b.rule)) {
      out.push_back(spoken(s->name) + " selector" + where(m, ref.layer) + ", " + label(s->next) + " steps" +
                    (s->prev ? ", " + label(*s->prev) + " back" : "") + ": " + positions(*s) + "; starts at " +
                    position(*s, s->positions.at(static_cast<std::size_t>(s->initial))));
    } else if (const auto* k = std::get_if<mapping::KnobBinding>(&b.rule)) {
      const auto& w = protocol::words(k->analog);
      out.push_back(signal_words(k->analog) + " knob" + where(m, ref.layer) + ": " + label(k->increase) + " " +
                    std::string(w.more) + ", " + label(k->decrease) + " " + std::string(w.less) + ", " +
                    std::to_string(k->rate) + " units/s; starts at " + std::to_string(k->initial.value_or(0)) +
                    ", kept while not enabled");
    } else if (const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule); w != nullptr && w->arm) {
      arms.insert(label(*w->arm));
    } else if (const auto* a = std::get_if<mapping::AxisBinding>(&b.rule)) {
      // The figures that make a stick feel as it does, to recognise it by.
      const auto layer = ref.layer < 0 ? "" : ", " + m.layers.at(static_cast<std::size_t>(ref.layer)).name + " layer";
      shapes += (shapes.empty() ? "" : "; ") + signal_words(a->analog) + " (" + label(a->axis) + layer +
                "): deadzone " + figure(a->shape.deadzone) + ", expo " + figure(a->shape.expo);
    }
  }
  if (m.scale.up) out.push_back(speed_note(m));
  else if (m.scale.levels.front() != 1.0) {
    out.push_back("Drive and pivot move " + exact_percent(m.scale.levels.front()) +
                  " of the stick's travel from rest (scale).");
  }
  if (!shapes.empty()) out.push_back("Analog inputs: " + shapes + ".");
  if (!arms.empty()) {
    std::string list;
    for (const auto& a : arms) list += (list.empty() ? "" : " or ") + a;
    const bool consent = m.supervisor && m.supervisor->weapons_consent;
    out.push_back("Weapons fire only when the run has --weapons, the deadman" +
                  (m.deadman ? " (" + label(m.deadman->key) + ")" : std::string()) + " is held and the arming input (" +
                  list + ") is held" + (consent ? ", and the supervisor holds its consent." : "."));
  }
  if (m.supervisor) {
    // On the second controller: not drawn on the operator's pad, said here.
    const auto reset = reset_words(m.supervisor->reset, m);
    std::string text =
        "Supervisor's controller (run --supervisor): " + label(m.supervisor->stop.key) +
        " stops (latched; it never resets)" +
        (reset.empty() ? "; it has no reset" : "; " + reset + " resets any stop (then the deadman pressed afresh)");
    if (m.supervisor->weapons_consent) {
      text += "; " + label(m.supervisor->weapons_consent->key) +
              " held is the weapons consent (a two-person rule: pressed after the weapons became possible)";
    }
    out.push_back(text + ". Losing either controller stops motion.");
  }
  if (m.estop) {
    const auto reset = reset_words(m.stop_reset, m);
    out.push_back("STOP: a press of " + label(m.estop->key) +
                  " (or holding it) stops the vehicle, whenever; it stays stopped until reset on the controller "
                  "that stopped: " +
                  (reset.empty() ? std::string("this mapping has no stop_reset (the supervisor resets, or restart)")
                                 : "release every stop button and the deadman, then " + reset) +
                  "; then press the deadman afresh.");
  }
  if (m.enable_timeout_ms) {
    char timeout[160];
    std::snprintf(timeout, sizeof timeout,
                  "Enable timeout: after %g s enabled with no input change the vehicle stops; release and press the "
                  "deadman to go on.",
                  static_cast<double>(*m.enable_timeout_ms) / 1000.0);
    out.emplace_back(timeout);
  }
  out.push_back(
      "Releasing the deadman switches toggles and toggled layers off. After the deadman press or a layer "
      "change, an input with a new meaning acts only once seen at rest.");
  const auto numbered = [](const mapping::InputUse& u) { return u.key.kind >= InputKind::kJoyButton; };
  bool joystick = (m.deadman && numbered(*m.deadman)) ||
                  std::any_of(m.layers.begin(), m.layers.end(), [&](const auto& l) { return numbered(l.input); });
  for (const auto ref : mapping::all_bindings(m)) {
    const auto& b = mapping::binding_at(m, ref);
    joystick = joystick || std::any_of(b.inputs.begin(), b.inputs.end(), numbered) || (b.arm && numbered(*b.arm));
  }
  if (joystick) {
    out.push_back(
        "Joystick buttons, axes and hats are numbered from 0, as SDL numbers them and 'andros-bridge "
        "inputs' shows them: button 0 is the first, which the device may print as 1.");
  }
  return out;
}

}  // namespace andros::view::sheet_detail

// The cheat sheet's content: each layer's inputs and what they do, read off
// the mapping model (docs/sheets.md). The renderers only lay it out.
#include "andros/view/sheet.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <set>

#include "andros/base/text.hpp"
#include "andros/protocol/words.hpp"
#include "sheet_layout.hpp"

namespace andros::view {
namespace {

using input::InputKey;
using input::InputKind;
using mapping::Binding;

constexpr std::array<std::string_view, input::kPadButtonNames.size()> kButtonLabels = {"A",
                                                                                       "B",
                                                                                       "X",
                                                                                       "Y",
                                                                                       "Back",
                                                                                       "Guide",
                                                                                       "Start",
                                                                                       "left stick click",
                                                                                       "right stick click",
                                                                                       "LB",
                                                                                       "RB",
                                                                                       "D-pad up",
                                                                                       "D-pad down",
                                                                                       "D-pad left",
                                                                                       "D-pad right",
                                                                                       "Misc",
                                                                                       "paddle 1",
                                                                                       "paddle 2",
                                                                                       "paddle 3",
                                                                                       "paddle 4",
                                                                                       "touchpad"};
constexpr std::array<std::string_view, input::kPadAxisNames.size()> kAxisLabels = {
    "left stick left/right", "left stick up/down", "right stick left/right", "right stick up/down", "LT", "RT"};

std::string label(InputKey key) {
  switch (key.kind) {
    case InputKind::kPadButton: return std::string(kButtonLabels.at(key.index));
    case InputKind::kPadAxis: return std::string(kAxisLabels.at(key.index));
    case InputKind::kJoyButton: return "button " + std::to_string(key.index);
    case InputKind::kJoyAxis: return "axis " + std::to_string(key.index);
    case InputKind::kHat:
      return "hat " + std::to_string(key.index / 4) + " " + std::string(input::kHatDirectionNames.at(key.index % 4));
  }
  return input::input_name(key);
}

bool is_trigger(InputKey key) { return key.kind == InputKind::kPadAxis && key.index >= 4; }

/// The way an axis is pushed to read as `positive` after invert: "up", "right", "squeezed".
std::string direction(InputKey axis, bool invert, bool positive) {
  const bool raw_positive = positive != invert;
  if (axis.kind != InputKind::kPadAxis) return raw_positive ? "positive" : "negative";
  if (is_trigger(axis)) return raw_positive ? "squeezed" : "below 0";
  const bool vertical = axis.index % 2 == 1;
  if (vertical) return raw_positive ? "down" : "up";
  return raw_positive ? "right" : "left";
}

/// What a signal does, in the operator's words (protocol/words.hpp): "zoom out".
std::string name(protocol::SignalId id) { return std::string(protocol::words(id).words); }

/// A mapping's own name (a selector's) as words: "main_video" reads "main video".
std::string spoken(std::string text) {
  std::replace(text.begin(), text.end(), '_', ' ');
  return text;
}

/// A number of the mapping as it is written there: 0.1, 0.35.
std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string percent(double fraction) { return std::to_string(static_cast<int>(std::lround(fraction * 100))) + "%"; }

/// A fraction as a percentage to three significant figures: "25%", "12.5%".
std::string exact_percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", fraction * 100);
  return buf;
}

std::string past(double threshold) {
  return threshold == mapping::kDefaultThreshold ? "" : "past " + percent(threshold);
}

/// Collects one layer's entries, one per input (a second meaning is joined on).
class PanelBuilder {
 public:
  void add(InputKey key, SheetMark mark, const std::string& function, std::string detail = {}, bool inherited = false) {
    auto [it, fresh] =
        entries_.try_emplace(key, SheetEntry{key, label(key), mark, function, std::move(detail), inherited});
    if (!fresh) it->second.function += "; " + function;
  }

  void add_binding(const Binding& b, bool inherited) {
    std::visit([&](const auto& rule) { add_rule(rule, inherited); }, b.rule);
  }

  std::vector<SheetEntry> entries() const {
    std::vector<SheetEntry> out;
    for (const auto& [key, entry] : entries_) out.push_back(entry);
    std::stable_sort(out.begin(), out.end(), [](const SheetEntry& a, const SheetEntry& b) {
      const auto ia = sheet_detail::pad_slot_index(a.key);
      const auto ib = sheet_detail::pad_slot_index(b.key);
      if (ia && ib) return *ia < *ib;
      return ia.has_value() && !ib.has_value();  // drawn inputs first, the rest in key order
    });
    return out;
  }

 private:
  void add_rule(const mapping::ButtonBinding& b, bool inherited) {
    const auto mark = b.toggle ? SheetMark::kToggle : SheetMark::kPlain;
    if (b.input.is_button()) return add(b.input, mark, name(b.signal), {}, inherited);
    const auto dir = direction(b.input, b.invert, true);
    const bool plain_trigger = is_trigger(b.input) && !b.invert;
    add(b.input, mark, plain_trigger ? name(b.signal) : dir + ": " + name(b.signal), past(b.threshold), inherited);
  }
  void add_rule(const mapping::WeaponBinding& b, bool inherited) {
    const std::string arm = b.arm ? label(*b.arm) : "arming";
    add(b.input, SheetMark::kWeapon, "fire " + name(b.signal), "needs --weapons + " + arm, inherited);
    if (b.arm && entries_.count(*b.arm) == 0) {
      add(*b.arm, SheetMark::kArming, "hold to arm weapons", is_trigger(*b.arm) ? "past half way" : "", inherited);
    }
  }
  void add_rule(const mapping::PairBinding& b, bool inherited) {
    add(b.axis, SheetMark::kPlain,
        direction(b.axis, b.invert, false) + ": " + name(b.signals[0]) + ", " + direction(b.axis, b.invert, true) +
            ": " + name(b.signals[1]),
        past(b.threshold), inherited);
  }
  void add_rule(const mapping::AxisBinding& b, bool inherited) {
    const auto& w = protocol::words(b.analog);
    // "up = forward" (drive forward/back reads as analog already); "analog"
    // when the way is the word ("right = right").
    const auto dir = direction(b.axis, b.shape.invert, true);
    const auto grows = dir == w.more ? std::string() : dir + " = " + std::string(w.more);
    std::string detail;
    if (protocol::info(b.analog).kind == protocol::SignalKind::kCentred) {
      detail = grows.empty() ? "analog" : grows;
    } else {
      detail = "analog 0..255";
      if ((!is_trigger(b.axis) || b.shape.invert) && !grows.empty()) detail += ", " + grows;
    }
    // The words in the order the input's label names its way ("left stick
    // left/right": pivot left/right): a stick's label goes from its raw
    // negative end; a trigger's has no way, so the growing word first.
    const bool stick = !is_trigger(b.axis) && b.axis.kind == InputKind::kPadAxis;
    const bool negative_first = stick && !b.shape.invert;
    const auto words = negative_first ? std::string(w.less) + "/" + std::string(w.more)
                                      : std::string(w.more) + "/" + std::string(w.less);
    add(b.axis, SheetMark::kPlain, name(b.analog) + " " + words, detail, inherited);
  }
  void add_rule(const mapping::KnobBinding& b, bool inherited) {
    const auto rate = std::to_string(b.rate) + "/s";
    const auto& w = protocol::words(b.analog);
    add(b.increase, SheetMark::kKnob, name(b.analog) + " " + std::string(w.more), rate, inherited);
    add(b.decrease, SheetMark::kKnob, name(b.analog) + " " + std::string(w.less), rate, inherited);
  }
  void add_rule(const mapping::SelectorBinding& b, bool inherited) {
    add(b.next, SheetMark::kSelector, spoken(b.name) + " selector: next", {}, inherited);
    if (b.prev) add(*b.prev, SheetMark::kSelector, spoken(b.name) + " selector: previous", {}, inherited);
  }

  std::map<InputKey, SheetEntry> entries_;
};

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
  for (const auto id : signals) out += (out.empty() ? "" : "+") + name(id);
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

/// How long a stop button is held to reset a stop: "2 s".
std::string reset_hold(const mapping::Mapping& m) {
  return figure(static_cast<double>(m.stop_reset_hold_ms) / 1000) + " s";
}

/// How the deadman is held, when it is not a plain button: "past half way;
/// off past 90% until fully released".
std::string deadman_detail(const mapping::Mapping& m) {
  std::string detail = m.deadman->key.is_button() ? "" : "past half way";
  if (m.deadman_panic) {
    char panic[64];
    std::snprintf(panic, sizeof panic, "; off past %.0f%% until fully released", *m.deadman_panic * 100.0);
    detail += panic;
  }
  return detail;
}

std::vector<std::string> notes(const mapping::Mapping& m) {
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
      out.push_back(name(k->analog) + " knob" + where(m, ref.layer) + ": " + label(k->increase) + " " +
                    std::string(w.more) + ", " + label(k->decrease) + " " + std::string(w.less) + ", " +
                    std::to_string(k->rate) + " units/s; starts at " + std::to_string(k->initial.value_or(0)) +
                    ", kept while not enabled");
    } else if (const auto* w = std::get_if<mapping::WeaponBinding>(&b.rule); w != nullptr && w->arm) {
      arms.insert(label(*w->arm));
    } else if (const auto* a = std::get_if<mapping::AxisBinding>(&b.rule)) {
      // The figures that make a stick feel as it does, to recognise it by.
      const auto layer = ref.layer < 0 ? "" : ", " + m.layers.at(static_cast<std::size_t>(ref.layer)).name + " layer";
      shapes += (shapes.empty() ? "" : "; ") + name(a->analog) + " (" + label(a->axis) + layer + "): deadzone " +
                figure(a->shape.deadzone) + ", expo " + figure(a->shape.expo);
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
    std::string text = "Supervisor's controller (run --supervisor): " + label(m.supervisor->stop.key) +
                       " stops (latched; released, then held " + reset_hold(m) +
                       ", it resets any stop; then the deadman pressed afresh)";
    if (m.supervisor->weapons_consent) {
      text += "; " + label(m.supervisor->weapons_consent->key) +
              " held is the weapons consent (a two-person rule: pressed after the weapons became possible)";
    }
    out.push_back(text + ". Losing either controller stops motion.");
  }
  if (m.estop) {
    out.push_back("STOP: a press of " + label(m.estop->key) +
                  " stops the vehicle; it stays stopped until reset on the controller that stopped: release " +
                  label(m.estop->key) + ", then hold it " + reset_hold(m) +
                  " with the deadman released; then press the deadman afresh.");
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

void add_layer_keys(const mapping::Mapping& m, int panel, PanelBuilder& out) {
  if (m.deadman) out.add(m.deadman->key, SheetMark::kDeadman, "hold to enable motion", deadman_detail(m));
  if (m.estop) out.add(m.estop->key, SheetMark::kStop, "stop (latched)");
  for (std::size_t i = 0; i < m.layers.size(); ++i) {
    const auto& layer = m.layers[i];
    const bool own = static_cast<int>(i) == panel;
    std::string what = layer.toggle ? (own ? layer.name + " layer off (back to base)" : layer.name + " layer on/off")
                                    : (own ? "held: " + layer.name + " layer" : "hold: " + layer.name + " layer");
    out.add(layer.input.key, SheetMark::kLayerKey, what);
  }
  // The speed buttons step the level in every layer.
  const auto& scale = m.scale;
  if (scale.up)
    out.add(scale.up->key, SheetMark::kSpeed, "speed level up", scale.down ? "" : "then back to the slowest");
  if (scale.down) out.add(scale.down->key, SheetMark::kSpeed, "speed level down");
}

bool drawable(const Sheet& sheet) {
  for (const auto& panel : sheet.panels) {
    for (const auto& e : panel.entries) {
      if (!sheet_detail::pad_slot_index(e.key)) return false;
    }
  }
  return true;
}

}  // namespace

std::string_view mark_name(SheetMark mark) {
  switch (mark) {
    case SheetMark::kPlain: return "";
    case SheetMark::kDeadman: return "DEADMAN";
    case SheetMark::kStop: return "STOP";
    case SheetMark::kLayerKey: return "LAYER";
    case SheetMark::kArming: return "ARMING";
    case SheetMark::kWeapon: return "WEAPON";
    case SheetMark::kToggle: return "TOGGLE";
    case SheetMark::kKnob: return "KNOB";
    case SheetMark::kSelector: return "SELECTOR";
    case SheetMark::kSpeed: return "SPEED";
  }
  return "";
}

namespace {

/// The mapping with the names its file gives (layers, selectors) as the
/// sheet shows them: escaped (base/text.hpp), so that a name holding a
/// newline or ESC is shown, never obeyed, on a terminal or in the SVG.
mapping::Mapping shown_names(mapping::Mapping m) {
  const auto escape = [](std::vector<mapping::Binding>& list) {
    for (auto& b : list) {
      if (auto* s = std::get_if<mapping::SelectorBinding>(&b.rule)) s->name = printable_text(s->name);
    }
  };
  escape(m.bindings);
  for (auto& layer : m.layers) {
    layer.name = printable_text(layer.name);
    escape(layer.bindings);
  }
  return m;
}

}  // namespace

Sheet build_sheet(const mapping::Mapping& from_file) {
  const auto m = shown_names(from_file);
  Sheet sheet;
  sheet.robot = m.robot.value_or("");
  sheet.file = printable_text(std::filesystem::path(m.file).filename().string());
  sheet.deadman = m.deadman ? label(m.deadman->key) : "";
  sheet.stop = m.estop ? label(m.estop->key) : "";
  for (int layer = -1; layer < static_cast<int>(m.layers.size()); ++layer) {
    PanelBuilder builder;
    add_layer_keys(m, layer, builder);
    for (const auto ref : mapping::effective_bindings(m, layer)) {
      builder.add_binding(mapping::binding_at(m, ref), layer >= 0 && ref.layer < 0);
    }
    SheetPanel panel{"base layer", "active when no other layer is", builder.entries()};
    if (layer >= 0) {
      const auto& l = m.layers.at(static_cast<std::size_t>(layer));
      panel.title = l.name + " layer";
      panel.how = l.toggle ? label(l.input.key) + " turns it on and off" : "while " + label(l.input.key) + " is held";
    }
    sheet.panels.push_back(std::move(panel));
  }
  sheet.notes = notes(m);
  sheet.pad = drawable(sheet);
  sheet.speed = m.scale.up.has_value();
  return sheet;
}

SheetFormat parse_sheet_format(std::string_view text, const SourcePos& pos) {
  if (text == "svg") return SheetFormat::kSvg;
  if (text == "text") return SheetFormat::kText;
  throw InputError(pos, "unknown format " + quote(text) + " (svg or text)");
}

}  // namespace andros::view

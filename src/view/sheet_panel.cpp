#include "sheet_panel.hpp"

#include <algorithm>
#include <map>
#include <string>

#include "andros/protocol/words.hpp"
#include "sheet_layout.hpp"
#include "sheet_words.hpp"

namespace andros::view::sheet_detail {
namespace {

using input::InputKey;
using input::InputKind;
using mapping::Binding;

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
      const auto ia = pad_slot_index(a.key);
      const auto ib = pad_slot_index(b.key);
      if (ia && ib) return *ia < *ib;
      return ia.has_value() && !ib.has_value();  // drawn inputs first, the rest in key order
    });
    return out;
  }

 private:
  void add_rule(const mapping::ButtonBinding& b, bool inherited) {
    const auto mark = b.toggle ? SheetMark::kToggle : SheetMark::kPlain;
    if (b.input.is_button()) return add(b.input, mark, signal_words(b.signal), {}, inherited);
    const auto dir = direction(b.input, b.invert, true);
    const bool plain_trigger = is_trigger(b.input) && !b.invert;
    add(b.input, mark, plain_trigger ? signal_words(b.signal) : dir + ": " + signal_words(b.signal), past(b.threshold),
        inherited);
  }
  void add_rule(const mapping::WeaponBinding& b, bool inherited) {
    const std::string arm = b.arm ? label(*b.arm) : "arming";
    add(b.input, SheetMark::kWeapon, "fire " + signal_words(b.signal), "needs --weapons + " + arm, inherited);
    if (b.arm && entries_.count(*b.arm) == 0) {
      add(*b.arm, SheetMark::kArming, "hold to arm weapons", is_trigger(*b.arm) ? "past half way" : "", inherited);
    }
  }
  void add_rule(const mapping::PairBinding& b, bool inherited) {
    add(b.axis, SheetMark::kPlain,
        direction(b.axis, b.invert, false) + ": " + signal_words(b.signals[0]) + ", " +
            direction(b.axis, b.invert, true) + ": " + signal_words(b.signals[1]),
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
    add(b.axis, SheetMark::kPlain, signal_words(b.analog) + " " + words, detail, inherited);
  }
  void add_rule(const mapping::KnobBinding& b, bool inherited) {
    const auto rate = std::to_string(b.rate) + "/s";
    const auto& w = protocol::words(b.analog);
    add(b.increase, SheetMark::kKnob, signal_words(b.analog) + " " + std::string(w.more), rate, inherited);
    add(b.decrease, SheetMark::kKnob, signal_words(b.analog) + " " + std::string(w.less), rate, inherited);
  }
  void add_rule(const mapping::SelectorBinding& b, bool inherited) {
    add(b.next, SheetMark::kSelector, spoken(b.name) + " selector: next", {}, inherited);
    if (b.prev) add(*b.prev, SheetMark::kSelector, spoken(b.name) + " selector: previous", {}, inherited);
  }

  std::map<InputKey, SheetEntry> entries_;
};

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

}  // namespace

std::vector<SheetEntry> panel_entries(const mapping::Mapping& m, int layer) {
  PanelBuilder builder;
  add_layer_keys(m, layer, builder);
  for (const auto ref : mapping::effective_bindings(m, layer)) {
    builder.add_binding(mapping::binding_at(m, ref), layer >= 0 && ref.layer < 0);
  }
  return builder.entries();
}

}  // namespace andros::view::sheet_detail

// The cheat sheet's content: each layer's inputs and what they do, read off
// the mapping model (docs/sheets.md). The renderers only lay it out.
#include "andros/view/sheet.hpp"

#include <filesystem>

#include "andros/base/text.hpp"
#include "sheet_layout.hpp"
#include "sheet_notes.hpp"
#include "sheet_panel.hpp"
#include "sheet_words.hpp"

namespace andros::view {
namespace {

using sheet_detail::label;

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
    SheetPanel panel{"base layer", "active when no other layer is", sheet_detail::panel_entries(m, layer)};
    if (layer >= 0) {
      const auto& l = m.layers.at(static_cast<std::size_t>(layer));
      panel.title = l.name + " layer";
      panel.how = l.toggle ? label(l.input.key) + " turns it on and off" : "while " + label(l.input.key) + " is held";
    }
    sheet.panels.push_back(std::move(panel));
  }
  sheet.notes = sheet_detail::sheet_notes(m);
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
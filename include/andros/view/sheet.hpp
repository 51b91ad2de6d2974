#pragma once
/// The cheat sheet (docs/sheets.md): what every input does in every layer of a
/// mapping, as a printable SVG drawing of the pad or as plain text tables.
/// Built from the loaded mapping only, so it cannot drift from it.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/input/input_state.hpp"
#include "andros/mapping/model.hpp"

namespace andros::view {

/// What kind of meaning an input has, as the sheet marks it.
enum class SheetMark : std::uint8_t {
  kPlain,     ///< a momentary switch or an analog axis: no mark
  kDeadman,   ///< the enabling button
  kStop,      ///< the latching stop button (`estop`)
  kLayerKey,  ///< holds or toggles a layer
  kArming,    ///< held with a weapon button to fire it
  kWeapon,    ///< fires only with --weapons, the deadman and the arming input
  kToggle,    ///< each press flips the signal
  kKnob,      ///< moves a level while held
  kSelector,  ///< steps a rotary switch
  kSpeed,     ///< steps the speed level of drive and pivot
};

/// The word the sheet prints for a mark ("" for kPlain).
std::string_view mark_name(SheetMark mark);

/// The marks the legend explains, in its order.
inline constexpr std::array kLegendMarks = {SheetMark::kDeadman, SheetMark::kStop,     SheetMark::kLayerKey,
                                            SheetMark::kArming,  SheetMark::kWeapon,   SheetMark::kToggle,
                                            SheetMark::kKnob,    SheetMark::kSelector, SheetMark::kSpeed};

/// One input's meaning in one layer.
struct SheetEntry {
  input::InputKey key{};
  std::string input;  ///< the input as an operator names it: "LB", "left stick up/down", "button 4"
  SheetMark mark = SheetMark::kPlain;
  std::string function;    ///< what it does: "fire weapon_1", "up: pt_up, down: pt_down"
  std::string detail;      ///< a qualifier, or empty: "analog, up = above 128", "needs --weapons + LT"
  bool inherited = false;  ///< a base binding a layer keeps
};

/// One layer: its title, how it is entered, and its inputs in sheet order.
struct SheetPanel {
  std::string title;  ///< "base layer", "arm layer"
  std::string how;    ///< "active when no other layer is", "while RB is held"
  std::vector<SheetEntry> entries;
};

struct Sheet {
  std::string robot;    ///< "HD1", or "" for a base mapping
  std::string file;     ///< the mapping's file name, without its directory
  std::string deadman;  ///< the deadman input as an operator names it ("LB")
  std::string stop;     ///< the stop button as an operator names it, or "" when none
  bool pad = true;      ///< every input is one the pad drawing shows; else list panels
  bool speed = false;   ///< the mapping has speed levels (the SPEED mark is used)
  std::vector<SheetPanel> panels;
  std::vector<std::string> notes;  ///< selectors' positions, knobs, the weapons rule
};

/// Walks a validated mapping: the base layer, then each layer with the base
/// bindings it keeps; the deadman and layer keys in every panel.
Sheet build_sheet(const mapping::Mapping& mapping);

/// Plain text: one table per layer (input, mark, function), then the notes.
std::string render_sheet_text(const Sheet& sheet);

/// A standalone SVG of 190 x 260 mm, which prints at 100% on A4 and on
/// Letter with at least 9 mm of margin on every side.
std::string render_sheet_svg(const Sheet& sheet);

enum class SheetFormat : std::uint8_t { kSvg, kText };

/// "svg" or "text"; anything else is an InputError at pos.
SheetFormat parse_sheet_format(std::string_view text, const SourcePos& pos);

}  // namespace andros::view

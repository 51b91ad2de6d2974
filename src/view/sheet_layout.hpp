#pragma once
// What the cheat sheet's parts share: the pad drawing's inputs (their order on
// the sheet and where each points on the drawing) and the SVG text helpers.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "andros/input/input_state.hpp"

namespace andros::view::sheet_detail {

/// The weapons' red: a weapon on the sheet, the weapons layer and weapon signals on the plot.
inline constexpr std::string_view kWeaponRed = "#b71c1c";

/// An input the pad drawing shows: its label column, the point of the
/// drawing its leader line ends at and the height of its label, in pad units
/// (kPadWidth x kPadHeight; a label may sit a little above the pad).
struct PadSlot {
  input::InputKey key{};
  bool right = false;
  double x = 0;
  double y = 0;
  double label_y = 0;
  bool vertical = false;  ///< the line runs level to above or below the point, then straight to it
};

inline constexpr double kPadWidth = 100;
inline constexpr double kPadHeight = 70;

/// Every input the drawing shows, left column top to bottom, then the right.
const std::vector<PadSlot>& pad_slots();

/// The input's position in pad_slots(), if the drawing shows it.
std::optional<std::size_t> pad_slot_index(input::InputKey key);

/// The schematic pad, its top-left corner at (x, y), scale mm per pad unit.
std::string draw_pad(double x, double y, double scale);

/// Text cut into lines of at most width characters, at spaces (a longer word
/// stays whole on its own line).
std::vector<std::string> wrap(const std::string& text, std::size_t width);

/// A coordinate as SVG reads it: at most two decimals, no trailing zeros.
std::string num(double value);

}  // namespace andros::view::sheet_detail

// The cheat sheet as plain text: a table per layer, for a terminal and a diff.
#include <algorithm>
#include <cctype>

#include "andros/view/sheet.hpp"
#include "sheet_layout.hpp"

namespace andros::view {
namespace {

constexpr std::size_t kInputColumn = 23;
constexpr std::size_t kMarkColumn = 9;
constexpr std::size_t kNoteWidth = 78;  // with the "- " before it: 80 columns

std::string padded(std::string text, std::size_t width) {
  text.resize(std::max(text.size() + 1, width), ' ');
  return text;
}

std::string upper(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return text;
}

}  // namespace

std::string render_sheet_text(const Sheet& sheet) {
  std::string out = (sheet.robot.empty() ? std::string("base mapping") : sheet.robot) + " cheat sheet (" + sheet.file +
                    "), made by andros-bridge sheet from the mapping\n";
  if (!sheet.deadman.empty()) {
    out += "Hold " + sheet.deadman + " (the deadman) to move anything; after connecting, press it afresh.\n";
  }
  if (!sheet.stop.empty()) {
    out += "Press " + sheet.stop + " to STOP: latched until reset on that controller (see the notes).\n";
  }
  for (const auto& panel : sheet.panels) {
    out += "\n" + upper(panel.title) + ": " + panel.how + "\n";
    out += "  " + padded("input", kInputColumn) + padded("mark", kMarkColumn) + "function\n";
    for (const auto& e : panel.entries) {
      std::string function = e.function;
      if (!e.detail.empty()) function += " (" + e.detail + ")";
      if (e.inherited) function += " [base]";
      out += "  " + padded(e.input, kInputColumn) + padded(std::string(mark_name(e.mark)), kMarkColumn) + function;
      while (!out.empty() && out.back() == ' ') out.pop_back();
      out += '\n';
    }
  }
  out += "\nNOTES\n";
  auto notes = sheet.notes;
  notes.emplace_back(
      "Marks: DEADMAN enables motion, STOP stops until reset, LAYER switches "
      "layers, ARMING is held to fire a WEAPON, TOGGLE flips on each press, KNOB moves a level while "
      "held, SELECTOR steps a rotary switch" +
      std::string(sheet.speed ? ", SPEED steps the speed level" : "") +
      ". [base]: "
      "a base binding the layer keeps. Stick and trigger switches act past half way unless a figure "
      "is given.");
  for (const auto& note : notes) {
    const auto lines = sheet_detail::wrap(note, kNoteWidth);
    for (std::size_t i = 0; i < lines.size(); ++i) out += (i == 0 ? "- " : "  ") + lines[i] + "\n";
  }
  return out;
}

}  // namespace andros::view

// The cheat sheet as one printable SVG page (docs/sheets.md): a header, one
// panel per layer (the pad with labelled leader lines, or a list for a plain
// joystick), the notes. Units are millimetres.
#include <algorithm>
#include <cctype>

#include "andros/base/sink_text.hpp"
#include "andros/view/sheet.hpp"
#include "sheet_layout.hpp"

namespace andros::view {
namespace {

using sheet_detail::num;

constexpr double kPageWidth = 190;  // fits A4 (210 x 297) and Letter (215.9 x 279.4) with margins
constexpr double kPageHeight = 260;
constexpr double kHeaderHeight = 13;
constexpr double kPanelGap = 1.2;
constexpr double kTitleBand = 5.5;
constexpr double kPadPanelHeight = 53;
constexpr double kPadScale = 0.6;  // mm per pad unit
constexpr double kPadTop = 9.5;    // below the title band, room for a label above the pad
constexpr double kLabelSize = 2.5;
constexpr double kSmallSize = 2.0;
constexpr double kListRow = 4.2;
constexpr double kListFunctionX = 38;
constexpr double kColumnGap = 3;
constexpr double kNoteSize = 2.2;
constexpr double kNoteRow = 2.9;
constexpr std::size_t kNoteWrap = 150;  // characters per note line at kNoteSize across the page
constexpr double kCharWidth = 0.56;     // of the font size: a little above the average of DejaVu Sans and Arial

std::string_view mark_colour(SheetMark mark) {
  switch (mark) {
    case SheetMark::kDeadman: return "#c62828";
    case SheetMark::kStop: return "#d50000";
    case SheetMark::kLayerKey: return "#1565c0";
    case SheetMark::kArming: return "#e65100";
    case SheetMark::kWeapon: return sheet_detail::kWeaponRed;
    case SheetMark::kToggle: return "#6a1b9a";
    case SheetMark::kKnob: return "#00695c";
    case SheetMark::kSelector: return "#2e7d32";
    case SheetMark::kSpeed: return "#4e342e";
    case SheetMark::kPlain: break;
  }
  return "#222222";
}

double label_width(const SheetEntry& e, double size) {
  const auto mark = mark_name(e.mark);
  const double chars = static_cast<double>(e.function.size()) +
                       (mark.empty() ? 0 : static_cast<double>(mark.size()) + 1.2) +
                       (e.detail.empty() ? 0 : static_cast<double>(e.detail.size() + 3) * kSmallSize / kLabelSize);
  return chars * kCharWidth * size;
}

/// One label: the mark in its colour, the function, the detail small and grey.
/// Shrunk to fit width when the estimate says it would not; when that would
/// take it below a readable size, its detail is left off (the notes say it:
/// the deadman's hold, the weapons' rule) and only the rest shrinks.
std::string label(const SheetEntry& entry, double x, double y, std::string_view anchor, double width) {
  constexpr double kMinScale = 0.85;
  SheetEntry e = entry;
  double scale = std::min(1.0, width / label_width(e, kLabelSize));
  if (scale < kMinScale && !e.detail.empty()) {
    e.detail.clear();
    scale = std::min(1.0, width / label_width(e, kLabelSize));
  }
  const double size = kLabelSize * scale;
  std::string out = "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + num(size) + "\" text-anchor=\"" +
                    std::string(anchor) + "\"" + (e.inherited ? " fill-opacity=\"0.55\"" : "") + ">";
  if (e.mark != SheetMark::kPlain) {
    out += "<tspan font-weight=\"bold\" fill=\"" + std::string(mark_colour(e.mark)) + "\">" +
           std::string(mark_name(e.mark)) + " </tspan>";
  }
  out += "<tspan fill=\"" + std::string(e.inherited ? "#555555" : "#111111") + "\"" +
         (e.inherited ? " font-style=\"italic\"" : "") + ">" + svg_text(e.function) + "</tspan>";
  if (!e.detail.empty()) {
    out +=
        "<tspan fill=\"#555555\" font-size=\"" + num(kSmallSize * scale) + "\"> (" + svg_text(e.detail) + ")</tspan>";
  }
  return out + "</text>";
}

std::string panel_frame(const SheetPanel& panel, double width, double height) {
  std::string title = panel.title;
  std::transform(title.begin(), title.end(), title.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  return "<rect x=\"0.3\" y=\"0.3\" width=\"" + num(width - 0.6) + "\" height=\"" + num(height - 0.6) +
         "\" rx=\"2\" fill=\"none\" stroke=\"#999999\" stroke-width=\"0.3\"/><rect x=\"0.3\" y=\"0.3\" width=\"" +
         num(width - 0.6) + "\" height=\"" + num(kTitleBand) +
         "\" rx=\"2\" fill=\"#e4e9f0\"/><text x=\"3\" y=\"4.3\" font-size=\"3.2\"><tspan font-weight=\"bold\">" +
         svg_text(title) + "</tspan><tspan font-size=\"2.6\" fill=\"#333333\">  " + svg_text(panel.how) +
         "</tspan></text>";
}

/// The leader line from a label at height y (mm) to its input: level to near
/// the pad's edge, then straight to the point; a vertical slot runs level to
/// above (or below) the point first.
std::string leader(const sheet_detail::PadSlot& slot, double pad_x, double pad_y, double from_x, double y) {
  const double ax = pad_x + slot.x * kPadScale;
  const double ay = pad_y + slot.y * kPadScale;
  const double edge = slot.right ? std::max(pad_x + 94 * kPadScale, ax + 2) : std::min(pad_x + 6 * kPadScale, ax - 2);
  const double elbow = slot.vertical ? ax : edge;
  return "<polyline points=\"" + num(from_x) + "," + num(y) + " " + num(elbow) + "," + num(y) + " " + num(ax) + "," +
         num(ay) + "\"/>";
}

/// The pad in the middle, the left column's labels right-aligned against it,
/// the right column's left-aligned, each at its slot's fixed height.
std::string pad_panel(const SheetPanel& panel) {
  const double pad_w = sheet_detail::kPadWidth * kPadScale;
  const double pad_x = (kPageWidth - pad_w) / 2;
  const double pad_y = kPadTop;
  const double column = pad_x - 5;  // each column's width for text
  std::string lines;
  std::string dots;
  std::string labels;
  for (const auto& slot : sheet_detail::pad_slots()) {
    const auto it =
        std::find_if(panel.entries.begin(), panel.entries.end(), [&](const auto& e) { return e.key == slot.key; });
    if (it == panel.entries.end()) continue;
    const double y = pad_y + slot.label_y * kPadScale;
    const double text_x = slot.right ? pad_x + pad_w + 2 : pad_x - 2;
    lines += leader(slot, pad_x, pad_y, slot.right ? text_x - 1 : text_x + 1, y);
    dots += "<circle cx=\"" + num(pad_x + slot.x * kPadScale) + "\" cy=\"" + num(pad_y + slot.y * kPadScale) +
            "\" r=\"0.55\"/>";
    labels += label(*it, text_x, y + 0.8, slot.right ? "start" : "end", column);
  }
  // A white halo under each line keeps it readable where it crosses the drawing.
  return panel_frame(panel, kPageWidth, kPadPanelHeight) + sheet_detail::draw_pad(pad_x, pad_y, kPadScale) +
         "<g fill=\"none\" stroke-linejoin=\"round\"><g stroke=\"#ffffff\" stroke-width=\"0.7\">" + lines +
         "</g><g stroke=\"#777777\" stroke-width=\"0.22\">" + lines + "</g></g><g fill=\"#333333\">" + dots + "</g>" +
         labels;
}

double panel_height(const Sheet& sheet, const SheetPanel& panel) {
  if (sheet.pad) return kPadPanelHeight;
  return kTitleBand + 2 + kListRow * static_cast<double>(std::max<std::size_t>(panel.entries.size(), 1));
}

/// A plain joystick's layer: input and meaning in two columns.
std::string list_panel(const Sheet& sheet, const SheetPanel& panel, double width) {
  std::string out = panel_frame(panel, width, panel_height(sheet, panel));
  double y = kTitleBand + kListRow;
  for (const auto& e : panel.entries) {
    out += "<text x=\"3\" y=\"" + num(y) + "\" font-size=\"" + num(kLabelSize) + "\" font-weight=\"bold\">" +
           svg_text(e.input) + "</text>" + label(e, kListFunctionX, y, "start", width - kListFunctionX - 2);
    y += kListRow;
  }
  return out;
}

struct Placement {
  double x = 0;
  double y = 0;
  double width = kPageWidth;
};

/// Where each panel goes (before scaling) and the scale that fits them in
/// room: one column, or for lists that do not fit, two (each panel to the
/// shorter); more than fits is drawn smaller, still on one page.
std::vector<Placement> place(const Sheet& sheet, double room, double& scale) {
  double total = 0;
  for (const auto& p : sheet.panels) total += panel_height(sheet, p) + kPanelGap;
  const bool two = !sheet.pad && total > room;
  const double width = two ? (kPageWidth - kColumnGap) / 2 : kPageWidth;
  std::vector<Placement> out;
  double column[2] = {0, 0};
  for (const auto& p : sheet.panels) {
    const int c = two && column[1] < column[0] ? 1 : 0;
    out.push_back({c * (width + kColumnGap), column[c], width});
    column[c] += panel_height(sheet, p) + kPanelGap;
  }
  scale = std::min(1.0, room / std::max(column[0], column[1]));
  return out;
}

/// The marks in their colours, how to read grey labels and thresholds.
std::string legend(const Sheet& sheet, double y) {
  std::string out = "<text x=\"0\" y=\"" + num(y) + "\" font-size=\"" + num(kNoteSize) + "\">";
  for (const auto mark : kLegendMarks) {
    if (mark == SheetMark::kSpeed && !sheet.speed) continue;
    out += "<tspan font-weight=\"bold\" fill=\"" + std::string(mark_colour(mark)) + "\">" +
           std::string(mark_name(mark)) + "</tspan>   ";
  }
  return out + "<tspan fill=\"#555555\" font-style=\"italic\">grey: a base binding the layer keeps</tspan>" +
         "</text><text x=\"0\" y=\"" + num(y + kNoteRow) + "\" font-size=\"" + num(kNoteSize) +
         "\">Stick and trigger switches act past half way unless a figure is given.</text>";
}

}  // namespace

std::string render_sheet_svg(const Sheet& sheet) {
  std::vector<std::string> notes;
  for (const auto& note : sheet.notes) {
    for (auto& line : sheet_detail::wrap(note, kNoteWrap)) notes.push_back(std::move(line));
  }
  const double footer = kNoteRow * static_cast<double>(notes.size() + 2) + 3;  // + the legend, + room below
  double scale = 1;
  const auto placements = place(sheet, kPageHeight - kHeaderHeight - footer, scale);

  const std::string robot = sheet.robot.empty() ? "base mapping" : sheet.robot;
  std::string out = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" +
                    num(kPageWidth) + "mm\" height=\"" + num(kPageHeight) + "mm\" viewBox=\"0 0 " + num(kPageWidth) +
                    " " + num(kPageHeight) +
                    "\" xml:space=\"preserve\" font-family=\"DejaVu Sans, Arial, Helvetica, sans-serif\">\n";
  out += "<title>" + svg_text(robot + " cheat sheet (" + sheet.file + ")") + "</title>\n";
  out += "<rect width=\"" + num(kPageWidth) + "\" height=\"" + num(kPageHeight) + "\" fill=\"#ffffff\"/>\n";
  out += "<text x=\"0\" y=\"6\" font-size=\"5.5\" font-weight=\"bold\">" + svg_text(robot) +
         " cheat sheet</text><text x=\"" + num(kPageWidth) +
         "\" y=\"6\" font-size=\"2.6\" text-anchor=\"end\" "
         "fill=\"#555555\">" +
         svg_text(sheet.file) + ", made by andros-bridge sheet</text>\n";
  if (!sheet.deadman.empty()) {
    out +=
        "<text x=\"0\" y=\"11.5\" font-size=\"3\">Hold <tspan font-weight=\"bold\" fill=\"#c62828\">" +
        svg_text(sheet.deadman) +
        (sheet.stop.empty() ? std::string("</tspan> (the deadman) to move anything; after connecting, press it afresh. "
                                          "Releasing it stops everything.")
                            : "</tspan> (the deadman) to move anything; press it afresh after connecting. "
                              "<tspan font-weight=\"bold\" fill=\"#d50000\">" +
                                  svg_text(sheet.stop) + "</tspan> = STOP (latched: see the notes).") +
        "</text>\n";
  }
  const double x = (kPageWidth - kPageWidth * scale) / 2;
  for (std::size_t i = 0; i < sheet.panels.size(); ++i) {
    const auto& at = placements[i];
    out += "<g transform=\"translate(" + num(x + at.x * scale) + " " + num(kHeaderHeight + at.y * scale) + ") scale(" +
           num(scale) + ")\">" +
           (sheet.pad ? pad_panel(sheet.panels[i]) : list_panel(sheet, sheet.panels[i], at.width)) + "</g>\n";
  }
  double y = kPageHeight - footer + kNoteRow;
  out += legend(sheet, y) + "\n";
  y += kNoteRow;
  for (const auto& line : notes) {
    y += kNoteRow;
    out += "<text x=\"0\" y=\"" + num(y) + "\" font-size=\"" + num(kNoteSize) + "\">" + svg_text(line) + "</text>\n";
  }
  return out + "</svg>\n";
}

}  // namespace andros::view

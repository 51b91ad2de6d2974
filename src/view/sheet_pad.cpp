// The cheat sheet's pad: a schematic SDL game controller (Xbox layout) and
// the point on it each label's leader line ends at.
#include <cmath>
#include <cstdio>
#include <utility>

#include "sheet_layout.hpp"

namespace andros::view::sheet_detail {
namespace {

using input::InputKey;
using input::InputKind;

InputKey button(std::string_view name) { return *input::parse_button_name(name); }
InputKey axis(std::string_view name) { return *input::parse_axis_name(name); }

// Where things are, in pad units.
constexpr double kLeftStickX = 27, kLeftStickY = 30;
constexpr double kRightStickX = 62, kRightStickY = 48;
constexpr double kDpadX = 38, kDpadY = 48, kDpadArm = 5.5, kDpadLength = 16;
constexpr double kFaceX = 75, kFaceY = 31, kFaceStep = 7.5, kFaceRadius = 3.4;
constexpr double kStickRadius = 7.5;
constexpr double kBackX = 42, kStartX = 58, kSmallY = 24, kSmallRadius = 2.4;
constexpr double kGuideX = 50, kGuideY = 22, kGuideRadius = 3.4;

std::string circle(double cx, double cy, double r, std::string_view extra = {}) {
  return "<circle cx=\"" + num(cx) + "\" cy=\"" + num(cy) + "\" r=\"" + num(r) + "\"" + std::string(extra) + "/>";
}

std::string rect(double x, double y, double w, double h, double rx) {
  return "<rect x=\"" + num(x) + "\" y=\"" + num(y) + "\" width=\"" + num(w) + "\" height=\"" + num(h) + "\" rx=\"" +
         num(rx) + "\"/>";
}

std::string text(double x, double y, double size, std::string_view s) {
  return "<text x=\"" + num(x) + "\" y=\"" + num(y) + "\" font-size=\"" + num(size) + "\" text-anchor=\"middle\">" +
         std::string(s) + "</text>";
}

// The body: a bar and two grips, drawn as one outline (each shape stroked
// wide, then all filled over the inner half of the strokes).
std::string body_shapes() {
  return rect(8, 13, 84, 31, 15) + "<ellipse cx=\"24\" cy=\"48\" rx=\"15\" ry=\"20\" transform=\"rotate(18 24 48)\"/>" +
         "<ellipse cx=\"76\" cy=\"48\" rx=\"15\" ry=\"20\" transform=\"rotate(-18 76 48)\"/>";
}

std::string stick(double cx, double cy) {
  return circle(cx, cy, kStickRadius, " fill=\"#ffffff\"") + circle(cx, cy, 4.6, " fill=\"#d0d0d0\"");
}

std::string dpad() {
  const double arm = kDpadArm;
  const double len = kDpadLength;
  return "<path fill=\"#ffffff\" d=\"M" + num(kDpadX - arm / 2) + " " + num(kDpadY - len / 2) + " h" + num(arm) + " v" +
         num((len - arm) / 2) + " h" + num((len - arm) / 2) + " v" + num(arm) + " h" + num(-(len - arm) / 2) + " v" +
         num((len - arm) / 2) + " h" + num(-arm) + " v" + num(-(len - arm) / 2) + " h" + num(-(len - arm) / 2) + " v" +
         num(-arm) + " h" + num((len - arm) / 2) + " Z\"/>";
}

}  // namespace

// Each label's height is fixed (7.2 units apart in a column) and chosen with
// its route so that no leader line crosses another input: Back, Start, the
// guide button and D-pad right are reached from above or below (vertical).
const std::vector<PadSlot>& pad_slots() {
  constexpr double kArm = kDpadArm / 2;
  static const std::vector<PadSlot> slots = {
      {axis("lefttrigger"), false, 16.3, 3, -1, false},
      {button("leftshoulder"), false, 14.2, 9.5, 6.2, false},
      {button("back"), false, kBackX, kSmallY - kSmallRadius, 15.5, true},
      {axis("lefty"), false, kLeftStickX, kLeftStickY - kStickRadius, 22.8, false},
      {axis("leftx"), false, kLeftStickX - kStickRadius, kLeftStickY, 30.1, false},
      {button("leftstick"), false, kLeftStickX - 2.5, kLeftStickY + 3.5, 37.4, false},
      {button("dpup"), false, kDpadX, kDpadY - kDpadLength / 2 + 0.5, 44.7, false},
      {button("dpleft"), false, kDpadX - kDpadLength / 2 + 0.5, kDpadY, 52, false},
      {button("dpdown"), false, kDpadX, kDpadY + kDpadLength / 2 - 0.5, 59.3, false},
      {button("dpright"), false, kDpadX + kDpadLength / 2 - 2, kDpadY + kArm, 66.6, true},
      {button("guide"), true, kGuideX, kGuideY - kGuideRadius, -2.5, true},
      {axis("righttrigger"), true, 83.7, 3, 4.7, false},
      {button("rightshoulder"), true, 85.8, 9.5, 11.9, false},
      {button("start"), true, kStartX, kSmallY - kSmallRadius, 18.3, true},
      {button("y"), true, kFaceX + kFaceRadius, kFaceY - kFaceStep, 25.5, false},
      {button("b"), true, kFaceX + kFaceStep + kFaceRadius, kFaceY, 32.7, false},
      {button("x"), true, kFaceX - kFaceStep + 2.4, kFaceY + 2.4, 39.9, false},
      {button("a"), true, kFaceX + 2.4, kFaceY + kFaceStep + 2.4, 47.1, false},
      {axis("righty"), true, kRightStickX, kRightStickY - kStickRadius, 54.3, false},
      {axis("rightx"), true, kRightStickX + kStickRadius, kRightStickY, 61.5, false},
      {button("rightstick"), true, kRightStickX + 2.5, kRightStickY + 3.5, 68.7, false},
  };
  return slots;
}

std::optional<std::size_t> pad_slot_index(input::InputKey key) {
  const auto& slots = pad_slots();
  for (std::size_t i = 0; i < slots.size(); ++i) {
    if (slots[i].key == key) return i;
  }
  return std::nullopt;
}

std::string draw_pad(double x, double y, double scale) {
  std::string out = "<g transform=\"translate(" + num(x) + " " + num(y) + ") scale(" + num(scale) +
                    ")\" stroke=\"#444444\" stroke-width=\"0.6\">";
  out += "<g fill=\"#ffffff\">" + rect(16, 0, 16, 8, 3) + rect(68, 0, 16, 8, 3) + rect(14, 6, 22, 6, 3) +
         rect(64, 6, 22, 6, 3) + "</g>";
  out += "<g fill=\"none\" stroke-width=\"1.6\">" + body_shapes() + "</g>";
  out += "<g fill=\"#eeeeee\" stroke=\"none\">" + body_shapes() + "</g>";
  out += stick(kLeftStickX, kLeftStickY) + stick(kRightStickX, kRightStickY) + dpad();
  out += "<g fill=\"#ffffff\">" + circle(kBackX, kSmallY, kSmallRadius) + circle(kStartX, kSmallY, kSmallRadius) +
         circle(kGuideX, kGuideY, kGuideRadius) + circle(kFaceX, kFaceY - kFaceStep, kFaceRadius) +
         circle(kFaceX - kFaceStep, kFaceY, kFaceRadius) + circle(kFaceX + kFaceStep, kFaceY, kFaceRadius) +
         circle(kFaceX, kFaceY + kFaceStep, kFaceRadius) + "</g>";
  out += "<g fill=\"#333333\" stroke=\"none\" font-weight=\"bold\">" +
         text(kFaceX, kFaceY - kFaceStep + 1.3, 3.6, "Y") + text(kFaceX - kFaceStep, kFaceY + 1.3, 3.6, "X") +
         text(kFaceX + kFaceStep, kFaceY + 1.3, 3.6, "B") + text(kFaceX, kFaceY + kFaceStep + 1.3, 3.6, "A") +
         text(24, 5.2, 3.2, "LT") + text(76, 5.2, 3.2, "RT") + text(25, 10.6, 3.2, "LB") + text(75, 10.6, 3.2, "RB") +
         "</g>";
  out += "<g fill=\"#555555\" stroke=\"none\">" + text(kBackX, kSmallY + 5.4, 2.4, "back") +
         text(kStartX, kSmallY + 5.4, 2.4, "start") + text(kGuideX, kGuideY + 7, 2.4, "guide") + "</g>";
  return out + "</g>";
}

std::vector<std::string> wrap(const std::string& text, std::size_t width) {
  std::vector<std::string> lines;
  std::string line;
  std::size_t start = 0;
  while (start < text.size()) {
    auto end = text.find(' ', start);
    if (end == std::string::npos) end = text.size();
    const auto word = text.substr(start, end - start);
    if (!line.empty() && line.size() + 1 + word.size() > width) lines.push_back(std::exchange(line, ""));
    line += (line.empty() ? "" : " ") + word;
    start = end + 1;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

std::string num(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", std::round(value * 100) / 100);
  std::string s = buf;
  while (s.back() == '0') s.pop_back();
  if (s.back() == '.') s.pop_back();
  return s == "-0" ? "0" : s;
}

}  // namespace andros::view::sheet_detail

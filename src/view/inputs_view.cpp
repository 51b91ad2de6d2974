#include "andros/view/inputs_view.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "andros/base/text.hpp"
#include "andros/mapping/axis.hpp"
#include "format.hpp"

namespace andros::view {
namespace {

using detail::fmt;
using input::InputKey;
using input::InputKind;

constexpr int kMinBarHalf = 5;
constexpr int kMaxBarHalf = 10;  ///< 1/10 of the way a cell: enough to see a deadzone of 0.1 at work
/// An axis line's width without its bar's cells, and with room for its limit
/// ("deadzone 0.00 (default)"): the bar grows only where that still fits.
constexpr std::size_t kAxisFixed = 70;
constexpr std::size_t kButtonWidth = 19;  ///< " *  11 rightshoulder"

bool is_axis(InputKey key) { return key.kind == InputKind::kPadAxis || key.kind == InputKind::kJoyAxis; }
bool is_trigger(InputKey key) { return key.kind == InputKind::kPadAxis && key.index >= 4; }

std::string signal_name(protocol::SignalId id) { return std::string(protocol::info(id).name); }

/// The axis a binding reads and how, if it reads one.
std::optional<std::pair<InputKey, AxisUse>> read_by(const mapping::BindingRule& rule) {
  using R = AxisUse::Rest;
  using Use = std::pair<InputKey, AxisUse>;
  if (const auto* a = std::get_if<mapping::AxisBinding>(&rule)) {
    return Use{a->axis, {R::kDeadzone, a->shape.deadzone, a->shape.invert, signal_name(a->analog), ""}};
  }
  if (const auto* p = std::get_if<mapping::PairBinding>(&rule)) {
    return Use{p->axis,
               {R::kBand, p->threshold, p->invert, signal_name(p->signals[0]) + "/" + signal_name(p->signals[1]), ""}};
  }
  if (const auto* b = std::get_if<mapping::ButtonBinding>(&rule); b != nullptr && is_axis(b->input)) {
    return Use{b->input, {R::kThreshold, b->threshold, b->invert, signal_name(b->signal), ""}};
  }
  if (const auto* w = std::get_if<mapping::WeaponBinding>(&rule); w != nullptr && w->arm && is_axis(*w->arm)) {
    return Use{*w->arm, {R::kThreshold, mapping::kDefaultThreshold, false, "arms " + signal_name(w->signal), ""}};
  }
  return std::nullopt;
}

/// "moves"/"on" when the mapping would act on this value, else "at rest".
const char* reading(const AxisUse& use, std::int16_t value) {
  double x = mapping::normalise_axis(value);
  if (use.invert) x = -x;
  switch (use.rest) {
    case AxisUse::Rest::kDeadzone: return std::fabs(x) > use.limit ? "moves" : "at rest";
    case AxisUse::Rest::kBand: return std::fabs(x) >= use.limit ? "on" : "at rest";
    case AxisUse::Rest::kThreshold: return x >= use.limit ? "on" : "at rest";
  }
  return "";
}

/// "deadzone 0.10 drive", "threshold 0.50 zoom_up in layer camera".
std::string limit_text(const AxisUse& use) {
  std::string out = fmt("%s %.2f", use.rest == AxisUse::Rest::kDeadzone ? "deadzone" : "threshold", use.limit);
  if (use.signal.empty()) return out + " (default)";
  return out + " " + use.signal + (use.layer.empty() ? "" : " in layer " + use.layer);
}

/// "a #0" for a pad input, "3" for a joystick's.
std::string input_label(InputKey key) {
  const std::string name = input::input_name(key);
  return key.kind == InputKind::kPadButton || key.kind == InputKind::kPadAxis ? name + " #" + std::to_string(key.index)
                                                                              : name;
}

std::string hat_text(int mask) {
  if (mask == 0) return "centred";
  std::string out;
  for (std::size_t d = 0; d < input::kHatDirectionNames.size(); ++d) {
    if ((mask & (1 << d)) == 0) continue;
    if (!out.empty()) out += "+";
    out += input::kHatDirectionNames[d];
  }
  return out;
}

/// A bar of 2*half+1 cells: a stick's grows from the middle, a trigger's from the left.
std::string bar(InputKey key, std::int16_t value, int half) {
  std::string out(static_cast<std::size_t>(2 * half + 1), ' ');
  const double x = mapping::normalise_axis(value);
  if (is_trigger(key)) {  // 0..32767, from the left
    const int n = static_cast<int>(std::lround(std::max(0.0, x) * 2 * half));
    for (int i = 0; i < n; ++i) out[static_cast<std::size_t>(i + 1)] = '=';
    out[0] = '|';
    return "[" + out + "]";
  }
  const int n = static_cast<int>(std::lround(x * half));
  for (int i = std::min(0, n); i <= std::max(0, n); ++i) out[static_cast<std::size_t>(half + i)] = '=';
  out[static_cast<std::size_t>(half)] = '|';
  return "[" + out + "]";
}

std::string device_text(const input::DeviceLayout& d) {
  return printable_text(d.name) + " (" + (d.game_controller ? "game controller" : "joystick") + ", GUID " +
         printable_text(d.guid) + ")";
}

void append_axis(std::string& out, const input::InputState& state, InputKey key, const AxisUses& uses, int half) {
  const std::int16_t v = state.axis(key);
  const AxisUse use = axis_use(uses, key);
  // The verdict before the limit: a narrow screen cuts the signal's name, not
  // it. The value from -1 to 1 beside the bar, to read a deadzone against.
  out += fmt("  %3u %-12s %6d %6.3f %s %-7s ", static_cast<unsigned>(key.index), input::input_name(key).c_str(), v,
             mapping::normalise_axis(v), bar(key, v, half).c_str(), reading(use, v));
  out += limit_text(use) + "\n";
}

void append_hat(std::string& out, const input::InputState& state, int hat) {
  out += fmt("  %3d %-12s %s\n", hat, ("hat" + std::to_string(hat)).c_str(), hat_text(state.hat(hat)).c_str());
}

constexpr std::size_t kHang = 6;  ///< a wrapped line's continuations: under an axis line's name, past its number
/// The shortest fit() cuts a word to: a binding's name such as
/// pt_left/pt_right stays whole, a path keeps its file name.
constexpr std::size_t kShortestWord = 16;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  for (std::size_t from = 0; from < text.size();) {
    const auto end = std::min(text.find('\n', from), text.size());
    lines.push_back(text.substr(from, end - from));
    from = end + 1;
  }
  return lines;
}

std::vector<std::string> wrapped(const std::vector<std::string>& lines, std::size_t width) {
  std::vector<std::string> out;
  for (const auto& line : lines) {
    for (auto& part : wrap_text(line, width, kHang)) out.push_back(std::move(part));
  }
  return out;
}

bool too_wide(const std::string& line, std::size_t width) { return wrap_text(line, width, kHang).size() > 1; }

/// line with each word longer than cap cut in its middle to cap (cut_middle),
/// but for a word with no letter in it (a bar, a number): the columns stay.
std::string shorten_words(const std::string& line, std::size_t cap) {
  std::string out;
  for (std::size_t at = 0; at < line.size();) {
    const auto end = std::min(line.find(' ', at), line.size());
    const auto word = std::string_view(line).substr(at, end - at);
    const bool named =
        std::any_of(word.begin(), word.end(), [](unsigned char c) { return std::isalpha(c) != 0 || c >= 0x80; });
    out += named ? cut_middle(word, cap) : std::string(word);
    if (end < line.size()) out += ' ';
    at = end + 1;
  }
  return out;
}

/// The lines too wide for width with their words shortened to cap.
std::vector<std::string> shortened(const std::vector<std::string>& lines, std::size_t width, std::size_t cap) {
  std::vector<std::string> out;
  out.reserve(lines.size());
  for (const auto& line : lines) out.push_back(too_wide(line, width) ? shorten_words(line, cap) : line);
  return out;
}

/// The longest word of the lines too wide for width, in bytes.
std::size_t longest_word(const std::vector<std::string>& lines, std::size_t width) {
  std::size_t longest = 0;
  for (const auto& line : lines) {
    if (!too_wide(line, width)) continue;
    for (std::size_t at = 0, end = 0; at < line.size(); at = end + 1) {
      end = std::min(line.find(' ', at), line.size());
      longest = std::max(longest, end - at);
    }
  }
  return longest;
}

/// The lines of text, each wrapped to width under its text (a long path, a
/// binding's or a layer's name: shown whole) while that leaves them within
/// the rows; else, first, without the blank lines; then with the long words
/// of the lines too wide (a path, a name) cut in their middle, no more than
/// the rows need; and only when that is not enough, each line cut to width
/// (every input still shown: the triggers, the last column of buttons).
std::string fit(const std::string& text, TermSize size) {
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  const auto rows = static_cast<std::size_t>(std::max(size.rows, 1));
  auto lines = split_lines(text);
  auto out = wrapped(lines, width);
  if (out.size() > rows) {
    std::erase_if(lines, [](const std::string& line) { return line.empty(); });
    out = wrapped(lines, width);
  }
  if (const auto longest = longest_word(lines, width); out.size() > rows && longest > kShortestWord) {
    // The longest cap that fits: each word cut as little as the rows need.
    std::size_t cap = kShortestWord;
    for (std::size_t low = kShortestWord + 1, high = longest - 1; low <= high;) {
      const auto mid = low + (high - low) / 2;
      if (wrapped(shortened(lines, width, mid), width).size() <= rows) {
        cap = mid;
        low = mid + 1;
      } else {
        high = mid - 1;
      }
    }
    lines = shortened(lines, width, cap);
    out = wrapped(lines, width);
  }
  if (out.size() > rows) {
    out.clear();
    for (const auto& line : lines) out.push_back(line.substr(0, std::min(line.size(), width)));
  }
  std::string screen;
  for (const auto& line : out) screen += line + "\n";
  return screen;
}

}  // namespace

AxisUses axis_uses(const mapping::Mapping& mapping) {
  AxisUses uses;
  if (mapping.deadman && is_axis(mapping.deadman->key)) {
    uses[mapping.deadman->key] = {AxisUse::Rest::kThreshold, mapping::kDefaultThreshold, false, "deadman", ""};
  }
  for (const auto ref : mapping::all_bindings(mapping)) {
    auto use = read_by(mapping::binding_at(mapping, ref).rule);
    if (!use) continue;
    if (ref.layer >= 0) use->second.layer = printable_text(mapping.layers[static_cast<std::size_t>(ref.layer)].name);
    uses.emplace(use->first, use->second);  // the first reader wins
  }
  return uses;
}

AxisUse axis_use(const AxisUses& uses, InputKey axis) {
  const auto it = uses.find(axis);
  return it == uses.end() ? AxisUse{} : it->second;
}

std::string format_input_change(const input::InputEvent& e, const AxisUses& uses,
                                const std::optional<input::DeviceLayout>& layout) {
  using T = input::InputEvent::Type;
  const std::string t = std::to_string(e.t_ms) + " ";
  switch (e.type) {
    case T::kConnect: return t + "connect " + (layout ? device_text(*layout) : printable_text(e.name));
    case T::kDisconnect: return t + "disconnect";
    case T::kButton: return t + "button " + input_label(e.key) + (e.value != 0 ? " down" : " up");
    case T::kAxis: {
      const auto v = static_cast<std::int16_t>(e.value);
      const AxisUse use = axis_use(uses, e.key);
      return t + (is_trigger(e.key) ? "trigger " : "axis ") + input_label(e.key) +
             fmt(" %d %.3f ", v, mapping::normalise_axis(v)) + limit_text(use) + ": " + reading(use, v);
    }
    case T::kHat: return t + "hat " + std::to_string(e.key.index / 4) + " " + hat_text(e.value);
    default: break;  // end and the fault events: not from a controller
  }
  return t + "end";
}

std::string render_inputs_screen(const input::InputState& state, const std::optional<input::DeviceLayout>& layout,
                                 const AxisUses& uses, const std::string& heading, TermSize size) {
  std::string out = heading + "\n";
  if (!layout || !state.connected()) return fit(out + "controller: none connected, waiting\n", size);
  // The grid and the bars follow the width.
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  const auto per_row = std::max<std::size_t>(1, width / kButtonWidth);
  const int half =
      std::clamp(static_cast<int>(width > kAxisFixed ? (width - kAxisFixed) / 2 : 0), kMinBarHalf, kMaxBarHalf);
  // The GUID apart: a long name must not push it off the screen.
  out += "controller: " + printable_text(layout->name) +
         (layout->game_controller ? " (game controller)" : " (joystick)") + "\n  GUID " + printable_text(layout->guid) +
         "\n\nbuttons (* held)\n";
  std::size_t column = 0;
  for (const auto key : layout->buttons) {
    out += fmt(" %c%3u %-13s", state.button(key).down ? '*' : ' ', static_cast<unsigned>(key.index),
               input::input_name(key).c_str());
    if (++column % per_row == 0) out += "\n";
  }
  if (column % per_row != 0) out += "\n";
  if (layout->game_controller && layout->buttons.size() < input::kPadButtonNames.size()) {
    std::string missing;
    for (std::size_t b = 0; b < input::kPadButtonNames.size(); ++b) {
      const InputKey key{InputKind::kPadButton, static_cast<std::uint16_t>(b)};
      if (std::find(layout->buttons.begin(), layout->buttons.end(), key) == layout->buttons.end()) {
        missing += " " + input::input_name(key);
      }
    }
    out += "  not in its SDL mapping:" + missing + "\n";
  }
  out += "\naxes               value   -1..1\n";
  for (const auto key : layout->axes) {
    if (!is_trigger(key)) append_axis(out, state, key, uses, half);
  }
  if (layout->game_controller) {
    out += "triggers\n";
    for (const auto key : layout->axes) {
      if (is_trigger(key)) append_axis(out, state, key, uses, half);
    }
  }
  if (layout->hats > 0) {
    out += "hats\n";
    for (int h = 0; h < layout->hats; ++h) append_hat(out, state, h);
  }
  if (!layout->free_hats.empty()) {
    out += "hats outside its SDL mapping (bind them as hatNup, ...)\n";
    for (const int h : layout->free_hats) append_hat(out, state, h);
  }
  return fit(out, size);
}

}  // namespace andros::view

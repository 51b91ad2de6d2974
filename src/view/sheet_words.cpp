#include "sheet_words.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string_view>

#include "andros/protocol/words.hpp"

namespace andros::view::sheet_detail {
namespace {

using input::InputKey;
using input::InputKind;

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

std::string percent(double fraction) { return std::to_string(static_cast<int>(std::lround(fraction * 100))) + "%"; }

}  // namespace

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

std::string direction(InputKey axis, bool invert, bool positive) {
  const bool raw_positive = positive != invert;
  if (axis.kind != InputKind::kPadAxis) return raw_positive ? "positive" : "negative";
  if (is_trigger(axis)) return raw_positive ? "squeezed" : "below 0";
  const bool vertical = axis.index % 2 == 1;
  if (vertical) return raw_positive ? "down" : "up";
  return raw_positive ? "right" : "left";
}

std::string signal_words(protocol::SignalId id) { return std::string(protocol::words(id).words); }

std::string spoken(std::string text) {
  std::replace(text.begin(), text.end(), '_', ' ');
  return text;
}

std::string figure(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", value);
  return text;
}

std::string exact_percent(double fraction) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g%%", fraction * 100);
  return buf;
}

std::string past(double threshold) {
  return threshold == mapping::kDefaultThreshold ? "" : "past " + percent(threshold);
}

std::string deadman_detail(const mapping::Mapping& m) {
  std::string detail = m.deadman->key.is_button() ? "" : "past half way";
  if (m.deadman_panic) {
    char panic[64];
    std::snprintf(panic, sizeof panic, "; off past %.0f%% until fully released", *m.deadman_panic * 100.0);
    detail += panic;
  }
  return detail;
}

}  // namespace andros::view::sheet_detail

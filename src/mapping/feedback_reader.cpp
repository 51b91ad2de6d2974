#include "feedback_reader.hpp"

#include <string>

namespace andros::mapping {
namespace {

constexpr std::string_view kOff = "off";

bool is_off(const YAML::Node& node) { return node.IsScalar() && node.Scalar() == kOff; }

std::uint8_t channel(const yaml::Reader& r, const YAML::Node& node) {
  return static_cast<std::uint8_t>(r.integer(node, 0, 255, "a colour channel"));
}

void read_pattern(const yaml::Reader& r, const YAML::Node& n, input::FeedbackPattern& p) {
  r.expect_keys(n, {"low", "high", "ms", "pulses", "led"}, "a feedback pattern");
  if (n["low"]) p.low = r.number(n["low"], 0.0, 1.0, false, "low (rumble strength)");
  if (n["high"]) p.high = r.number(n["high"], 0.0, 1.0, false, "high (rumble strength)");
  if (n["ms"]) p.ms = static_cast<int>(r.integer(n["ms"], 1, input::kMaxFeedbackMs, "ms (pulse length)"));
  if (n["pulses"]) p.pulses = static_cast<int>(r.integer(n["pulses"], 1, input::kMaxFeedbackPulses, "pulses"));
  if (const auto led = n["led"]) {
    if (is_off(led)) {
      p.led.reset();
    } else {
      if (!led.IsSequence() || led.size() != 3) r.fail(led, "led is [RED, GREEN, BLUE] (each 0..255) or 'off'");
      p.led = std::array<std::uint8_t, 3>{channel(r, led[0]), channel(r, led[1]), channel(r, led[2])};
    }
  }
}

}  // namespace

void read_feedback(const yaml::Reader& r, const YAML::Node& node, FeedbackTable& table) {
  if (is_off(node)) {
    for (auto& p : table.patterns) p.reset();
    return;
  }
  if (!node.IsMap()) r.fail(node, "feedback is 'off' or a map of events to patterns");
  r.expect_keys(node,
                {"deadman_refused", "link_lost", "disabled", "weapons_on", "weapons_off", "enabled", "controller_back",
                 "speed_level"},
                "feedback");
  for (std::size_t i = 0; i < kFeedbackEventCount; ++i) {
    const auto event = static_cast<FeedbackEvent>(i);
    const auto n = node[std::string(feedback_event_name(event))];
    if (!n) continue;
    auto& pattern = table[event];
    if (is_off(n)) {
      pattern.reset();
      continue;
    }
    if (event == FeedbackEvent::kSpeedLevel && n.IsMap() && n["pulses"]) {
      r.fail(n["pulses"], "speed_level plays one pulse per level (level 3: three pulses); it takes no 'pulses'");
    }
    // Keys left out keep the pattern in force (the base file's, or the built-in one).
    if (!pattern) pattern = default_feedback_pattern(event);
    read_pattern(r, n, *pattern);
  }
}

}  // namespace andros::mapping

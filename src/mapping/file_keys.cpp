#include "file_keys.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "andros/base/text.hpp"
#include "andros/protocol/robots.hpp"
#include "binding_reader.hpp"
#include "feedback_reader.hpp"

namespace andros::mapping {
namespace {

using yaml::Reader;

/// A trim of drive and pivot's rest while enabled, within the band of model.hpp.
int read_center(const Reader& r, const YAML::Node& node) {
  const auto value =
      r.integer(node, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max(), "center");
  if (value < kCenterTrimMin || value > kCenterTrimMax) r.fail(node, center_out_of_band(r.text(node, "center")));
  return static_cast<int>(value);
}

/// `scale: {button: B, down: B, levels: [...], initial: L}` (docs/mapping.md, `scale`).
SpeedScale read_scale(const Reader& r, const YAML::Node& n) {
  r.expect_keys(n, {"button", "down", "levels", "initial"}, "scale");
  if (!n["levels"]) r.fail(n, "scale needs 'levels': a list of fractions of full speed, such as [0.25, 0.5, 1.0]");
  SpeedScale s;
  s.pos = r.pos(n);
  const auto levels = n["levels"];
  r.expect_list(levels, "levels");
  if (levels.size() == 0) r.fail(levels, "levels lists at least one fraction of full speed");
  if (levels.size() > kMaxSpeedLevels) {
    r.fail(levels,
           "at most " + std::to_string(kMaxSpeedLevels) + " levels (a change is counted out in as many rumble pulses)");
  }
  s.levels.clear();
  for (const auto& l : levels) {
    const double v = r.number(l, 0.0, 1.0, false, "a level");
    if (v <= 0.0) r.fail(l, "a level is a fraction of full speed above 0, not " + r.text(l, "a level"));
    if (!s.levels.empty() && v <= s.levels.back()) {
      r.fail(l,
             "levels go from the slowest to the fastest: " + r.text(l, "a level") + " is not above the one before it");
    }
    s.levels.push_back(v);
  }
  if (n["button"]) s.up = input_use(r, n["button"], r.button(n["button"]));
  if (n["down"]) {
    if (!s.up) r.fail(n, "scale has 'down' but no 'button' to step up");
    s.down = input_use(r, n["down"], r.button(n["down"]));
  }
  if (s.levels.size() > 1 && !s.up)
    r.fail(n, "scale with more than one level needs 'button': the button that steps through them");
  if (s.levels.size() == 1 && s.up)
    r.fail(n["button"], "scale has one level: there is nothing for 'button' to step to");
  if (const auto i = n["initial"]) {
    const double v = r.number(i, 0.0, 1.0, false, "initial");
    const auto it = std::find(s.levels.begin(), s.levels.end(), v);
    if (it == s.levels.end()) r.fail(i, "initial " + r.text(i, "initial") + " is not one of the levels");
    s.initial = static_cast<std::size_t>(it - s.levels.begin());
  }
  return s;
}

/// A reset gesture: `BUTTON`, or `[BUTTON, BUTTON]` held together (a chord).
std::vector<InputUse> read_reset(const Reader& r, const YAML::Node& n, const std::string& what) {
  std::vector<InputUse> keys;
  if (!n.IsSequence()) {
    keys.push_back(input_use(r, n, r.button(n)));
    return keys;
  }
  if (n.size() == 0 || n.size() > kMaxResetChord) {
    r.fail(n, what + " is one button, or a chord of " + std::to_string(kMaxResetChord) +
                  " buttons held together ([back, start])");
  }
  for (const auto& b : n) {
    auto use = input_use(r, b, r.button(b));
    for (const auto& k : keys) {
      if (k.key == use.key) r.fail(b, "'" + input::input_name(use.key) + "' is twice in " + what);
    }
    keys.push_back(use);
  }
  return keys;
}

SupervisorButtons read_supervisor(const Reader& r, const YAML::Node& n) {
  r.expect_map(n, "the supervisor section");
  r.expect_keys(n, {"stop", "reset", "weapons_consent"}, "the supervisor section");
  if (!n["stop"]) r.fail(n, "the supervisor section needs 'stop: BUTTON': the supervisor's stop button");
  SupervisorButtons s;
  s.pos = r.pos(n);
  s.stop = input_use(r, n["stop"], r.button(n["stop"]));
  if (n["reset"]) s.reset = read_reset(r, n["reset"], "the supervisor's reset");
  if (n["weapons_consent"]) s.weapons_consent = input_use(r, n["weapons_consent"], r.button(n["weapons_consent"]));
  return s;
}

}  // namespace

void read_file_keys(const Reader& r, const YAML::Node& root, Mapping& m, ErrorList& errors) {
  if (root["robot"]) {
    errors.attempt([&] {
      const auto name = r.text(root["robot"], "robot");
      m.robot = protocol::canonical_robot(name);
      if (!m.robot)
        r.fail(root["robot"], "unknown robot " + quote(name) + " (expected " + protocol::robot_list() + ")");
      m.robot_pos = r.pos(root["robot"]);
    });
  }
  if (const auto c = root["center"]) errors.attempt([&] { m.center = read_center(r, c); });
  if (const auto c = root["constants"]) {
    errors.attempt([&] {
      r.expect_keys(c, {"byte12", "battery"}, "constants");
      if (c["byte12"])
        m.byte12 = static_cast<std::uint8_t>(r.integer(c["byte12"], 0, protocol::kWholeByteMax, "byte12"));
      if (c["battery"])
        m.battery = static_cast<std::uint8_t>(r.integer(c["battery"], 0, protocol::kWholeByteMax, "battery"));
    });
  }
  if (root["deadman"]) {
    errors.attempt([&] { m.deadman = input_use(r, root["deadman"], r.button_or_trigger(root["deadman"], "deadman")); });
  }
  if (const auto p = root["deadman_panic"]) {
    errors.attempt([&] {
      m.deadman_panic = r.number(p, kDeadmanPanicMin, 1.0, true, "deadman_panic");
      if (*m.deadman_panic <= kDeadmanPanicMin) {
        r.fail(p, "deadman_panic must lie above the trigger's press point (0.5) and below full travel (1.0)");
      }
      m.deadman_panic_pos = r.pos(p);
    });
  }
  if (const auto e = root["estop"]) errors.attempt([&] { m.estop = input_use(r, e, r.button(e)); });
  if (const auto s = root["stop_reset"]) errors.attempt([&] { m.stop_reset = read_reset(r, s, "stop_reset"); });
  if (const auto h = root["stop_reset_hold"]) {
    errors.attempt([&] {
      m.stop_reset_hold_ms =
          std::llround(r.number(h, kStopResetHoldMinS, kStopResetHoldMaxS, false, "stop_reset_hold") * 1000.0);
    });
  }
  if (const auto t = root["enable_timeout"]) {
    errors.attempt([&] {
      if (r.text(t, "enable_timeout") == "off") {
        m.enable_timeout_ms.reset();  // a base's timeout switched off
        return;
      }
      const double seconds = r.number(t, kEnableTimeoutMinS, kEnableTimeoutMaxS, false, "enable_timeout");
      m.enable_timeout_ms = std::llround(seconds * 1000.0);
    });
  }
  if (const auto sup = root["supervisor"]) errors.attempt([&] { m.supervisor = read_supervisor(r, sup); });
  if (const auto b = root["brake"]) {
    errors.attempt([&] {
      const auto mode = r.text(b, "brake");
      if (mode == "enabled") m.brake = BrakeMode::kEnabled;
      else if (mode == "moving") m.brake = BrakeMode::kMoving;
      else r.fail(b, "brake must be 'enabled' or 'moving', not " + quote(mode));
    });
  }
  if (const auto s = root["scale"]) errors.attempt([&] { m.scale = read_scale(r, s); });
  if (root["feedback"]) errors.attempt([&] { read_feedback(r, root["feedback"], m.feedback); });
}

}  // namespace andros::mapping

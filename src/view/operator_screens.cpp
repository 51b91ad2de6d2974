// The pieces both screens draw (switch groups, selectors, gauges) and
// `monitor`'s screen; `run`'s is run_screen.cpp.
#include "andros/view/operator_screens.hpp"

#include <cmath>
#include <cstdio>
#include <optional>
#include <tuple>
#include <type_traits>
#include <utility>

#include "andros/base/text.hpp"
#include "andros/protocol/words.hpp"
#include "format.hpp"

namespace andros::view {
namespace {

using detail::fmt;

constexpr int kGaugeHalf = 10;
constexpr std::size_t kIndent = 11;  ///< where a group's switches start

/// make()'s result for key, made again only when key is not the last one
/// asked for at this call site (each lambda type its own), in this thread:
/// the status view redraws 5 times a second a frame that, at rest, has not
/// changed, and these lines were most of a redraw's work.
template <typename Key, typename Make>
std::invoke_result_t<Make> last_made(const Key& key, Make make) {
  struct Kept {
    std::optional<Key> key;
    std::invoke_result_t<Make> value;
  };
  thread_local Kept kept;
  if (!kept.key || *kept.key != key) {
    kept.value = make();
    kept.key = key;
  }
  return kept.value;
}

std::vector<protocol::SignalId> ids(std::initializer_list<std::string_view> names) {
  std::vector<protocol::SignalId> out;
  for (const auto n : names) out.push_back(*protocol::find_signal(n));
  return out;
}

/// A bar 2*kGaugeHalf+1 wide; a centred one grows from the middle, which
/// stands for center, towards 0 or 255; a level (no center) from the left.
Line gauge(std::string_view name, std::uint8_t value, std::optional<int> center) {
  std::string bar(2 * kGaugeHalf + 1, ' ');
  if (center) {
    bar[kGaugeHalf] = '|';
    const int span = value >= *center ? protocol::kWholeByteMax - *center : *center;
    const double x = span == 0 ? 0.0 : (value - *center) / static_cast<double>(span);
    const int n = static_cast<int>(std::lround(x * kGaugeHalf));
    for (int i = 1; i <= std::abs(n); ++i) bar[static_cast<std::size_t>(kGaugeHalf + (n > 0 ? i : -i))] = '#';
  } else {
    const int n =
        static_cast<int>(std::lround(value / static_cast<double>(protocol::kWholeByteMax) * (2 * kGaugeHalf + 1)));
    for (int i = 0; i < n; ++i) bar[static_cast<std::size_t>(i)] = '#';
  }
  return Line(fmt("  %-10s [%s] %3u", std::string(name).c_str(), bar.c_str(), unsigned{value}));
}

std::uint8_t byte_of(const protocol::DataBytes& data, std::string_view signal) {
  return data[protocol::info(*protocol::find_signal(signal)).byte];
}

}  // namespace

std::string speed_text(const mapping::SpeedLevel& speed) {
  return fmt("%zu/%zu (%.3g%%)", speed.index + 1, speed.count, speed.value * 100);
}

bool shows_speed(const mapping::SpeedLevel& speed) { return speed.count > 1 || speed.value != 1.0; }

const std::vector<SignalGroup>& signal_groups() {
  static const std::vector<SignalGroup> groups = {
      {"drive", ids({"safety", "drive_brake", "speed_high", "speed_low", "front_art_up", "front_art_down",
                     "rear_art_up", "rear_art_down", "fiber_unwind", "fiber_takeup"})},
      {"arm", ids({"tool_on", "shoulder_cw", "shoulder_ccw", "torso_left", "torso_right", "elbow_cw", "elbow_ccw",
                   "wrist_cw", "wrist_ccw", "wrist_extend_left", "wrist_extend_right", "gripper_rot_ccw",
                   "gripper_rot_cw", "gripper_open", "gripper_close"})},
      {"camera", ids({"pt_left", "pt_right", "pt_up", "pt_down", "pt_extend_up", "pt_extend_down", "focus_down",
                      "focus_up", "iris_up", "iris_down", "zoom_down", "zoom_up", "graphics_down", "graphics_up"})},
      {"video",
       ids({"inset_3", "inset_4", "inset_video_1", "inset_video_2", "main_video_2", "main_video_3", "main_video_4"})},
      {"weapons",
       ids({"weapon_1", "weapon_2", "weapon_3", "weapon_4", "weapon_5", "weapon_6", "shotgun", "laser", "enable_key"})},
  };
  return groups;
}

namespace {

std::vector<Line> make_switch_lines(const protocol::DataBytes& data, std::size_t width, bool compact,
                                    SwitchNames names) {
  const auto state = protocol::read_signals(data);
  std::vector<Line> out;
  for (const auto& group : signal_groups()) {
    Line line(fmt("  %-8s", std::string(group.title).c_str()));
    for (const auto id : group.signals) {
      const bool on = state[id] != 0;
      if (compact && !on) continue;
      const auto name = names == SwitchNames::kOperator ? protocol::words(id).words : protocol::info(id).name;
      if (line.width() + name.size() + 1 > width && line.width() > kIndent) {
        out.push_back(std::move(line));
        line = Line(std::string(kIndent - 1, ' '));
      }
      line.add(" ");
      // A weapon firing must not look like any other switch.
      const bool weapon = protocol::info(id).kind == protocol::SignalKind::kWeapon;
      line.add(on ? to_upper(name) : std::string(name), on ? (weapon ? Style::kBanner : Style::kReverse) : Style::kDim);
    }
    if (!compact || line.width() > kIndent - 1) out.push_back(std::move(line));
  }
  if (out.empty()) out.emplace_back("  no switch on");
  return out;
}

}  // namespace

std::vector<Line> switch_lines(const protocol::DataBytes& data, std::size_t width, bool compact, SwitchNames names) {
  const auto key = std::tuple(data, width, names);
  return compact ? last_made(key, [&] { return make_switch_lines(data, width, true, names); })
                 : last_made(key, [&] { return make_switch_lines(data, width, false, names); });
}

namespace {

Line make_selector_line(const protocol::DataBytes& data) {
  const auto state = protocol::read_signals(data);
  Line line("  set     ");
  for (const auto& selector : protocol::kSelectorWords) {
    std::string position(selector.none);
    for (std::size_t i = 0; i < selector.bits.size(); ++i) {
      const auto id = selector.bits[i].empty() ? std::nullopt : protocol::find_signal(selector.bits[i]);
      if (id && state[*id] != 0) position = selector.words[i];
    }
    line.add("  " + std::string(selector.name) + " ").add(position, Style::kBold);
  }
  return line;
}

std::vector<Line> make_gauge_lines(const protocol::DataBytes& data, int center) {
  // A neutral frame (safety 0) carries the protocol's 128, not the trim: empty gauges at rest either way.
  if (protocol::read_signals(data)[protocol::signal_id("safety")] == 0) center = protocol::kNeutralCentre;
  return {gauge("drive", byte_of(data, "drive"), center), gauge("pivot", byte_of(data, "pivot"), center),
          gauge("arm_speed", byte_of(data, "arm_speed"), std::nullopt),
          gauge("light", byte_of(data, "light"), std::nullopt), Line("  frame     " + protocol::to_hex(data))};
}

}  // namespace

Line selector_line(const protocol::DataBytes& data) {
  return last_made(data, [&] { return make_selector_line(data); });
}

std::vector<Line> gauge_lines(const protocol::DataBytes& data, int center) {
  return last_made(std::pair(data, center), [&] { return make_gauge_lines(data, center); });
}

Screen render_monitor_screen(std::string_view source, const link::VehicleStatus& v, bool live, TermSize size) {
  Screen screen;
  screen.pin(Line("andros-bridge monitor", Style::kBold).add("  " + std::string(source)));
  if (live) {
    const bool flowing = v.timing.rate_hz > 0;
    screen.pin(Line("rate        ")
                   .add(fmt("%.1f Hz", v.timing.rate_hz), flowing ? Style::kGood : Style::kAlert)
                   .add(fmt(" (period %.2f ms, jitter %.2f ms, worst %.2f ms off)", v.timing.period_ms,
                            v.timing.jitter_ms, v.timing.worst_ms)));
  }
  screen.pin(Line(fmt(
      "frames      %llu, valid %llu, bad checksum %llu, invalid %llu, bytes skipped %llu of %llu",
      static_cast<unsigned long long>(v.stats.frames), static_cast<unsigned long long>(v.stats.valid),
      static_cast<unsigned long long>(v.stats.bad_checksum), static_cast<unsigned long long>(v.stats.invalid),
      static_cast<unsigned long long>(v.stats.bytes_skipped), static_cast<unsigned long long>(v.stats.bytes_total))));
  if (!v.last) {
    screen.pin(Line("last frame  none yet"));
    return screen;
  }
  std::string errors;
  for (const auto& e : v.last_errors) errors += (errors.empty() ? "" : "; ") + e;
  screen.pin(Line("last frame  ")
                 .add(v.last_valid ? "valid" : "INVALID: " + errors, v.last_valid ? Style::kGood : Style::kAlert));
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  const auto rows_left = size.rows - 4;
  auto switches = switch_lines(*v.last, width, false);
  const auto gauges = gauge_lines(*v.last, mapping::kDefaultCenter);
  if (static_cast<int>(switches.size() + gauges.size()) > rows_left) switches = switch_lines(*v.last, width, true);
  screen.block(std::move(switches), 1);
  screen.block(gauges, 2);
  return screen;
}

}  // namespace andros::view

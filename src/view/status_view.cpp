#include "andros/view/status_view.hpp"

#include <cmath>
#include <cstdio>

#include "andros/base/text.hpp"

namespace andros::view {
namespace {

constexpr std::string_view kReverse = "\x1b[7m";
constexpr std::string_view kDim = "\x1b[2m";
constexpr std::string_view kBold = "\x1b[1m";
constexpr std::string_view kReset = "\x1b[0m";
constexpr std::size_t kWidth = 78;
constexpr int kGaugeHalf = 10;

std::vector<protocol::SignalId> ids(std::initializer_list<std::string_view> names) {
  std::vector<protocol::SignalId> out;
  for (const auto n : names) out.push_back(*protocol::find_signal(n));
  return out;
}

std::string fmt(const char* format, auto... args) {
  char buf[256];
  std::snprintf(buf, sizeof buf, format, args...);
  return buf;
}

/// A bar 2*kGaugeHalf+1 wide; a centred one grows from the middle, which
/// stands for center, towards 0 or 255; a level (no center) from the left.
std::string gauge(std::string_view name, std::uint8_t value, std::optional<int> center) {
  std::string bar(2 * kGaugeHalf + 1, ' ');
  if (center) {
    bar[kGaugeHalf] = '|';
    const int span = value >= *center ? 255 - *center : *center;
    const double x = span == 0 ? 0.0 : (value - *center) / static_cast<double>(span);
    const int n = static_cast<int>(std::lround(x * kGaugeHalf));
    for (int i = 1; i <= std::abs(n); ++i) bar[static_cast<std::size_t>(kGaugeHalf + (n > 0 ? i : -i))] = '#';
  } else {
    const int n = static_cast<int>(std::lround(value / 255.0 * (2 * kGaugeHalf + 1)));
    for (int i = 0; i < n; ++i) bar[static_cast<std::size_t>(i)] = '#';
  }
  return fmt("  %-10s [%s] %3u\n", std::string(name).c_str(), bar.c_str(), unsigned{value});
}

/// "; at rest first: lefty" from the enabled text "enabled; at rest first: lefty".
std::string held_back_note(const std::string& enable_text) {
  constexpr std::string_view kEnabled = "enabled";
  return enable_text.starts_with(kEnabled) ? enable_text.substr(kEnabled.size()) : std::string();
}

}  // namespace

const std::vector<SignalGroup>& signal_groups() {
  static const std::vector<SignalGroup> groups = {
      {"drive", ids({"safety", "drive_brake", "speed_high", "speed_low", "front_art_up",
                     "front_art_down", "rear_art_up", "rear_art_down", "fiber_unwind", "fiber_takeup"})},
      {"arm", ids({"tool_on", "shoulder_cw", "shoulder_ccw", "torso_left", "torso_right", "elbow_cw",
                   "elbow_ccw", "wrist_cw", "wrist_ccw", "wrist_extend_left", "wrist_extend_right",
                   "gripper_rot_ccw", "gripper_rot_cw", "gripper_open", "gripper_close"})},
      {"camera", ids({"pt_left", "pt_right", "pt_up", "pt_down", "pt_extend_up", "pt_extend_down",
                      "focus_down", "focus_up", "iris_up", "iris_down", "zoom_down", "zoom_up",
                      "graphics_down", "graphics_up"})},
      {"video", ids({"inset_3", "inset_4", "inset_video_1", "inset_video_2", "main_video_2",
                     "main_video_3", "main_video_4"})},
      {"weapons", ids({"weapon_1", "weapon_2", "weapon_3", "weapon_4", "weapon_5", "weapon_6",
                       "shotgun", "laser", "enable_key"})},
  };
  return groups;
}

std::string render_frame_panel(const protocol::DataBytes& data, int center, bool ansi) {
  const auto state = protocol::read_signals(data);
  std::string out;
  for (const auto& group : signal_groups()) {
    std::string line = fmt("  %-8s", std::string(group.title).c_str());
    std::size_t visible = line.size();
    for (const auto id : group.signals) {
      const auto name = protocol::info(id).name;
      if (visible + name.size() + 1 > kWidth) {
        out += line + "\n";
        line = std::string(10, ' ');
        visible = line.size();
      }
      const bool on = state[id] != 0;
      line += ' ';
      if (ansi) {
        line += on ? kReverse : kDim;
        line += name;
        line += kReset;
      } else {
        line += on ? to_upper(name) : std::string(name);
      }
      visible += name.size() + 1;
    }
    out += line + "\n";
  }
  out += gauge("drive", data[protocol::info(*protocol::find_signal("drive")).byte], center);
  out += gauge("pivot", data[protocol::info(*protocol::find_signal("pivot")).byte], center);
  out += gauge("arm_speed", data[protocol::info(*protocol::find_signal("arm_speed")).byte], std::nullopt);
  out += gauge("light", data[protocol::info(*protocol::find_signal("light")).byte], std::nullopt);
  out += fmt("  frame     %s\n", protocol::to_hex(data).c_str());
  return out;
}

std::string render_run_view(const RunStatus& s, bool ansi) {
  const std::string_view bold = ansi ? kBold : "";
  const std::string_view reset = ansi ? kReset : "";
  std::string out;
  out += fmt("%sandros-bridge run%s  robot %s  code %02X  %g Hz  t %.1f s  input %s\n",
             std::string(bold).c_str(), std::string(reset).c_str(), s.robot.c_str(), unsigned{s.code},
             s.rate_hz, static_cast<double>(s.t_ms) / 1000.0, s.input.c_str());
  out += fmt("controller  %s\n", s.connected ? s.controller.c_str() : "no controller");
  std::string state = s.shutting_down ? "SHUTTING DOWN: sending neutral frames"
                      : s.enabled     ? "ENABLED" + held_back_note(s.enable_text)
                                      : "not enabled: " + s.enable_text;
  if (ansi && s.enabled && !s.shutting_down) state = std::string(kReverse) + state + std::string(kReset);
  state += s.layer.empty() ? "" : "   layer: " + s.layer;
  out += "state       " + state + "\n";
  out += fmt("link        %s: %s%s%s\n", s.link_name.c_str(), std::string(to_string(s.link_state)).c_str(),
             s.link_detail.empty() ? "" : " - ", s.link_detail.c_str());
  out += fmt("frames      sent %llu, skipped %llu busy, %llu down, link lost %llu times\n",
             static_cast<unsigned long long>(s.link.sent), static_cast<unsigned long long>(s.link.busy),
             static_cast<unsigned long long>(s.link.down), static_cast<unsigned long long>(s.link.losses));
  out += fmt("rate        %.1f Hz (period %.2f ms, jitter %.2f ms)\n", s.sent_timing.rate_hz,
             s.sent_timing.period_ms, s.sent_timing.jitter_ms);
  if (s.vehicle) {
    const auto& v = *s.vehicle;
    out += fmt("vehicle     %.1f Hz, %llu frames, %llu valid, %llu bad checksum, %llu invalid%s\n",
               v.timing.rate_hz, static_cast<unsigned long long>(v.stats.frames),
               static_cast<unsigned long long>(v.stats.valid),
               static_cast<unsigned long long>(v.stats.bad_checksum),
               static_cast<unsigned long long>(v.stats.invalid),
               v.last ? "" : " (nothing decoded yet)");
  }
  out += s.vehicle && s.vehicle->last ? "as the vehicle decodes it:\n" : "as sent:\n";
  out += render_frame_panel(s.vehicle && s.vehicle->last ? *s.vehicle->last : s.sent, s.center, ansi);
  return out;
}

std::string render_monitor_view(std::string_view source, const link::VehicleSnapshot& v, bool live, bool ansi) {
  std::string out;
  out += fmt("%sandros-bridge monitor%s  %s\n", ansi ? std::string(kBold).c_str() : "",
             ansi ? std::string(kReset).c_str() : "", std::string(source).c_str());
  if (live) {
    out += fmt("rate        %.1f Hz (period %.2f ms, jitter %.2f ms, worst %.2f ms off)\n",
               v.timing.rate_hz, v.timing.period_ms, v.timing.jitter_ms, v.timing.worst_ms);
  }
  out += fmt("frames      %llu, valid %llu, bad checksum %llu, invalid %llu, bytes skipped %llu of %llu\n",
             static_cast<unsigned long long>(v.stats.frames), static_cast<unsigned long long>(v.stats.valid),
             static_cast<unsigned long long>(v.stats.bad_checksum),
             static_cast<unsigned long long>(v.stats.invalid),
             static_cast<unsigned long long>(v.stats.bytes_skipped),
             static_cast<unsigned long long>(v.stats.bytes_total));
  if (!v.last) return out + "last frame  none yet\n";
  std::string errors;
  for (const auto& e : v.last_errors) errors += (errors.empty() ? "" : "; ") + e;
  out += "last frame  " + std::string(v.last_valid ? "valid" : "INVALID: " + errors) + "\n";
  out += render_frame_panel(*v.last, mapping::kDefaultCenter, ansi);
  return out;
}

}  // namespace andros::view

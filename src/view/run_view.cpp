// `run`'s screen: what matters first and always (docs/running.md, "What the
// operator sees"), then what fits.
#include "andros/view/status_view.hpp"

#include <algorithm>

#include "andros/base/text.hpp"
#include "format.hpp"

namespace andros::view {
namespace {

using detail::fmt;

constexpr std::string_view kWeapons = "WEAPONS ENABLED: weapon signals may be sent";
constexpr std::string_view kWeaponsLayer = "WEAPONS LAYER";
constexpr int kMinLogRows = 3;  ///< the full switch list only when it leaves the log this many rows

/// "; at rest first: lefty" from the enabled text "enabled; at rest first: lefty".
std::string held_back_note(const std::string& enable_text) {
  constexpr std::string_view kEnabled = "enabled";
  return enable_text.starts_with(kEnabled) ? enable_text.substr(kEnabled.size()) : std::string();
}

/// text broken at spaces into pieces at most room wide (a word longer than that is cut by the screen).
std::vector<std::string> wrap(const std::string& text, std::size_t room) {
  std::vector<std::string> out{""};
  std::size_t start = 0;
  while (start < text.size()) {
    const auto end = std::min(text.find(' ', start), text.size());
    const auto word = text.substr(start, end - start);
    if (!out.back().empty() && out.back().size() + 1 + word.size() > room) out.emplace_back();
    out.back() += (out.back().empty() ? "" : " ") + word;
    start = end + 1;
  }
  return out;
}

/// The state, whole: why the robot is not enabled is what the operator must
/// read, so it wraps under its label instead of being cut.
std::vector<Line> state_lines(const RunStatus& s, std::size_t width) {
  constexpr std::string_view kLabel = "state       ";
  std::vector<Line> out;
  if (s.enabled()) {
    out.push_back(Line(std::string(kLabel)).add("ENABLED", Style::kGood).add(held_back_note(s.enable_text), Style::kWarn));
  } else {
    const auto text = s.shutting_down() ? "SHUTTING DOWN: sending neutral frames" : to_upper(run::to_string(s.state)) + ": " + s.enable_text;
    const auto room = std::max<std::size_t>(width > kLabel.size() ? width - kLabel.size() : 0, 20);
    const std::string indent(kLabel.size(), ' ');
    for (const auto& part : wrap(text, room)) {
      out.push_back(Line(out.empty() ? std::string(kLabel) : indent)
                        .add(part, s.shutting_down() ? Style::kWarn : Style::kAlert));
    }
  }
  if (!s.layer.empty()) out.back().add("   layer: ").add(s.layer, Style::kBold);
  if (s.weapons_mode) out.back().add("   ").add(" " + std::string(kWeaponsLayer) + " ", Style::kBanner);
  return out;
}

Line link_line(const RunStatus& s) {
  Line line("link        " + s.link_name + ": ");
  line.add(std::string(to_string(s.link_state)), s.link_state == link::LinkState::kUp ? Style::kGood : Style::kAlert);
  if (!s.motion_allowed) return line.add(" - " + s.link_detail, Style::kAlert);
  return s.link_detail.empty() ? line : line.add(" - " + s.link_detail);
}

Line controller_line(const RunStatus& s) {
  Line line("controller  ");
  if (s.connected) line.add(s.controller, Style::kBold);
  else line.add("none connected", Style::kAlert);
  return s.input == "controller" ? line : line.add("  (script " + s.input + ")");
}

/// The file's path, its start left out when it is too long: the name matters most.
Line mapping_line(const std::string& file, std::size_t width) {
  constexpr std::string_view kLabel = "mapping     ";
  const std::size_t room = width > kLabel.size() + 4 ? width - kLabel.size() : 4;
  std::string path = file;
  if (path.size() > room) path = "..." + path.substr(path.size() - (room - 3));
  return Line(std::string(kLabel) + path);
}

std::vector<Line> counter_lines(const RunStatus& s) {
  std::vector<Line> out;
  out.emplace_back(fmt("frames      sent %llu, skipped %llu busy, %llu down, link lost %llu times",
                       static_cast<unsigned long long>(s.link.sent), static_cast<unsigned long long>(s.link.busy),
                       static_cast<unsigned long long>(s.link.down), static_cast<unsigned long long>(s.link.losses)));
  out.emplace_back(fmt("rate        %.1f Hz of %g (mean period %.2f ms, jitter %.2f ms)", s.sent_timing.rate_hz,
                       s.rate_hz, s.sent_timing.period_ms, s.sent_timing.jitter_ms));
  if (s.vehicle) {
    const auto& v = *s.vehicle;
    out.emplace_back(fmt("vehicle     %.1f Hz, %llu frames, %llu valid, %llu bad checksum, %llu invalid%s",
                         v.timing.rate_hz, static_cast<unsigned long long>(v.stats.frames),
                         static_cast<unsigned long long>(v.stats.valid),
                         static_cast<unsigned long long>(v.stats.bad_checksum),
                         static_cast<unsigned long long>(v.stats.invalid), v.last ? "" : " (nothing decoded yet)"));
  }
  if (!s.recorder.empty()) {
    out.push_back(Line("recorder    ").add(s.recorder, s.recorder_failing ? Style::kAlert : Style::kPlain));
  }
  return out;
}

}  // namespace

Screen render_run_view(const RunStatus& s, TermSize size) {
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  Screen screen;
  if (s.weapons) {
    // In a weapons mode the top line says so too: it is the one line every terminal shows.
    const std::string banner =
        s.weapons_mode ? std::string(kWeaponsLayer) + ": an armed fire input fires" : std::string(kWeapons);
    const auto pad = width > banner.size() ? width - banner.size() : 0;
    screen.pin(Line(std::string(pad / 2, ' ') + banner + std::string(pad - pad / 2, ' '), Style::kBanner));
  }
  screen.pin(Line("andros-bridge run", Style::kBold)
                 .add(fmt("  robot %s  code %02X  ", s.robot.c_str(), unsigned{s.code}))
                 .add(fmt("%.1f Hz", s.sent_timing.rate_hz), s.sent_timing.rate_hz > 0 ? Style::kBold : Style::kAlert)
                 .add(fmt("  t %.1f s", static_cast<double>(s.t_ms) / 1000.0)));
  const auto state = state_lines(s, width);
  for (const auto& line : state) screen.pin(line);
  screen.pin(link_line(s));
  screen.pin(controller_line(s));
  screen.pin(mapping_line(s.mapping_file, width));

  auto counters = counter_lines(s);
  const bool decoded = s.vehicle && s.vehicle->last;
  const auto& frame = decoded ? *s.vehicle->last : s.sent;
  auto gauges = gauge_lines(frame, s.center);
  auto switches = switch_lines(frame, width, false);
  const auto pinned = static_cast<int>(state.size()) + (s.weapons ? 5 : 4);
  const auto room = size.rows - pinned - static_cast<int>(counters.size() + gauges.size() + 1) - kMinLogRows;
  if (static_cast<int>(switches.size()) > room) switches = switch_lines(frame, width, true);
  switches.insert(switches.begin(), Line(decoded ? "as the vehicle decodes it:" : "as sent:"));

  screen.block(std::move(counters), 4);
  screen.block(std::move(switches), 2);
  screen.block(std::move(gauges), 3);
  return screen;
}

}  // namespace andros::view

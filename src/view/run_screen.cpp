// `run`'s screen: what matters first and always (docs/running.md, "What the
// operator sees"), then what fits.
#include "andros/view/operator_screens.hpp"

#include <algorithm>

#include "andros/base/text.hpp"
#include "andros/view/status_board.hpp"
#include "format.hpp"

namespace andros::view {
namespace {

using detail::fmt;

constexpr std::string_view kWeapons = "WEAPONS ENABLED: weapon signals may be sent";
constexpr std::string_view kWeaponsLayer = "WEAPONS LAYER";
constexpr std::string_view kStopBanner = "STOP";
/// "state       ", "link        ": where a line's text starts, and its continuations.
constexpr std::size_t kLabelWidth = 12;
constexpr int kMinLogRows = 3;  ///< the full switch list only when it leaves the log this many rows
/// Frames since the link came up before its rate and jitter mean something
/// (a second at 25 Hz): until then the screen says "measuring".
constexpr std::uint64_t kMeasuringFrames = 25;

bool measuring(const RunStatus& s) { return s.sent_timing.count < kMeasuringFrames; }

/// Enabled: "; at rest first: lefty", the inputs the rest rule still holds back; "" when none is.
std::string held_back_note(const RunStatus& s) {
  return s.enabled() && !s.held_back.empty() ? "; at rest first: " + s.held_back : std::string();
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

/// text centred in width.
std::string centred(const std::string& text, std::size_t width) {
  const auto pad = width > text.size() ? width - text.size() : 0;
  return std::string(pad / 2, ' ') + text + std::string(pad - pad / 2, ' ');
}

}  // namespace

std::string state_words(const RunStatus& s) {
  if (s.enabled()) return "ENABLED" + held_back_note(s);
  if (s.shutting_down()) return "SHUTTING DOWN: sending neutral frames";
  return to_upper(run::to_string(s.state)) + ": " + (s.reset_progress.empty() ? s.enable_text : s.reset_progress);
}

namespace {

/// The state, whole: why the robot is not enabled is what the operator must
/// read, so it wraps under its label instead of being cut.
std::vector<Line> state_lines(const RunStatus& s, std::size_t width) {
  constexpr std::string_view kLabel = "state       ";
  std::vector<Line> out;
  if (s.enabled()) {
    out.push_back(Line(std::string(kLabel)).add("ENABLED", Style::kGood).add(held_back_note(s), Style::kWarn));
  } else {
    const auto text = state_words(s);
    const auto room = std::max<std::size_t>(width > kLabel.size() ? width - kLabel.size() : 0, 20);
    const std::string indent(kLabel.size(), ' ');
    for (const auto& part : wrap(text, room)) {
      out.push_back(
          Line(out.empty() ? std::string(kLabel) : indent).add(part, s.shutting_down() ? Style::kWarn : Style::kAlert));
    }
  }
  // What follows the state goes on its line while it fits, else on a line
  // of its own under it: the layer and a weapons mode are never cut off.
  const auto append = [&](const std::vector<Piece>& pieces) {
    std::size_t need = 3;
    for (const auto& p : pieces) need += p.text.size();
    if (out.back().width() + need > width) out.emplace_back(std::string(kLabel.size(), ' '));
    else out.back().add("   ");
    for (const auto& p : pieces) out.back().add(p.text, p.style);
  };
  if (!s.layer.empty()) append({{"layer: "}, {s.layer, Style::kBold}});
  if (shows_speed(s.speed)) append({{"speed level " + speed_text(s.speed), Style::kBold}});
  if (s.weapons_mode) append({{" " + std::string(kWeaponsLayer) + (s.armed ? " ARMED " : " "), Style::kBanner}});
  for (auto& line : out) line.hang(kLabel.size());
  return out;
}

/// The link's state is what the line is for: the name gives way to it (cut
/// in its middle: a by-id path keeps its start and its serial number).
Line link_line(const RunStatus& s, std::size_t width) {
  constexpr std::string_view kLabel = "link        ";
  const auto state = std::string(to_string(s.link_state));
  const std::size_t fixed = kLabel.size() + 2 + state.size();
  Line line(std::string(kLabel) + cut_middle(s.link_name, width > fixed ? width - fixed : 0) + ": ");
  line.hang(kLabelWidth);
  line.add(std::string(to_string(s.link_state)), s.link_state == link::LinkState::kUp ? Style::kGood : Style::kAlert);
  if (!s.far_end_reading) return line.add(" - " + s.link_detail, Style::kAlert);
  return s.link_detail.empty() ? line : line.add(" - " + s.link_detail);
}

Line controller_line(const RunStatus& s) {
  Line line("controller  ");
  line.hang(kLabelWidth);
  if (s.connected) line.add(s.controller, Style::kBold);
  else line.add("none connected", Style::kAlert);
  if (s.connected && s.game_controller == false) {
    line.add("  (a plain joystick to SDL)",
             joystick_note(s.pad_names, s.game_controller).empty() ? Style::kPlain : Style::kWarn);
  }
  return s.input == "controller" ? line : line.add("  (script " + s.input + ")");
}

/// The supervisor's controller: its name, and what it holds that matters.
Line supervisor_line(const RunStatus& s) {
  Line line("supervisor  ");
  line.hang(kLabelWidth);
  if (!s.supervisor_connected) return line.add("none connected: nothing moves without it", Style::kAlert);
  line.add(s.supervisor, Style::kBold);
  if (s.supervisor_stop) line.add("  ").add(" STOP HELD ", Style::kBanner);
  switch (s.consent) {
    case mapping::ConsentState::kNotAsked: break;
    case mapping::ConsentState::kReleased: line.add("  consent: not given"); break;
    case mapping::ConsentState::kHeldBack: line.add("  consent: release and press again", Style::kWarn); break;
    case mapping::ConsentState::kGiven: line.add("  consent: GIVEN", Style::kGood); break;
  }
  return line;
}

/// The file's path, its start left out when it is too long: the name matters most.
Line mapping_line(const std::string& file, std::size_t width) {
  constexpr std::string_view kLabel = "mapping     ";
  const std::size_t room = width > kLabel.size() + 4 ? width - kLabel.size() : 4;
  std::string path = file;
  if (path.size() > room) path = "..." + path.substr(path.size() - (room - 3));
  return Line(std::string(kLabel) + path).hang(kLabelWidth);
}

std::vector<Line> counter_lines(const RunStatus& s) {
  std::vector<Line> out;
  out.emplace_back(fmt("frames      sent %llu, skipped %llu busy, %llu down, link lost %llu time%s",
                       static_cast<unsigned long long>(s.link.sent), static_cast<unsigned long long>(s.link.busy),
                       static_cast<unsigned long long>(s.link.down), static_cast<unsigned long long>(s.link.losses),
                       s.link.losses == 1 ? "" : "s"));
  if (measuring(s)) {
    out.emplace_back(fmt("rate        measuring since the link came up (%llu frames, of %g Hz)",
                         static_cast<unsigned long long>(s.sent_timing.count), s.rate_hz));
  } else {
    out.emplace_back(fmt("rate        %.1f Hz of %g (mean period %.2f ms, jitter %.2f ms)", s.sent_timing.rate_hz,
                         s.rate_hz, s.sent_timing.period_ms, s.sent_timing.jitter_ms));
  }
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
  for (auto& line : out) line.hang(kLabelWidth);
  return out;
}

}  // namespace

Screen render_run_screen(const RunStatus& s, TermSize size) {
  const auto width = static_cast<std::size_t>(std::max(size.cols, 1));
  Screen screen;
  if (s.weapons) {
    // In a weapons mode the top line says so too: it is the one line every terminal shows.
    const std::string banner = !s.weapons_mode ? std::string(kWeapons)
                               : s.armed       ? std::string(kWeaponsLayer) + ": ARMED: a fire button fires"
                                               : std::string(kWeaponsLayer) + ": an armed fire input fires";
    screen.pin(Line(centred(banner, width), Style::kBanner).one_row());
  }
  // Stopped by a stop button: a red line across the top, above all else, saying whose.
  const bool stopped = s.state == run::OpState::kStopped;
  if (stopped) {
    screen.pin(Line(centred(std::string(kStopBanner) + ": " + s.stopped_by, width), Style::kBanner).one_row());
  }
  // The trainer says so first: a trainee must never take it for the vehicle.
  auto title = Line(s.trainer.empty() ? "andros-bridge run" : "andros-bridge TRAINER", Style::kBold)
                   .add(fmt("  robot %s  code %02X  ", s.robot.c_str(), unsigned{s.code}))
                   .add(measuring(s) ? std::string("measuring") : fmt("%.1f Hz", s.sent_timing.rate_hz),
                        measuring(s) || s.sent_timing.rate_hz > 0 ? Style::kBold : Style::kAlert)
                   .add(fmt("  t %.1f s", static_cast<double>(s.t_ms) / 1000.0));
  // Without --weapons nothing on the screen would say so: no banner is not the same as "off".
  if (!s.weapons) title.add("  weapons off");
  screen.pin(std::move(title));
  if (!s.trainer.empty()) screen.pin(Line("trainer     ").hang(kLabelWidth).add(s.trainer, Style::kBold));
  const auto state = state_lines(s, width);
  for (const auto& line : state) screen.pin(line);
  screen.pin(link_line(s, width));
  screen.pin(controller_line(s));
  if (s.supervised) screen.pin(supervisor_line(s));
  screen.pin(mapping_line(s.mapping_file, width));

  auto counters = counter_lines(s);
  const bool decoded = s.vehicle && s.vehicle->last;
  const auto& frame = decoded ? *s.vehicle->last : s.sent;
  auto gauges = gauge_lines(frame, s.center);
  auto switches = switch_lines(frame, width, false, SwitchNames::kOperator);
  const auto pinned = static_cast<int>(state.size()) + (s.weapons ? 5 : 4) + (stopped ? 1 : 0) + (s.supervised ? 1 : 0);
  const auto room = size.rows - pinned - static_cast<int>(counters.size() + gauges.size() + 2) - kMinLogRows;
  if (static_cast<int>(switches.size()) > room) switches = switch_lines(frame, width, true, SwitchNames::kOperator);
  switches.insert(switches.begin(), selector_line(frame));
  switches.insert(switches.begin(), Line(decoded ? "as the vehicle decodes it:" : "as sent:"));

  screen.block(std::move(counters), 4);
  screen.block(std::move(switches), 2);
  screen.block(std::move(gauges), 3);
  return screen;
}

}  // namespace andros::view

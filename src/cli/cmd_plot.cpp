// `andros-bridge plot`: a drive on one A4 landscape page (docs/recording.md):
// from a flight recorder's session, or from an event script through replay.
#include <spdlog/fmt/fmt.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/base/text_file.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/cli/config.hpp"
#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/record/session.hpp"
#include "andros/run/replay.hpp"
#include "andros/timing/rate.hpp"
#include "andros/view/plot.hpp"
#include "commands.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

struct PlotOptions {
  std::string source;
  std::unique_ptr<CommandLine> settings;  ///< for a script: the settings table's replay flags
  std::string output;
  std::string from;
  std::string to;
};

/// The whole page is made before FILE is opened, and replaces it only
/// whole (OutputFile: a device or FIFO is written in place, a link followed).
void write_page(const std::string& output, const std::string& page) {
  write_output_file(output.empty() ? "-" : output, page);
}

/// Seconds (decimals allowed) as ms; InputError at the flag.
std::int64_t parse_seconds(const std::string& text, const char* flag) {
  std::size_t used = 0;
  double s = -1;
  try {
    s = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(s) || s < 0 || s > 86400) {
    throw InputError(SourcePos{flag}, "expected seconds from 0 to 86400, got " + quote(text));
  }
  return std::llround(s * 1000);
}

std::string weapons_text(bool weapons) { return weapons ? "WEAPONS ENABLED" : "weapons disabled"; }

std::string file_name(const std::string& path) { return std::filesystem::path(path).filename().string(); }

bool is_session(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string first(64, '\0');
  in.read(first.data(), static_cast<std::streamsize>(first.size()));
  first.resize(static_cast<std::size_t>(in.gcount()));
  return record::is_session_start(first);
}

view::PlotInput from_session(const PlotOptions& opt, const view::PlotAxis& axis) {
  for (const auto& row : settings_table()) {
    if ((row.commands & kPlot) != 0 && opt.settings->given(flag_name(row))) {
      throw InputError(SourcePos{std::string(flag_name(row))},
                       "not for a session: it is drawn with the settings it recorded");
    }
  }
  // The one reading verify makes: the records of the chain's intact part, never a last line cut short.
  const auto checked = record::read_checked_session(opt.source);
  if (checked.unreadable) throw *checked.unreadable;
  const auto& s = *checked.session;
  const auto& check = checked.verdict;
  view::PlotInput in;
  in.title = fmt::format("{} drive, mapping {}", s.settings.robot, file_name(s.settings.mapping_file));
  in.settings = fmt::format("{} Hz, code {:02X}, {}, input {}, port {}", timing::rate_text(s.settings.rate_millihertz),
                            s.settings.code, weapons_text(s.settings.weapons), s.settings.input, s.settings.port);
  if (!s.reloads.empty()) in.settings += fmt::format(", {} reload(s)", s.reloads.size());
  in.source = fmt::format("session {}, recorded {} on {} by andros-bridge {}", file_name(opt.source), s.started, s.host,
                          s.version);
  // Drawn all the same, but never passed off as a whole record.
  if (!check.intact)
    in.source += fmt::format("; NOT INTACT: {}: the {} records before it drawn", check.problem, check.records);
  else if (check.cut_short_line != 0) in.source += "; " + record::cut_short_text(check);
  if (check.intact && s.dropped != 0) in.source += fmt::format("; {} records dropped while recording", s.dropped);
  if (check.intact && s.stopped_for_room) in.source += "; " + record::room_text(s);
  in.rate_millihertz = s.settings.rate_millihertz;
  // Sampled to the page's width: a long session's samples take the page's memory, not its ticks'.
  in.samples = view::plot_samples(s, view::PlotAxis{axis.from_ms, axis.to_ms});
  view::add_lanes(in, s);
  return in;
}

/// A script's lanes and weapon layers: its events read again (it was checked
/// whole before the replay), with the mapping in effect (a `reload FILE`'s
/// from its time, when it loads), the link up from the start and as its fault events move it.
void add_script_lanes(view::PlotInput& in, const PlotOptions& opt, const mapping::Mapping& mapping, bool supervised) {
  in.weapon_layers = view::weapon_layers(mapping);
  view::LaneBuilder lanes(mapping, supervised);
  auto text = TextReader::open_regular(opt.source, kEventScriptLimits);
  input::EventReader reader(text);
  using T = input::InputEvent::Type;
  std::string current = mapping.file;
  while (const auto e = reader.next()) {
    if (e->type == T::kLinkDown || e->type == T::kLinkTaken || e->type == T::kLinkUp) {
      lanes.link(e->t_ms, e->type == T::kLinkUp);
    } else if (e->type == T::kReload) {
      try {
        const std::string wanted = e->name.empty() ? current : e->name;
        const auto m = mapping::load_mapping(beside(opt.source, wanted));
        current = wanted;
        lanes.use_mapping(e->t_ms, *m);
        for (auto& name : view::weapon_layers(*m)) in.weapon_layers.push_back(std::move(name));
      } catch (const std::exception&) {
        // A reload that fails keeps the mapping, as the replay's does.
      }
    } else {
      lanes.event(*e);
    }
  }
  in.lanes = lanes.lanes();
}

view::PlotInput from_script(const PlotOptions& opt) {
  if (opt.settings->given("--robot") && opt.settings->given("--mapping")) {
    throw InputError("plot: give --robot or --mapping, not both");
  }
  const Settings settings = resolve_settings(*opt.settings);
  auto mapping = mapping::load_chosen_mapping(settings.mapping, settings.robot);
  auto script = input::checked_event_script(TextReader::open(opt.source, kEventScriptLimits));
  view::PlotInput in;
  in.title = fmt::format("{} drive, mapping {}", mapping->robot.value_or(settings.robot), file_name(mapping->file));
  in.settings = fmt::format("{} Hz, code {:02X}, {}", timing::rate_text(settings.rate.millihertz), settings.code,
                            weapons_text(settings.weapons));
  in.source = "replay of " + file_name(opt.source);
  in.rate_millihertz = settings.rate.millihertz;
  input::ScriptPlayer player(script);
  add_script_lanes(in, opt, *mapping, player.supervised());
  run::ReplayOptions replay{.rate_millihertz = settings.rate.millihertz,
                            .engine = mapping::EngineOptions{settings.weapons, settings.code}};
  replay.load = [&opt](const std::string& file) { return mapping::load_mapping(beside(opt.source, file)); };
  replay.observe = [&in](const run::TickReport& r) {
    auto sample = view::plot_sample(r);
    // When a reset was: its first report, carried while it stands (a page
    // that begins after it does not draw it).
    if (!sample.reset.empty()) {
      const bool standing = !in.samples.empty() && in.samples.back().reset == sample.reset;
      sample.reset_ms = standing ? in.samples.back().reset_ms : sample.t_ms;
    }
    in.samples.push_back(std::move(sample));
  };
  run::replay(player, mapping::Engine(std::move(mapping), replay.engine), replay,
              [](std::int64_t, const protocol::DataBytes&) {});
  return in;
}

void run_plot(const PlotOptions& opt) {
  // Read twice (a script: replayed, then its lanes), so a regular file: what else is there is said.
  const auto kind = path_kind(opt.source);
  if (kind.empty()) throw InputError(SourcePos{opt.source}, "no such file");
  if (kind != "a regular file") {
    throw InputError(SourcePos{opt.source}, "is " + kind + ", not a session or an event script file");
  }
  const std::int64_t from = opt.from.empty() ? 0 : parse_seconds(opt.from, "--from");
  const std::int64_t to = opt.to.empty() ? -1 : parse_seconds(opt.to, "--to");
  if (to >= 0 && to <= from) throw InputError(SourcePos{"--to"}, "must be later than --from");
  view::PlotInput in = is_session(opt.source) ? from_session(opt, view::PlotAxis{from, to}) : from_script(opt);
  in.from_ms = from;
  in.to_ms = to;
  write_page(opt.output, view::render_plot_svg(in));
}

}  // namespace

void add_plot_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<PlotOptions>();
  auto* cmd =
      app.add_subcommand("plot",
                         "Draw a drive as SVG (docs/recording.md): drive and pivot over time; the operating state\n"
                         "as a band, a colour a state (a stop's by whose it was, who reset it; shutdown apart),\n"
                         "with a legend of the colours used; the active layer (a weapons layer in the weapons\n"
                         "red); lanes for the controllers, the link, the deadman, the stop buttons, the\n"
                         "supervisor's consent and arming; and every switch signal that was on (weapons in red),\n"
                         "with the robot, mapping and settings in the title. One 297 x 210 mm page: A4\n"
                         "landscape on paper, or a browser. From a session file (as recorded), or from an event\n"
                         "script through replay (with --robot/--mapping and the other replay settings).");
  cmd->add_option("SOURCE", opt->source,
                  "a session file (or its bare name, as 'sessions' prints it), or an event script\n"
                  "(docs/event-scripts.md)")
      ->required();
  opt->settings = std::make_unique<CommandLine>(*cmd, kPlot);
  cmd->add_option("--output", opt->output, "write to FILE instead of standard output")->type_name("FILE");
  cmd->add_option("--from", opt->from, "start the time axis at T seconds (what held then is drawn from there)")
      ->type_name("T");
  cmd->add_option("--to", opt->to, "end the time axis at T seconds (default: the end)")->type_name("T");
  cmd->callback([opt, &exit_code] {
    opt->source = find_session(opt->source);  // a bare session name, as `sessions` prints it
    run_plot(*opt);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli

// `andros-bridge replay`: an event script through a mapping on a virtual clock.
#include <spdlog/spdlog.h>

#include <functional>
#include <memory>
#include <ostream>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/output_file.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/base/text_file.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/cli/config.hpp"
#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/frame_output.hpp"
#include "andros/record/session.hpp"
#include "andros/record/session_replay.hpp"
#include "andros/run/replay.hpp"
#include "commands.hpp"
#include "session_files.hpp"

namespace andros::cli {
namespace {

struct ReplayOptions {
  std::string events;
  std::unique_ptr<CommandLine> settings;  ///< the settings table's flags
};

/// Frames to FILE, or to stdout. FILE is replaced only by a whole replay:
/// one that fails leaves it as it was, so that no partial output is mistaken
/// for a whole one.
void write_frames(const Settings& opt, const std::function<void(std::ostream&)>& body) {
  OutputFile out(opt.output.empty() ? "-" : opt.output);
  body(out.stream());
  out.commit();
}

/// A flight recorder's session (its first line says so), rather than an event
/// script. One named as a session that is a FIFO, a directory, a device or a
/// socket is refused at once, saying what it is, never waited on.
bool is_session_file(const std::string& path) {
  if (path == "-") return false;
  if (std::filesystem::path(path).extension() == record::kSessionExtension) record::require_session_file(path);
  if (!std::filesystem::is_regular_file(path)) return false;
  std::ifstream in(path, std::ios::binary);
  std::string first(64, '\0');
  in.read(first.data(), static_cast<std::streamsize>(first.size()));
  first.resize(static_cast<std::size_t>(in.gcount()));
  return record::is_session_start(first);
}

/// A session replayed with its own settings and mapping: are its frames what the loop makes again?
int replay_session_file(const ReplayOptions& opt) {
  for (const auto& row : settings_table()) {
    const auto flag = flag_name(row);
    if ((row.commands & kReplay) != 0 && opt.settings->given(flag)) {
      throw InputError(SourcePos{std::string(flag)}, "not for a session: it replays with the settings it recorded");
    }
  }
  // The one reading verify makes: only the records of an intact chain are
  // replayed, never a last line cut short.
  const auto checked = record::read_checked_session(opt.events);
  if (!checked.verdict.intact) {
    std::cout << "NOT INTACT: " << terminal_line(checked.verdict.problem) << " (andros-bridge verify)\n";
    return kExitRuntime;
  }
  if (checked.unreadable) throw *checked.unreadable;
  const auto result = record::replay_session(*checked.session);
  if (!result.identical) {
    std::cout << "DIFFERENT after " << result.compared << " identical frames: " << terminal_line(result.difference)
              << "\n";
    return kExitRuntime;
  }
  std::cout << result.compared << " frames identical; " << result.records
            << " records of the loop's (state, stop, reset, layer, gate, request, frame) made again the same";
  if (result.unproven != 0) {
    std::cout << "; " << result.unproven << " from line " << result.first_unproven_line
              << " on not replayed (the session was not closed: what the loop sent then is not known)";
  }
  std::cout << "\n";
  return kExitOk;
}

int run_replay(const ReplayOptions& opt) {
  if (is_session_file(opt.events)) return replay_session_file(opt);
  // Everything is checked, the whole script included, before a frame is written.
  if (opt.settings->given("--robot") && opt.settings->given("--mapping")) {
    throw InputError("replay: give --robot or --mapping, not both");
  }
  const Settings settings = resolve_settings(*opt.settings);
  const timing::FrameClock clock(settings.rate.millihertz);
  auto mapping = mapping::load_chosen_mapping(settings.mapping, settings.robot);
  auto script = input::checked_event_script(opt.events == "-" ? TextReader::standard_input(kEventScriptLimits)
                                                              : TextReader::open(opt.events, kEventScriptLimits));

  input::ScriptPlayer player(script);
  run::ReplayOptions replay_options{.rate_millihertz = settings.rate.millihertz,
                                    .engine = mapping::EngineOptions{settings.weapons, settings.code}};
  mapping::Engine engine(std::move(mapping), replay_options.engine);
  // A script's `reload FILE` names FILE relative to the script's folder.
  replay_options.load = [&opt](const std::string& file) { return mapping::load_mapping(beside(opt.events, file)); };
  // One that fails is `run`'s: the old mapping stays, it is logged, the replay goes on.
  replay_options.reloaded = [](std::int64_t t_ms, const run::ReloadOutcome& outcome) {
    if (!outcome.ok) spdlog::error("reload at {} ms failed, the old mapping stays: {}", t_ms, outcome.message);
  };
  write_frames(settings, [&](std::ostream& out) {
    run::replay(player, std::move(engine), replay_options, [&](std::int64_t t, const protocol::DataBytes& data) {
      protocol::write_frame(out, settings.format, t, data);
    });
  });
  return kExitOk;
}

}  // namespace

void add_replay_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<ReplayOptions>();
  auto* cmd =
      app.add_subcommand("replay",
                         "Run an event script through the bridge's own loop on a virtual clock and write the\n"
                         "frames the vehicle receives: one every 1000/rate ms from t=0 through the script's end.\n"
                         "Fault events (link down|up|taken|stalled|reading, suspend, resume, reload [MAPPING], stop)\n"
                         "are answered "
                         "as run answers the real thing. Deterministic: the same script gives the same bytes on\n"
                         "any machine, at any speed. Given a flight recorder's session (docs/recording.md), replays\n"
                         "it with its own settings and mapping and prints 'N frames identical; M records ... made\n"
                         "again the same' (every state, stop, reset, layer, gate, request and frame record the loop\n"
                         "wrote, in order), or the first frame or record that differs, with its line (exit 1).");
  cmd->add_option("EVENTS", opt->events,
                  "event script (docs/event-scripts.md), or - for standard input; checked whole\n"
                  "before the first frame is written; or a session file (a bare name, as 'sessions'\n"
                  "prints it, is looked up in the sessions' folder)")
      ->required();
  opt->settings = std::make_unique<CommandLine>(*cmd, kReplay);
  cmd->callback([opt, &exit_code] {
    opt->events = find_session(opt->events);  // a bare session name, as `sessions` prints it
    exit_code = run_replay(*opt);
  });
}

}  // namespace andros::cli

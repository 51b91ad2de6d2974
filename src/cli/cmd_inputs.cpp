// `andros-bridge inputs`: what the controller itself reports, live.
#include <unistd.h>

#include <cstdio>
#include <memory>
#include <optional>
#include <string>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/cli/config.hpp"
#include "andros/input/sdl_input.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/view/inputs_view.hpp"
#include "andros/view/terminal_display.hpp"
#include "commands.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

constexpr int kPollMs = 20;  ///< how often the controller is read: twice per frame at 25 Hz
constexpr int kInputsRedrawsPerSecond = 10;

struct InputsOptions {
  input::SdlInputOptions sdl;
  std::string robot;
  std::string mapping;
};

/// The deadzones to show, and where they come from. With neither --robot
/// nor --mapping, the mapping `run` would use: the config file's (mapping=,
/// robot=), else HD1's; the screen's second line says which.
view::AxisUses load_uses(const InputsOptions& opt, std::string& source) {
  if (!opt.robot.empty() && !opt.mapping.empty()) {
    throw InputError(SourcePos{"--mapping"}, "give --robot or --mapping, not both");
  }
  std::string why;
  Settings settings;  // run's defaults: robot HD1
  if (opt.robot.empty() && opt.mapping.empty()) {
    const auto config = find_default_config(true);
    if (!config.empty()) read_config_file(config, settings);
    why = config.empty() ? " (run's default: no --robot or --mapping given)"
                         : " (run's, from " + terminal_text(config) + ": no --robot or --mapping given)";
  } else {
    settings.mapping = opt.mapping;
    if (!opt.robot.empty()) settings.robot = opt.robot;
  }
  const auto mapping = mapping::load_chosen_mapping(settings.mapping, settings.robot);
  source = "deadzones and thresholds of " + terminal_text(mapping->file) + why;
  return view::axis_uses(*mapping);
}

int run_inputs(const InputsOptions& opt) {
  std::string source;
  auto uses = load_uses(opt, source);
  ShutdownRequest stop(kShutdownSignals);  // before SDL starts a thread: every thread inherits the mask
  std::optional<input::SdlInput> sdl;
  try {
    sdl.emplace(opt.sdl, [&stop] { return stop.requested(); });
  } catch (const ReadStopped&) {
    return kExitOk;  // stopped while reading the controller database: as asked
  }
  auto& input = *sdl;
  view::InputsBoard board(std::move(uses), "andros-bridge inputs: " + input.selection() + " (Ctrl-C ends)\n" + source);
  std::optional<view::TerminalDisplay> display;
  if (view::is_interactive(STDOUT_FILENO)) {
    display.emplace([&board](view::TermSize size) { return view::text_screen(board.compose(size)); },
                    kInputsRedrawsPerSecond);
    display->start();
  } else {
    std::printf("# %s\n# %s\n", input.selection().c_str(), source.c_str());
    std::fflush(stdout);  // line by line down a pipe: the header too, before the first change
  }
  const auto grid = TickGrid::every(kPollMs * kNsPerMs);
  const std::int64_t start_ns = monotonic_ns();
  for (std::int64_t tick = 0;; tick = grid.next_tick(tick, monotonic_ns() - start_ns)) {
    if (!stop.sleep_until(start_ns + grid.tick_ns(tick))) break;
    const auto& events = input.poll(tick * kPollMs);
    const auto lines = board.update(events, input.device());
    if (display) continue;
    for (const auto& line : lines) std::printf("%s\n", line.c_str());
    // Line by line down a pipe; a reader that went away ends the tester.
    if (!lines.empty() && (std::fflush(stdout) != 0 || std::ferror(stdout) != 0)) break;
  }
  display.reset();
  return kExitOk;
}

}  // namespace

void add_inputs_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<InputsOptions>();
  auto* cmd = app.add_subcommand("inputs",
                                 "Show what the controller reports, live: every button, axis, trigger and hat by SDL\n"
                                 "name and number, each axis with its value and the deadzone (or threshold) the\n"
                                 "mapping applies to it. On a terminal a screen; otherwise one line per change.\n"
                                 "Ctrl-C ends it. See docs/controllers.md.");
  cmd->add_option("--robot", opt->robot, "show the deadzones of this robot type's mapping");
  cmd->add_option("--mapping", opt->mapping,
                  "show the deadzones of this mapping file (with neither option: the mapping 'run'\n"
                  "uses, the config file's or HD1's; the screen names it)");
  add_sdl_options(cmd, opt->sdl);
  cmd->callback([opt, &exit_code] { exit_code = run_inputs(*opt); });
}

}  // namespace andros::cli

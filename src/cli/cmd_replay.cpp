// `andros-bridge replay`: an event script through a mapping on a virtual clock.
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "andros/error.hpp"
#include "andros/events.hpp"
#include "andros/mapping_loader.hpp"
#include "andros/parse.hpp"
#include "andros/replay.hpp"
#include "andros/robots.hpp"
#include "andros/text_file.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

struct ReplayOptions {
  std::string events;
  std::string robot;
  std::string mapping;
  std::string code = "01";
  std::string rate = "25";
  bool weapons = false;
  std::string format = "hex";
  std::string output;
};

/// Frames to FILE, or to stdout. A replay that fails after FILE was created
/// removes it, so that no partial output is mistaken for a whole one.
void write_frames(const ReplayOptions& opt, const std::function<void(std::ostream&)>& body) {
  if (opt.output.empty()) {
    body(std::cout);
    std::cout.flush();
    if (!std::cout) throw RuntimeError("stdout: write error");
    return;
  }
  std::ofstream file(opt.output, std::ios::binary | std::ios::trunc);
  if (!file) throw RuntimeError(opt.output + ": cannot open for writing");
  try {
    body(file);
    file.close();
    if (!file) throw RuntimeError(opt.output + ": write error");
  } catch (...) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(opt.output, ec)) std::filesystem::remove(opt.output, ec);
    throw;
  }
}

void run_replay(const ReplayOptions& opt) {
  // Everything is checked, the whole script included, before a frame is written.
  if (!opt.robot.empty() && !opt.mapping.empty()) throw InputError("replay: give --robot or --mapping, not both");
  const auto code = parse_code(opt.code, SourcePos{"--code"});
  const FrameClock clock(parse_rate(opt.rate, kReplayBaud, SourcePos{"--rate"}));
  const auto format = parse_replay_format(opt.format, SourcePos{"--format"});
  Mapping mapping = opt.mapping.empty() ? load_robot_mapping(opt.robot.empty() ? kDefaultRobot : opt.robot)
                                        : load_mapping(opt.mapping);
  auto script = checked_event_script(opt.events == "-" ? TextReader::standard_input(kEventScriptLimits)
                                                       : TextReader::open(opt.events, kEventScriptLimits));

  ScriptPlayer player(script);
  Engine engine(std::move(mapping), EngineOptions{opt.weapons, code});
  write_frames(opt, [&](std::ostream& out) {
    replay(player, engine, clock, [&](std::int64_t t, const DataBytes& data) { write_frame(out, format, t, data); });
  });
}

}  // namespace

void add_replay_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<ReplayOptions>();
  auto* cmd = app.add_subcommand(
      "replay",
      "Run an event script through a mapping on a virtual clock and write the frames:\n"
      "one every 1000/rate ms from t=0 through the script's end. Deterministic: the same\n"
      "script gives the same bytes on any machine, at any speed.");
  cmd->add_option("EVENTS", opt->events,
                  "event script (docs/event-scripts.md), or - for standard input; checked whole\n"
                  "before the first frame is written")
      ->required();
  cmd->add_option("--robot", opt->robot, "robot type (" + robot_list() + "); default HD1");
  cmd->add_option("--mapping", opt->mapping, "mapping file to use instead of a robot's shipped one");
  cmd->add_option("--code", opt->code, "dip-switch code for byte 11, in hex")->default_str("01");
  cmd->add_option("--rate", opt->rate, "frames per second (at most 26.666: 360-bit frames at 9600 baud)")
      ->default_str("25");
  cmd->add_flag("--weapons", opt->weapons, "enable weapon signals (they still need the deadman and arming input)");
  cmd->add_option("--format", opt->format, "hex (T HEX72 per line), raw (36 bytes per frame) or jsonl")
      ->default_str("hex");
  cmd->add_option("--output", opt->output,
                  "write to FILE instead of standard output (created only once every input is\n"
                  "checked; removed again if the replay fails)");
  cmd->callback([opt, &exit_code] {
    run_replay(*opt);
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli

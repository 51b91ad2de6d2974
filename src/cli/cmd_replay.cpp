// `andros-bridge replay`: an event script through a mapping on a virtual clock.
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/base/text_file.hpp"
#include "andros/input/events.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/protocol/robots.hpp"
#include "andros/run/replay.hpp"
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
  const timing::FrameClock clock(timing::parse_rate(opt.rate, timing::kReplayBaud, SourcePos{"--rate"}));
  const auto format = run::parse_replay_format(opt.format, SourcePos{"--format"});
  auto mapping = opt.mapping.empty() ? mapping::load_robot_mapping(opt.robot.empty() ? protocol::kDefaultRobot : opt.robot)
                                     : mapping::load_mapping(opt.mapping);
  auto script = input::checked_event_script(opt.events == "-" ? TextReader::standard_input(kEventScriptLimits)
                                                       : TextReader::open(opt.events, kEventScriptLimits));

  input::ScriptPlayer player(script);
  mapping::Engine engine(std::move(mapping), mapping::EngineOptions{opt.weapons, code});
  write_frames(opt, [&](std::ostream& out) {
    run::replay(player, engine, clock, [&](std::int64_t t, const protocol::DataBytes& data) { run::write_frame(out, format, t, data); });
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
  cmd->add_option("--robot", opt->robot, "robot type (" + protocol::robot_list() + "); default HD1");
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

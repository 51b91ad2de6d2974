// `andros-bridge learn`: change a mapping's inputs by pressing them.
#include <unistd.h>

#include <cstdio>
#include <memory>

#include "andros/base/error.hpp"
#include "andros/base/shutdown_request.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/cli/learn_session.hpp"
#include "andros/mapping/loader.hpp"
#include "commands.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

struct LearnCommandOptions {
  std::string robot;
  std::string mapping;
  std::string output;
  bool force = false;
  input::SdlInputOptions sdl;
};

int run_learn(const LearnCommandOptions& opt) {
  if (opt.robot.empty() == opt.mapping.empty())
    throw InputError("learn: give --robot NAME or --mapping FILE (one of them)");
  if (opt.output == "-")
    throw InputError(SourcePos{"--output"}, "learn writes a file (its dialogue is on standard output)");
  auto base = mapping::load_chosen_mapping(opt.mapping, opt.robot);
  const auto target = learn_target(*base, opt.output, opt.force);  // checked before the operator does any work
  ShutdownRequest signals(kShutdownSignals);  // SIGTERM, SIGHUP (and SIGINT off a terminal): quit, terminal restored
  input::LiveGestures pad(opt.sdl);
  mapping::LearnPlan plan(*base);
  Keyboard keys(STDIN_FILENO);
  std::printf(
      "learning %s (robot %s, %zu inputs) from %s\n"
      "Enter keeps the input, s skips the rest of this layer, b goes back, w writes now, q quits without writing\n",
      terminal_text(opt.output).c_str(), plan.base().robot.value_or("?").c_str(), plan.steps().size(),
      pad.selection().c_str());
  LearnSession session(plan, pad, keys, stdout);
  while (!signals.requested() && session.step(20)) {
  }
  if (session.end() != LearnSession::End::kWrite) {
    std::printf("quit: %s not written\n", terminal_text(opt.output).c_str());
    return kExitRuntime;
  }
  if (!plan.changed()) {
    std::printf("nothing changed: %s not written\n", terminal_text(opt.output).c_str());
    return kExitOk;
  }
  const auto text = plan.extending_yaml(target.extends, target.over);
  write_learned_or_show(plan, text, opt.output, stdout);  // on failure the YAML on stdout, the reason on stderr
  const auto shown = terminal_text(opt.output);
  std::printf("wrote %s; try it with 'andros-bridge check %s'\n", shown.c_str(), shown.c_str());
  return kExitOk;
}

}  // namespace

void add_learn_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<LearnCommandOptions>();
  auto* cmd =
      app.add_subcommand("learn",
                         "Change a mapping's buttons by pressing them: walks every input of the mapping\n"
                         "(the deadman, each binding, each layer key), shows what it does and its input now,\n"
                         "and takes the next button, stick push or trigger pull on the controller. Enter keeps\n"
                         "the input, s skips the rest of the layer, b goes back, w writes now, q (or Ctrl-C)\n"
                         "quits without writing. An input already used in the same layer is refused. Writes a\n"
                         "mapping that extends the one learned from with only what changed (extends: ROBOT\n"
                         "for a robot's mapping), loaded and checked before it is written; if it cannot be\n"
                         "written, it is printed instead. See docs/mapping.md (Changing buttons with learn).\n"
                         "Exit: 0 written or nothing changed, 1 quit, 2 bad options or mapping.");
  cmd->add_option("--robot", opt->robot, "the robot whose mapping to learn from (as 'run --robot' finds it)")
      ->type_name("NAME");
  cmd->add_option("--mapping", opt->mapping, "the mapping file to learn from")->type_name("FILE");
  cmd->add_option("--output,-o", opt->output,
                  "the mapping file to write; its missing folders are made. An existing FILE\n"
                  "is refused unless --force")
      ->type_name("FILE")
      ->required();
  cmd->add_flag("--force", opt->force,
                "replace an existing --output FILE (only once the new file is written whole;\n"
                "its mode kept). FILE may be the mapping learned from: the new file then\n"
                "extends what FILE extended, so learn can be run again on its own output");
  add_sdl_options(cmd, opt->sdl);
  cmd->callback([opt, &exit_code] { exit_code = run_learn(*opt); });
}

}  // namespace andros::cli

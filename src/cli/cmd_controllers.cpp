// `andros-bridge controllers`: what SDL sees, and how to choose among it.
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>

#include "andros/base/error.hpp"
#include "andros/base/sink_text.hpp"
#include "andros/input/sdl_input.hpp"
#include "commands.hpp"
#include "sdl_options.hpp"

namespace andros::cli {
namespace {

struct ControllersOptions {
  input::SdlInputOptions sdl;
  bool json = false;
};

int run_controllers(const ControllersOptions& opt) {
  const auto list = input::list_controllers(opt.sdl);
  if (opt.json) {
    for (const auto& c : list) {
      // A name is bytes from the device: escaped, so that the line is JSON whatever they are.
      const nlohmann::json line = {{"index", c.index},
                                   {"name", json_text(c.name)},
                                   {"guid", json_text(c.guid)},
                                   {"type", c.game_controller ? "controller" : "joystick"},
                                   {"path", json_text(c.path)}};
      std::printf("%s\n", line.dump().c_str());
    }
    return kExitOk;
  }
  if (list.empty()) {
    std::fprintf(stderr, "no controllers found (see docs/controllers.md if one is plugged in)\n");
    return kExitOk;
  }
  std::printf("%-5s  %-10s  %-32s  %-18s  %s\n", "INDEX", "TYPE", "GUID", "PATH", "NAME");
  for (const auto& c : list) {
    std::printf("%-5d  %-10s  %-32s  %-18s  %s\n", c.index, c.game_controller ? "controller" : "joystick",
                terminal_text(c.guid).c_str(), c.path.empty() ? "-" : terminal_text(c.path).c_str(),
                terminal_text(c.name).c_str());
  }
  return kExitOk;
}

}  // namespace

void add_controllers_command(CLI::App& app, int& exit_code) {
  auto opt = std::make_shared<ControllersOptions>();
  auto* cmd = app.add_subcommand("controllers",
                                 "List the attached controllers: index, type (game controller, or plain joystick\n"
                                 "with numbered buttons, axes and hats), GUID, device path and name. Any of them\n"
                                 "can be given to --controller.");
  // Only the mappings matter here: they decide the type and name shown.
  add_controller_db_option(cmd, opt->sdl);
  cmd->add_flag("--json", opt->json,
                "one JSON object per controller per line: index, name, guid, type "
                "(\"controller\" or \"joystick\"), path");
  cmd->callback([opt, &exit_code] { exit_code = run_controllers(*opt); });
}

}  // namespace andros::cli

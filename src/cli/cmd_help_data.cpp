// `andros-bridge help-data`: the command line as JSON, walked from the same
// CLI11 definitions that print --help, and the config file's keys from the
// settings table. The man pages andros-bridge(1) and andros-bridge.conf(5)
// and the bash completion are generated from it at build time (scripts/man/),
// so that none can drift from the program.
#include <CLI/CLI.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include "andros/base/error.hpp"
#include "andros/base/version.hpp"
#include "andros/cli/settings.hpp"
#include "andros/protocol/robots.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

nlohmann::json describe_option(const CLI::Option& o) {
  return {{"names", o.get_lnames()},
          {"short", o.get_snames()},
          {"positional", o.get_positional() ? o.get_name() : ""},
          {"value", o.get_items_expected_min() > 0 ? o.get_type_name() : ""},
          {"default", o.get_default_str()},
          {"required", o.get_required()},
          {"help", o.get_description()}};
}

nlohmann::json describe_app(const CLI::App& app) {
  nlohmann::json options = nlohmann::json::array();
  for (const auto* o : app.get_options()) {
    if (!o->get_group().empty()) options.push_back(describe_option(*o));
  }
  nlohmann::json commands = nlohmann::json::array();
  for (const auto* sub : app.get_subcommands({})) {
    if (!sub->get_group().empty()) commands.push_back(describe_app(*sub));
  }
  return {{"name", app.get_name()},
          {"description", app.get_description()},
          {"footer", app.get_footer()},
          {"options", options},
          {"commands", commands}};
}

}  // namespace

void add_help_data_command(CLI::App& app, int& exit_code) {
  auto* cmd = app.add_subcommand("help-data", "the command line as JSON, for the man page and completion");
  cmd->group("");  // not listed in --help: a build step's input, not an operator's command
  cmd->callback([&app, &exit_code] {
    nlohmann::json data = describe_app(app);
    data["version"] = kVersion;
    data["config_keys"] = nlohmann::json::array();
    for (const auto& row : settings_table()) {
      if (row.key.empty()) continue;
      data["config_keys"].push_back({{"key", row.key},
                                     {"flag", flag_name(row)},
                                     {"value", row.value_name},
                                     {"default", default_text(row)},
                                     {"help", help_text(row)},
                                     {"file_relative", row.file_relative}});
    }
    data["robots"] = nlohmann::json::array();
    for (const auto robot : protocol::kRobotTypes) data["robots"].push_back(robot);
    std::cout << data.dump(1) << '\n';
    exit_code = kExitOk;
  });
}

}  // namespace andros::cli

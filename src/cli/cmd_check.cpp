// `andros-bridge check FILE...`: load and validate mapping files.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "andros/error.hpp"
#include "andros/mapping_loader.hpp"
#include "commands.hpp"

namespace andros::cli {

void add_check_command(CLI::App& app, int& exit_code) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto* cmd = app.add_subcommand(
      "check",
      "Load and validate mapping files: prints 'FILE: ok' for each good one and the\n"
      "error (FILE:LINE:COL: error: ...) for each bad one; exits 2 if any is bad.\n"
      "A file with no 'robot:' is checked as a base for other files to extend.");
  cmd->add_option("FILE", *files, "mapping files (YAML)")->required();
  cmd->callback([files, &exit_code] {
    bool all_ok = true;
    for (const auto& file : *files) {
      try {
        const auto mapping = load_mapping_file(file);
        validate(mapping, mapping.robot.has_value());
        std::printf("%s: ok%s\n", file.c_str(), mapping.robot ? "" : " (a base mapping: no robot)");
      } catch (const InputError& e) {
        std::fflush(stdout);
        std::fprintf(stderr, "%s\n", e.what());
        all_ok = false;
      }
    }
    std::fflush(stdout);
    exit_code = all_ok ? kExitOk : kExitBadInput;
  });
}

}  // namespace andros::cli

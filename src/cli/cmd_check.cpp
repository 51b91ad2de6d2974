// `andros-bridge check FILE...`: load and validate mapping files.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "andros/base/error.hpp"
#include "andros/mapping/loader.hpp"
#include "commands.hpp"

namespace andros::cli {
namespace {

/// Loads, but would surprise the operator: a stick driving drive or pivot with
/// no deadzone must read exactly 0 to count as at rest after the deadman press
/// or a layer change (the rest rule), which a worn stick may never do.
std::vector<std::string> warnings(const mapping::Mapping& mapping) {
  std::vector<std::string> out;
  for (const auto ref : mapping::all_bindings(mapping)) {
    const auto& b = mapping::binding_at(mapping, ref);
    const auto* axis = std::get_if<mapping::AxisBinding>(&b.rule);
    if (axis == nullptr || protocol::info(axis->analog).kind != protocol::SignalKind::kCentred || axis->shape.deadzone > 0) continue;
    out.push_back(format_error(b.pos,
                               "no deadzone on the stick driving '" + std::string(protocol::info(axis->analog).name) +
                                   "': after the deadman press or a layer change it acts only once it reads "
                                   "exactly 0 (give it a deadzone, e.g. 0.1)",
                               "warning"));
  }
  return out;
}

}  // namespace

void add_check_command(CLI::App& app, int& exit_code) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto* cmd = app.add_subcommand(
      "check",
      "Load and validate mapping files: prints 'FILE: ok' for each good one and the\n"
      "error (FILE:LINE:COL: error: ...) for each bad one; exits 2 if any is bad.\n"
      "A file with no 'robot:' is checked as a base for other files to extend. Warnings\n"
      "(FILE:LINE:COL: warning: ...) point at what loads but may surprise: a stick on\n"
      "drive or pivot with no deadzone. They do not change the exit code. A 'center:'\n"
      "trim other than 128 is said on the ok line: 'FILE: ok (center 124: drive and\n"
      "pivot rest at 124 while enabled; neutral frames carry 128)'.");
  cmd->add_option("FILE", *files, "mapping files (YAML)")->required();
  cmd->callback([files, &exit_code] {
    bool all_ok = true;
    for (const auto& file : *files) {
      try {
        const auto mapping = mapping::load_mapping_file(file);
        validate(mapping, mapping.robot.has_value());
        std::string notes = mapping.robot ? "" : "a base mapping: no robot";
        if (const auto trim = mapping::center_effect(mapping.center); !trim.empty()) {
          notes += (notes.empty() ? "" : "; ") + trim;
        }
        if (!notes.empty()) notes = " (" + notes + ")";
        std::printf("%s: ok%s\n", file.c_str(), notes.c_str());
        std::fflush(stdout);
        for (const auto& w : warnings(mapping)) std::fprintf(stderr, "%s\n", w.c_str());
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

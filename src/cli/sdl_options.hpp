#pragma once
// The live controller's flags, shared by `run`, `record` and `controllers`.

#include <CLI/CLI.hpp>

#include "andros/input/sdl_input.hpp"

namespace andros::cli {

/// Adds --controller-db FILE to cmd, filling opts.controller_db.
inline void add_controller_db_option(CLI::App* cmd, input::SdlInputOptions& opts) {
  cmd->add_option("--controller-db", opts.controller_db,
                  "a file of extra SDL controller mappings (gamecontrollerdb.txt format); the\n"
                  "SDL_GAMECONTROLLERCONFIG environment variable is read as well")
      ->type_name("FILE");
}

/// Adds --controller INDEX|NAME|GUID|PATH and --controller-db FILE to cmd, filling
/// opts. opts must outlive parsing (hold it in a shared_ptr like the other
/// commands' options).
inline void add_sdl_options(CLI::App* cmd, input::SdlInputOptions& opts) {
  cmd->add_option("--controller", opts.controller,
                  "which controller to use when several are attached: INDEX (as 'andros-bridge\n"
                  "controllers' lists them), GUID (32 hex digits), PATH (its device node or a\n"
                  "link to it, such as /dev/input/by-path/...: the pad in that port) or NAME\n"
                  "(case-insensitive, a part is enough); the others are ignored. Default: the first\n"
                  "one found")
      ->type_name("INDEX|NAME|GUID|PATH");
  add_controller_db_option(cmd, opts);
}

}  // namespace andros::cli

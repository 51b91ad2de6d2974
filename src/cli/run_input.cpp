// The seam between `run` and the SDL input source (issue 4's SDL half, built
// in parallel): when include/andros/sdl_input.hpp is in the tree, `--input
// sdl` uses its factory; until then it is a clear error and scripts still run.
#include "run_input.hpp"

#include <CLI/CLI.hpp>

#include "andros/error.hpp"
#include "andros/io/script_input.hpp"

#if __has_include("andros/sdl_input.hpp")
#include "andros/sdl_input.hpp"
#include "sdl_options.hpp"
#define ANDROS_HAVE_SDL_INPUT 1
#else
#define ANDROS_HAVE_SDL_INPUT 0
#endif

namespace andros::cli {
namespace {

#if ANDROS_HAVE_SDL_INPUT
SdlInputOptions& sdl_options() {
  static SdlInputOptions options;
  return options;
}
#endif

}  // namespace

void add_sdl_input_options([[maybe_unused]] CLI::App& run) {
#if ANDROS_HAVE_SDL_INPUT
  add_sdl_options(&run, sdl_options());  // --controller, --controller-db
#endif
}

std::unique_ptr<InputSource> make_input_source(const std::string& input) {
  if (input != "sdl") return std::make_unique<io::ScriptInput>(input);
#if ANDROS_HAVE_SDL_INPUT
  return make_sdl_input_source(sdl_options());
#else
  throw InputError(SourcePos{"--input"},
                   "this build has no SDL controller input yet; play an event script with "
                   "--input FILE (e.g. --input demos/drive.events)");
#endif
}

}  // namespace andros::cli

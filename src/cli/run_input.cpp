#include "run_input.hpp"

#include "andros/base/error.hpp"
#include "andros/cli/settings.hpp"
#include "andros/input/script_input.hpp"

namespace andros::cli {

std::unique_ptr<input::InputSource> make_input_source(const std::string& input, const input::SdlInputOptions& sdl,
                                                      const StopCheck& stop) {
  if (input != kSdlInput) {
    // Silently ignored, it would leave the operator believing the pad they named drives.
    if (!sdl.controller.empty()) {
      throw InputError(SourcePos{"--controller"}, "chooses a live controller, but the input is the event script " +
                                                      quote(input) + " (--controller goes with --input sdl)");
    }
    return std::make_unique<input::ScriptInput>(input, stop);
  }
  return input::make_sdl_input_source(sdl, stop);
}

}  // namespace andros::cli

#include "run_input.hpp"

#include "andros/io/script_input.hpp"

namespace andros::cli {

std::unique_ptr<InputSource> make_input_source(const std::string& input, const SdlInputOptions& sdl,
                                               const StopCheck& stop) {
  if (input != "sdl") return std::make_unique<io::ScriptInput>(input, stop);
  return make_sdl_input_source(sdl, stop);
}

}  // namespace andros::cli

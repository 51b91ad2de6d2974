#pragma once
// Where `run` gets controller events: an event script, or SDL.

#include <memory>
#include <string>

#include "andros/input_source.hpp"

namespace CLI {
class App;
}

namespace andros::cli {

/// Adds the SDL input's own flags to `run`, when this build has it.
void add_sdl_input_options(CLI::App& run);

/// "sdl" -> the live controller; anything else -> an event script played in
/// real time. Throws InputError for a bad script, or for "sdl" in a build
/// without SDL input.
std::unique_ptr<InputSource> make_input_source(const std::string& input);

}  // namespace andros::cli

#pragma once
// Where `run` gets controller events: an event script, or SDL.

#include <memory>
#include <string>

#include "andros/base/text_file.hpp"
#include "andros/input/input_source.hpp"
#include "andros/input/sdl_input.hpp"

namespace andros::cli {

/// "sdl" -> the live controller chosen by sdl; anything else -> an event
/// script played in real time. Throws InputError for a bad script, a bad
/// controller database or a controller chosen (--controller) for a script;
/// ReadStopped when stop says so while either is read.
std::unique_ptr<input::InputSource> make_input_source(const std::string& input, const input::SdlInputOptions& sdl,
                                                      const StopCheck& stop);

}  // namespace andros::cli

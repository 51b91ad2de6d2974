#pragma once
// Where `run` gets controller events: an event script, or SDL.

#include <memory>
#include <string>

#include "andros/input_source.hpp"
#include "andros/sdl_input.hpp"
#include "andros/text_file.hpp"

namespace andros::cli {

/// "sdl" -> the live controller chosen by sdl; anything else -> an event
/// script played in real time. Throws InputError for a bad script or a bad
/// controller database, ReadStopped when stop says so while either is read.
std::unique_ptr<InputSource> make_input_source(const std::string& input, const SdlInputOptions& sdl,
                                               const StopCheck& stop);

}  // namespace andros::cli

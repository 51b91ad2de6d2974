#include "andros/input/script_input.hpp"

#include "andros/input/events.hpp"

namespace andros::input {

ScriptInput::ScriptInput(const std::string& path, const StopCheck& stop)
    : text_(checked_event_script(hold_in_memory(TextReader::open(path, kEventScriptLimits, stop)))),
      player_(std::make_unique<ScriptPlayer>(text_)) {}

}  // namespace andros::input

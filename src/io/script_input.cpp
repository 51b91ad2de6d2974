#include "andros/io/script_input.hpp"

#include "andros/events.hpp"

namespace andros::io {

ScriptInput::ScriptInput(const std::string& path, const StopCheck& stop)
    : text_(checked_event_script(hold_in_memory(TextReader::open(path, kEventScriptLimits, stop)))),
      player_(std::make_unique<ScriptPlayer>(text_)) {}

}  // namespace andros::io

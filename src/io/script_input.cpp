#include "andros/io/script_input.hpp"

#include <fstream>

#include "andros/error.hpp"
#include "andros/events.hpp"

namespace andros::io {

ScriptInput::ScriptInput(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourcePos{path}, "cannot read the event script");
  std::ostringstream all;
  all << in.rdbuf();
  parse_event_script(all.str(), path);  // throws on the first bad line
  text_.str(all.str());
  player_ = std::make_unique<ScriptPlayer>(text_, path);
}

}  // namespace andros::io

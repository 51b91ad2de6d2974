#pragma once
/// Event scripts (contract section 3): what `record` writes and what `replay`
/// and `run --input` read. One event a line: `T_MS EVENT ARGS`, `#` comments.

#include <cstdint>
#include <istream>
#include <optional>
#include <string>
#include <vector>

#include "andros/input.hpp"

namespace andros {

/// Reads a script one event at a time, so a long script needs no memory to
/// speak of. Every error is an InputError at FILE:LINE:COL.
class EventReader {
 public:
  EventReader(std::istream& in, std::string file_name) : in_(in), file_(std::move(file_name)) {}

  /// The next event, or nullopt at the end of the text. An `end` event is
  /// returned like any other; anything after it is an error.
  std::optional<InputEvent> next();

 private:
  std::istream& in_;
  std::string file_;
  int line_no_ = 0;
  std::int64_t last_t_ = 0;
  bool ended_ = false;
};

/// Parses a whole script held in memory.
std::vector<InputEvent> parse_event_script(const std::string& text, const std::string& file_name);

/// One event as a script line (`120     axis        lefty -32768`), no newline.
std::string format_event(const InputEvent& event);

}  // namespace andros

#pragma once
/// Event scripts (docs/event-scripts.md): what `record` writes and what `replay`
/// and `run --input` read. One event a line: `T_MS EVENT ARGS`, `#` comments.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/text_file.hpp"
#include "andros/input/input_state.hpp"

namespace andros::input {

/// The latest time an event may have: a script lasts at most a day.
inline constexpr std::int64_t kMaxScriptMs = std::int64_t{24} * 3600 * 1000;
/// The longest controller name a `connect` line may carry, so that every
/// event written back (`record`) stays far inside the line bound.
inline constexpr std::size_t kMaxControllerNameBytes = 256;

/// Reads a script one event at a time, so a long script needs no memory to
/// speak of. Every error is an InputError at FILE:LINE:COL.
class EventReader {
 public:
  explicit EventReader(TextReader& text) : text_(text) {}

  /// The next event, or nullopt at the end of the text. An `end` event is
  /// returned like any other; anything after it is an error.
  std::optional<InputEvent> next();

 private:
  TextReader& text_;
  std::int64_t last_t_ = 0;
  bool ended_ = false;
};

/// Parses a whole script held in memory.
std::vector<InputEvent> parse_event_script(const std::string& text, const std::string& file_name);

/// text checked to its end (every line, nothing after `end`, no time past
/// kMaxScriptMs) and rewound, so that no bad line is found once the script
/// plays. A stream (pipe, FIFO, standard input) is held in memory for that; a
/// regular file is read twice.
TextReader checked_event_script(TextReader text);

/// Whether a line of text addresses the supervisor's controller (`T
/// supervisor EVENT`): such a script runs with a supervisor's controller
/// configured from its start (docs/event-scripts.md). Reads text to its end
/// (or to its first line over the limits, which playing it reports) and
/// rewinds it: text must be able to rewind and be unread.
bool addresses_supervisor(TextReader& text);

/// One event as a script line (`120     axis        lefty -32768`), no newline.
std::string format_event(const InputEvent& event);

}  // namespace andros::input

// libFuzzer target: the event-script parser. Any text either parses or is
// rejected with an InputError that names the file and a line inside the text;
// what parses keeps the script's bounds (nothing after `end`, no time past a
// day, no line over the limit), and written back with format_event parses to
// the same events.
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "andros/base/error.hpp"
#include "andros/input/events.hpp"
#include "fuzz_check.hpp"

using andros::fuzz::check;

namespace {

std::size_t longest_line(std::string_view text) {
  std::size_t longest = 0;
  while (!text.empty()) {
    const auto nl = std::min(text.find('\n'), text.size());
    longest = std::max(longest, nl);
    text.remove_prefix(std::min(nl + 1, text.size()));
  }
  return longest;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<andros::input::InputEvent> events;
  // The check before a script plays agrees with the parser, line for line.
  int checked_line = 0;
  try {
    (void)andros::input::checked_event_script(andros::TextReader(text, "fuzz.events", andros::kEventScriptLimits));
  } catch (const andros::InputError& e) {
    checked_line = e.pos().line;
  }
  try {
    events = andros::input::parse_event_script(text, "fuzz.events");
  } catch (const andros::InputError& e) {
    check(e.pos().file == "fuzz.events");
    check(e.pos().line >= 1);
    check(e.pos().line == checked_line);
    return 0;
  }
  check(checked_line == 0);
  check(longest_line(text) <= andros::kMaxLineBytes);
  for (std::size_t i = 0; i < events.size(); ++i) {
    check(events[i].t_ms >= 0 && events[i].t_ms <= andros::input::kMaxScriptMs);
    check(events[i].type != andros::input::InputEvent::Type::kEnd || i + 1 == events.size());
  }
  std::string again;
  for (const auto& e : events) again += andros::input::format_event(e) + "\n";
  const auto reparsed = andros::input::parse_event_script(again, "again.events");
  check(reparsed.size() == events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    check(reparsed[i].t_ms == events[i].t_ms);
    check(reparsed[i].type == events[i].type);
    check(reparsed[i].key == events[i].key);
    check(reparsed[i].value == events[i].value);
  }
  return 0;
}

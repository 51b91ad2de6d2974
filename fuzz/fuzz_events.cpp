// libFuzzer target: the event-script parser. Any text either parses or is
// rejected with an InputError that names the file and a line inside the text;
// what parses, written back with format_event, parses to the same events.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "andros/error.hpp"
#include "andros/events.hpp"
#include "fuzz_check.hpp"

using andros::fuzz::check;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<andros::InputEvent> events;
  try {
    events = andros::parse_event_script(text, "fuzz.events");
  } catch (const andros::InputError& e) {
    check(e.pos().file == "fuzz.events");
    check(e.pos().line >= 1);
    return 0;
  }
  std::string again;
  for (const auto& e : events) again += andros::format_event(e) + "\n";
  const auto reparsed = andros::parse_event_script(again, "again.events");
  check(reparsed.size() == events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    check(reparsed[i].t_ms == events[i].t_ms);
    check(reparsed[i].type == events[i].type);
    check(reparsed[i].key == events[i].key);
    check(reparsed[i].value == events[i].value);
  }
  return 0;
}

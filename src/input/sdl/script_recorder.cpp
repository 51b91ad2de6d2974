#include "andros/input/script_recorder.hpp"

#include <sstream>

#include "andros/base/clock.hpp"
#include "andros/base/error.hpp"
#include "andros/input/events.hpp"

namespace andros::input {
namespace {

void write_line(std::ostream& out, const std::string& line) {
  out << line << '\n';
  if (!out) throw RuntimeError("cannot write the event script");
}

}  // namespace

RecordStatus record_script(SdlInput& input, std::ostream& out, const RecordOptions& options, ShutdownRequest& stop,
                           const std::function<bool(const RecordStatus&)>& keep_going) {
  std::istringstream header(options.header);
  for (std::string line; std::getline(header, line);) write_line(out, "# " + line);
  out.flush();

  const auto grid = TickGrid::every(std::int64_t{options.period_ms} * kNsPerMs);
  const std::int64_t start_ns = monotonic_ns();
  RecordStatus status;
  std::int64_t tick = 0;
  while (true) {
    if (tick * options.period_ms > options.max_ms) {
      status.at_limit = true;
      break;
    }
    status.t_ms = tick * options.period_ms;
    const auto& events = input.poll(status.t_ms);
    bool wrote = !events.empty();
    for (const auto& event : events) {
      write_line(out, format_event(event));
      bool& connected = event.pad == Pad::kSupervisor ? status.supervisor_connected : status.connected;
      if (event.type == InputEvent::Type::kConnect) connected = true;
      if (event.type == InputEvent::Type::kDisconnect) connected = false;
    }
    if (tick == 0 && input.supervised() && !status.supervisor_connected) {
      // The script says a supervisor was configured even if its controller never comes: replay then
      // needs it, as the live run did (docs/event-scripts.md).
      InputEvent absent;
      absent.t_ms = status.t_ms;
      absent.type = InputEvent::Type::kDisconnect;
      absent.pad = Pad::kSupervisor;
      write_line(out, format_event(absent));
      wrote = true;
    }
    if (wrote) out.flush();  // a killed recording keeps what it saw
    status.events += static_cast<std::int64_t>(events.size());
    status.tick = tick + 1;
    if (!keep_going(status) || stop.requested()) break;
    tick = grid.next_tick(tick, monotonic_ns() - start_ns);
    if (!stop.sleep_until(start_ns + grid.tick_ns(tick))) break;
  }
  InputEvent end;
  end.t_ms = status.t_ms;
  end.type = InputEvent::Type::kEnd;
  write_line(out, format_event(end));
  out.flush();
  return status;
}

}  // namespace andros::input

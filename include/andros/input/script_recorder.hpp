#pragma once
/// `andros-bridge record`: the live controller's events written as an event
/// script (docs/event-scripts.md) that replay and `run --input` read back.

#include <cstdint>
#include <functional>
#include <ostream>
#include <string>

#include "andros/base/shutdown_request.hpp"
#include "andros/input/events.hpp"
#include "andros/input/sdl_input.hpp"

namespace andros::input {

struct RecordOptions {
  /// How often the controller is read. The bridge's own period (40 ms at
  /// 25 Hz) makes a replay see each event in the frame the live bridge did.
  int period_ms = 40;
  /// Written first, each line prefixed with "# ".
  std::string header;
  /// The recording ends here at the latest, so that `replay` and `run
  /// --input` take what it wrote (a script lasts at most a day).
  std::int64_t max_ms = kMaxScriptMs;
};

/// What the recording has reached, for a progress line and for stopping.
struct RecordStatus {
  std::int64_t tick = 0;  ///< ticks done so far
  std::int64_t t_ms = 0;  ///< time of the last tick, ms from the start
  std::int64_t events = 0;
  bool connected = false;
  bool supervisor_connected = false;  ///< the supervisor's controller (record --supervisor)
  bool at_limit = false;              ///< ended at RecordOptions::max_ms, not by keep_going
};

/// Reads input every period on absolute time (a TickGrid: missed ticks are
/// skipped, not burst) and writes each event as a script line, t_ms from the
/// start (with a supervisor's controller not there at the start, `0
/// supervisor disconnect`, so that the script has one configured), until a stop request (which also ends the wait
/// between two ticks) or keep_going returning false; then writes `T end`. keep_going runs after every tick. Throws
/// RuntimeError when out fails. Ends by itself at options.max_ms. Returns where it ended.
RecordStatus record_script(SdlInput& input, std::ostream& out, const RecordOptions& options, ShutdownRequest& stop,
                           const std::function<bool(const RecordStatus&)>& keep_going);

}  // namespace andros::input

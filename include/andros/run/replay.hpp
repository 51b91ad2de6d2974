#pragma once
/// Replay (docs/event-scripts.md): an event script through the run loop
/// itself (Bridge) on a virtual clock, with the script as the input and a
/// sink as the link. Same script, same mapping, same options: same bytes, on
/// any machine, at any speed, fault events (link, suspend, reload, stop)
/// included. The CLI's `replay` is a thin wrapper over this.

#include <cstdint>
#include <functional>
#include <memory>
#include <string>

#include "andros/base/error.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/engine.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// A frame the vehicle received: its time (ms since start) and data bytes.
using FrameSink = std::function<void(std::int64_t t_ms, const protocol::DataBytes& data)>;
/// A script's `reload FILE`: the mapping in FILE (as the script names it),
/// validated; throws for a bad one or one it cannot read (InputError,
/// RuntimeError...): the old mapping then stays, as in `run`.
using MappingLoader = std::function<mapping::ValidMapping(const std::string& file)>;

struct ReplayOptions {
  std::int64_t rate_millihertz = timing::kDefaultRateMillihertz;
  mapping::EngineOptions engine;
  /// For `reload`: FILE, or the running mapping's file when the event names none.
  MappingLoader load = [](const std::string& file) -> mapping::ValidMapping {
    throw InputError("reload " + file + ": no mapping loader in this replay");
  };
  /// Each reload's outcome, when it is taken: a failed one is said (`replay` logs it) and the replay goes on.
  std::function<void(std::int64_t t_ms, const ReloadOutcome& outcome)> reloaded = [](std::int64_t,
                                                                                     const ReloadOutcome&) {};
  /// Every tick's report (the state machine's state with it), for tests.
  Bridge::Observer observe = [](const TickReport&) {};
  /// Every frame the link took, as its bytes on the wire, before that tick's report: for tests that read
  /// the encoding itself (the fault simulation).
  std::function<void(std::int64_t t_ms, const protocol::Frame& frame)> wire = [](std::int64_t, const protocol::Frame&) {
  };
  /// The link the loop sends to, for tests (the fault simulation's TCP link to a scripted server); frames it
  /// takes reach the sink as the sink link's do. nullptr: the sink link, which takes every frame.
  link::Link* link = nullptr;
  /// Each engine as the loop's frame source (the first, and each reload's): for tests that put an engine at fault
  /// before the frame gate (the fault simulation, tests/support/faulty_frames.hpp).
  std::function<std::unique_ptr<FrameSource>(std::unique_ptr<FrameSource>)> frames =
      [](std::unique_ptr<FrameSource> source) { return source; };
};

/// Runs the loop from t = 0 through the first frame time >= the script's end
/// (its `end`, or its last event: no neutral tail, as docs/event-scripts.md
/// has it; a `stop` event ends on a stop's neutral frames), each frame
/// reflecting every event with a time <= its own; frames the link did not take (a `link down`, a suspend)
/// are not delivered. Returns the count delivered.
std::int64_t replay(input::ScriptPlayer& player, mapping::Engine engine, const ReplayOptions& options,
                    const FrameSink& sink);

}  // namespace andros::run

#pragma once
/// The one assembly of the run loop (docs/architecture.md, "One loop"):
/// `run` and `trainer` (cli/cmd_run.cpp), `replay` (replay.hpp) and a
/// session's replay (record/session_replay.hpp) each describe the loop's
/// parts, and run_loop() puts them together and runs them. What differs
/// between the commands is only in the parts: no command builds a Bridge of
/// its own.

#include <vector>

#include "andros/base/clock.hpp"
#include "andros/input/input_source.hpp"
#include "andros/link/link.hpp"
#include "andros/run/bridge.hpp"

namespace andros::run {

/// The loop's parts, as a command describes them.
struct LoopParts {
  /// When ticks come: a RealClock live; a VirtualClock in a replay (the session's replay moves it as the live
  /// clock moved).
  Clock& clock;
  /// Where input comes from: the SDL pad, an event script, a session's events (recorded or watched on the way).
  input::InputSource& input;
  /// The frame source: the engine the mapping makes (a reload's comes in its outcome).
  FrameSource& frames;
  /// Where frames go: serial, TCP, the simulated vehicle, a replay's sink, a session's recorded answers.
  link::Link& link;
  /// The rate, the frame gate's rules, whether the end of the input ends on neutral frames.
  BridgeOptions options;
  /// What the world asks (requests), the pause after a suspend, a reload's reading.
  RunControl control;
  /// Who reads each tick's report, in this order (the recorder, the status board, a replay's sink...).
  std::vector<Bridge::Observer> observers;
};

/// Builds the loop from parts and runs it until a shutdown or the end of
/// the input (Bridge::run). Returns how its last neutral frames went; an
/// InputError from a script escapes after them.
ShutdownReport run_loop(const LoopParts& parts);

}  // namespace andros::run

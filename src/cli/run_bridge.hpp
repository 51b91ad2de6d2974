#pragma once
// `run`'s loop with its set-up, for `run` and `trainer` (cmd_trainer.cpp):
// the trainer is the same loop with a few hooks, never a second copy of it.
#include <functional>
#include <memory>
#include <string>

#include "andros/base/shutdown_request.hpp"
#include "andros/cli/command_line.hpp"
#include "andros/input/input_source.hpp"
#include "andros/input/sdl_input.hpp"
#include "andros/link/vehicle_view.hpp"
#include "andros/run/bridge.hpp"
#include "andros/view/status_board.hpp"

namespace andros::cli {

struct RunOptions {
  std::unique_ptr<CommandLine> settings;  ///< every setting's flag (the settings table)
  input::SdlInputOptions sdl;             ///< --controller, --controller-db
};

/// What `trainer` adds to `run` (`run` itself passes none).
struct RunHooks {
  /// The settings resolved, before anything is opened: throws InputError for what the command refuses.
  std::function<void(const Settings&)> check;
  /// Before the loop starts (after every check): what the command sets up; returns the status view's
  /// trainer line.
  std::function<std::string(const Settings&)> start;
  /// The simulated vehicle's decoded frames, on its thread, as they arrive.
  link::VehicleView::FrameObserver frames;
  /// The input the loop reads, wrapped (the loop's thread calls it).
  std::function<input::InputSource&(input::InputSource&)> input;
  /// After each tick, on the loop's thread, with the board after it.
  std::function<void(const run::TickReport&, const view::RunStatusBoard&)> observe;
  /// After the loop's neutral frames, before the closing lines (the trainer keeps its page up).
  std::function<void(ShutdownRequest&)> after_run;
  /// Records the command adds to the session (their payloads): after its header (the trainer's course), and
  /// before its end record (the trainer's score).
  std::function<std::string()> opening_record;
  std::function<std::string()> closing_record;
};

int run_bridge(const RunOptions& opt, const RunHooks& hooks);

}  // namespace andros::cli

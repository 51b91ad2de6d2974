#pragma once
// What `run` tells the operator: the board that the run loop's reports feed,
// every tick, and that the terminal display's thread reads a copy of; off a
// terminal, one log line per change.

#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/input_source.hpp"
#include "andros/run/bridge.hpp"
#include "andros/timing/frame_timing.hpp"
#include "andros/view/operator_screens.hpp"

namespace andros::view {

/// The first cause of the operating state, followed from the machine's
/// transitions: the transition that brought the machine into its state (a
/// link regained, a reload done, a resume, the supervisor's controller
/// back...). A link that opened rather than came back (the first time, or
/// again after the bridge's own close for a suspend) is no cause: the cause
/// before it stays (none at start-up, the resume after a suspend).
class FirstCause {
 public:
  /// A report's transitions, in order.
  void follow(const std::vector<run::ReportedTransition>& transitions);
  /// None before the first change of state.
  [[nodiscard]] const std::optional<run::Transition>& transition() const { return cause_; }

 private:
  std::optional<run::Transition> cause_;
  bool link_lost_ = false;  ///< the link was lost (not closed by the loop) since it was last up
};

class RunStatusBoard {
 public:
  /// initial: what set-up knows (robot, code, rate, input, link name, centre).
  explicit RunStatusBoard(RunStatus initial) : status_(std::move(initial)) {}

  /// Called by the run loop after every tick. The report is all the board
  /// learns: it holds no link and no engine. A report that says what the
  /// last one said but for the frame, its time and the counters moves only
  /// those: no words are formed and nothing is logged.
  void observe(const run::TickReport& report);
  /// The same, for a run whose input may be a live controller: on a connect,
  /// first asks input what kind of device it is (set_game_controller). On the
  /// thread that pumps input (SDL's).
  void observe(const run::TickReport& report, const input::InputSource& input);
  /// After a reload: the robot and mapping file the view names, whether
  /// weapons are enabled, and the centre its gauges grow from.
  void set_mapping(std::string robot, std::string mapping_file, bool weapons, int center);
  /// Whether the mapping reads game-controller names: at start and after a reload.
  void set_pad_names(bool pad_names);
  /// What kind of device the live controller is, told by whoever owns it (on
  /// each connect, before the report of that tick): see joystick_note().
  void set_game_controller(std::optional<bool> game_controller);
  /// The last status, copied under the lock, with the rate and jitter of the
  /// frames sent as they stand now: for the display thread, and after the run
  /// for the closing line.
  [[nodiscard]] RunStatus status() const;

 private:
  /// What changed, logged: the state's lines on its transitions (a stop
  /// that latched or became another's, a state entered), the rest when its
  /// words changed.
  void log_changes(const RunStatus& before, const RunStatus& after,
                   const std::vector<run::ReportedTransition>& transitions) const;

  mutable std::mutex mutex_;
  RunStatus status_;
  timing::FrameTiming timing_;
  /// The last report whose words were formed; none before the first, or when they must be formed again.
  std::optional<run::TickReport> said_;
  FirstCause cause_;
  bool first_tick_ = true;
  bool was_connected_ = false;  ///< as the last report said, for observe(report, input)
};

/// "enabled", or why not ("deadman released"); while enabled, the inputs the
/// rest rule still holds back ("enabled; at rest first: lefty"), so that a
/// stick pushed through the deadman press explains itself.
std::string enable_text(const mapping::EngineStatus& status);

/// Enabled: the inputs the rest rule still holds back ("lefty a"); "" when none is, or not enabled.
std::string held_back_text(const mapping::EngineStatus& status);

/// What "stopped" asks, and of whom (the state line, after who stopped): a
/// stop button held first ("release the stop button"), a reset gesture under
/// way (its progress), or who may reset and with which gesture, and what to do
/// when nobody here may (the pad that stopped is gone, a mapping without a
/// reset): the supervisor resets, or the bridge is restarted.
std::string stopped_text(const run::TickReport& report);

/// Stopped, a reset gesture under way: "resetting: 1.2 of 2.0 s (back+start
/// held; a stop or the deadman ends it)"; "" when none is.
std::string reset_progress_text(const run::TickReport& report);

/// Who stopped, for the STOP banner, the log and the state line: "stopped by
/// the supervisor (NAME)"; "" when no stop is latched.
std::string stopped_by_text(const run::TickReport& report);

/// The operating state in words for the screen, the log and the service
/// status: why nothing moves (not enabled: the first cause, `cause`, never
/// its consequence), or (enabled) what the engine still holds back.
std::string state_text(const run::TickReport& report, const std::optional<run::Transition>& cause = std::nullopt);

/// Why a live controller does nothing although it is connected: SDL knows it
/// only as a plain joystick (numbered buttons and axes) while the mapping
/// reads game-controller names, which it never sends; with the two ways out.
/// "" when that is not so.
std::string joystick_note(bool pad_names, std::optional<bool> game_controller);

}  // namespace andros::view

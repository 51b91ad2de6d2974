#pragma once
/// The bridge's operating state: one machine that every event around the
/// frame loop goes through (docs/safety-states.md has its table and diagram).
/// Motion is sent only in kEnabled, and the only way into kEnabled is a fresh
/// deadman press seen in kNotEnabled. Everything that interrupts driving (the
/// link lost, regained or taken, the controller lost, a reload, a suspend or
/// a resume) lands in a state that is not kEnabled, and the way back from
/// each passes through kNotEnabled with the engine rebased, so that a press
/// made before it is history. A stop by a stop button (the operator's
/// `estop`, the supervisor's `stop`) latches: it outlives every other event
/// and ends only by a reset (kOperatorReset, kSupervisorReset: a stop button
/// held on purpose, StopButtons), and then through kNotEnabled too. The
/// supervisor may reset any stop, the operator only the operator's. What the
/// screen, the log, the pad's light and the service status say is read from
/// this state.

#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

namespace andros::run {

enum class OpState : std::uint8_t {
  kNoLink,        ///< the link is not up: nothing reaches the vehicle
  kNoController,  ///< the link is up, no controller
  kNotEnabled,    ///< needs a fresh deadman press, inputs at rest
  kEnabled,       ///< frames follow the controller
  kStopped,       ///< stopped by a stop button: latched, neutral until reset
  kSuspended,     ///< job control: neutral frames sent, link closed, waiting to go on
  kReloading,     ///< neutral frames while the settings are read again
  kStopping,      ///< the run ends: neutral frames, drain, close
};

enum class OpEvent : std::uint8_t {
  kLinkUp,           ///< the link came up (first time or again)
  kLinkDown,         ///< the link was lost
  kLinkTaken,        ///< another program holds the port
  kControllerUp,     ///< a controller connected
  kControllerDown,   ///< the controller was lost
  kFreshPress,       ///< the engine saw a fresh deadman press (it holds back inputs not at rest)
  kRelease,          ///< the engine is no longer enabled (deadman released)
  kPanic,            ///< the trigger deadman squeezed past `deadman_panic`: off until fully released
  kEnableTimeout,    ///< enabled with no input change for `enable_timeout`
  kOperatorStop,     ///< the operator's stop button (`estop`) pressed: latches
  kSupervisorStop,   ///< the supervisor's stop button pressed: latches, and the stop is the supervisor's
  kGateTrip,         ///< the frame gate replaced a frame that broke a safety rule (frame_gate.hpp): latches
  kOperatorReset,    ///< the operator's reset hold: resets the operator's stop or the gate's (not the supervisor's)
  kSupervisorReset,  ///< the supervisor's reset hold: resets any stop
  kReloadBegin,      ///< SIGHUP, or a script's `reload`
  kReloadDone,       ///< the reload's outcome is in (applied or refused)
  kSuspend,          ///< Ctrl-Z, or a script's `suspend`
  kResume,           ///< fg / SIGCONT, or a script's `resume`
  kShutdown,         ///< SIGINT, SIGTERM, a script's `stop` or its end
};

/// Who latched a stop (a stop button, or the frame gate), or reset one.
enum class StopBy : std::uint8_t { kOperator, kSupervisor, kGate };

/// What the loop must do on a transition, besides sending per the new state.
struct Effect {
  bool changed = false;  ///< the state changed
  /// The engine starts afresh from the input as it is now: every press so
  /// far is history, the deadman needs a fresh press (FrameSource::restart).
  bool rebase = false;
};

/// One row of the transition table: in `from`, `event` leads to `to`.
/// settle: the target is the first of kStopped, kNoLink, kNoController,
/// kNotEnabled whose condition holds (a stop latched; link down; no
/// controller; otherwise).
struct Transition {
  OpState from;
  OpEvent event;
  OpState to;
  bool rebase;
  bool settle;  ///< `to` is decided by the link and controller (see above)
};

class OperatingState {
 public:
  /// link_up: the link is up before the first frame (a replay's sink).
  explicit OperatingState(bool link_up = false);

  [[nodiscard]] OpState state() const { return state_; }
  [[nodiscard]] bool motion_allowed() const { return state_ == OpState::kEnabled; }
  [[nodiscard]] bool link_up() const { return link_up_; }
  [[nodiscard]] bool controller_up() const { return controller_up_; }
  /// A stop is latched (the state is kStopped, or will be once a suspend
  /// or reload under way settles).
  [[nodiscard]] bool stop_latched() const { return stopped_by_.has_value(); }
  /// Whose stop is latched: the supervisor's once the supervisor pressed its stop.
  [[nodiscard]] std::optional<StopBy> stopped_by() const { return stopped_by_; }
  /// Who reset the last stop, until the next stop or the bridge enabled again.
  [[nodiscard]] std::optional<StopBy> reset_by() const { return reset_by_; }

  /// Applies one event. An event with no row for the current state changes
  /// nothing but the conditions it reports: the link, the controller, and the
  /// stop latch (a stop latches it in every state but kStopping, and makes
  /// it the supervisor's if the supervisor's; a gate trip latches one that
  /// is not latched yet). A reset that may not reset the stop (the
  /// operator's of the supervisor's stop) changes nothing.
  Effect on(OpEvent event);

  /// The whole table, for docs and tests.
  static std::span<const Transition> table();

 private:
  [[nodiscard]] OpState settled() const;

  OpState state_;
  bool link_up_;
  bool controller_up_ = false;
  std::optional<StopBy> stopped_by_;  ///< a stop is latched, and whose
  std::optional<StopBy> reset_by_;
};

std::string_view to_string(OpState state);
std::string_view to_string(OpEvent event);
/// "operator", "supervisor", "frame gate".
std::string_view to_string(StopBy by);

}  // namespace andros::run

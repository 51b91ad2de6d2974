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
/// and ends only by a reset (kOperatorReset, kSupervisorReset: a reset
/// gesture of its own, never a stop button, StopButtons), and then through
/// kNotEnabled too. The supervisor may reset any stop, the operator only the
/// operator's, and each only from the physical pad that stopped (a
/// supervisor's reset of the operator's stop from any). What the
/// screen, the log, the pad's light and the service status say is read from
/// this state, and from the transitions it publishes (Transition).

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "andros/mapping/engine_status.hpp"

namespace andros::run {

enum class OpState : std::uint8_t {
  kNoLink,        ///< the link is not up: nothing reaches the vehicle
  kNoController,  ///< the link is up, no controller
  kNotEnabled,    ///< needs a fresh deadman press, inputs at rest
  kEnabled,       ///< frames follow the controller
  kStopped,       ///< stopped by a stop button: latched, neutral until reset
  kSuspended,     ///< job control: neutral frames sent, link closed, waiting to go on
  kReloading,     ///< neutral frames while the settings are read again
  kShuttingDown,  ///< the run ends: neutral frames, drain, close
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
  kOperatorReset,    ///< the operator's reset gesture: the operator's stop or the gate's, from the pad that stopped
  kSupervisorReset,  ///< the supervisor's reset gesture: any stop (its own from the pad that stopped)
  kReloadBegin,      ///< SIGHUP, or a script's `reload`
  kReloadDone,       ///< the reload's outcome is in (applied or refused)
  kSuspend,          ///< Ctrl-Z, or a script's `suspend`
  kResume,           ///< fg / SIGCONT, or a script's `resume`
  kShutdown,         ///< SIGINT, SIGTERM, a script's `stop` or its end
  kNeutralSent,      ///< a suspend's, reload's or shutdown's neutral frames are out (the loop counted them)
};

/// Who latched a stop (a stop button, or the frame gate), or reset one.
enum class StopBy : std::uint8_t { kOperator, kSupervisor, kGate };
/// Whose stop an event of the machine is (a stop button's, the frame gate's trip); none for any other.
std::optional<StopBy> stop_by(OpEvent event);

/// Where an event came from (docs/safety-states.md, "Where the events come from").
enum class Who : std::uint8_t {
  kOperator,    ///< the operator's pad: the deadman, its stop, its reset, its controller
  kSupervisor,  ///< the supervisor's pad: its stop, its reset, its controller
  kGate,        ///< the frame gate
  kLink,        ///< the link: opened, lost, taken, stalled
  kRequest,     ///< a request from around the process: a signal, job control (Request)
  kScript,      ///< an event script's word (`suspend`, `reload`, `link down`...) or its end
  kTimeout,     ///< the enable timeout
  kLoop,        ///< the loop itself: its neutral frames out, a reload's outcome, its own close of the link
};

/// One step of the machine, as it publishes it: every event that changed
/// something (its row applied, waited or was withdrawn, or a condition the
/// machine keeps changed: the link, the controller, the stop latch, a
/// reset, the neutral frames due), and every stop press it keeps as a fact
/// (one pressed again while stopped). The pad feedback, the status board
/// and the recorder react to these, never to a difference between two
/// reports.
struct Transition {
  OpState from;
  OpEvent event;
  OpState to;  ///< the same as `from` when only a condition changed
  Who who;
  /// The physical pad of a stop or reset (the operator's at a gate's trip);
  /// kNoPad for any other event.
  input::PadId pad = input::kNoPad;
  /// A stop pressed again while stopped: the latch and whose it is unchanged.
  bool again = false;
  /// kReloadDone: the reload was refused, the old settings kept.
  bool refused = false;

  bool operator==(const Transition&) const = default;
};

/// What the loop must do on a transition, besides sending per the new state.
struct Effect {
  bool changed = false;  ///< the state changed
  /// The engine starts afresh from the input as it is now: every press so
  /// far is history, the deadman needs a fresh press (FrameSource::rebase, DriveGuard::rebase).
  bool rebase = false;
  /// Neutral frames begin (again): a suspend, a reload or the shutdown
  /// began, or a second reload restarted the first; the loop counts them
  /// and says kNeutralSent once they are out.
  bool neutral_frames = false;
  /// A reload's reading begins (again): the loop starts its worker.
  bool begin_reload = false;

  bool operator==(const Effect&) const = default;
  /// Both effects: what either asks of the loop.
  Effect& operator|=(const Effect& other);
};

/// What a row does with its event.
enum class Act : std::uint8_t {
  kGo,        ///< to `to`
  kSettle,    ///< to the first of kStopped, kNoLink, kNoController, kNotEnabled whose condition holds
  kWait,      ///< the event waits in the machine; it is applied once the machine leaves `from`
  kWithdraw,  ///< the waiting `withdraws` is dropped (its answer came before it was applied)
  kAgain,     ///< stays in `from` and begins it again (its neutral frames and its work)
};

/// One row of the transition table: in `from`, `event` does `act`.
struct Row {
  OpState from;
  OpEvent event;
  Act act;
  OpState to;         ///< kGo only
  bool rebase;        ///< the engine is rebased (Effect::rebase)
  bool sending;       ///< the row holds only while `from`'s neutral frames go out (before kNeutralSent)
  OpEvent withdraws;  ///< kWithdraw only
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
  /// The physical pad whose stop is latched (the operator's pad at a gate's trip).
  [[nodiscard]] input::PadId stopper_pad() const { return stopper_pad_; }
  /// The pad that reset the last stop (with reset_by).
  [[nodiscard]] input::PadId reset_pad() const { return reset_pad_; }
  /// Whether a reset gesture completed now by `by` on `pad` would reset the
  /// latched stop: stopped; the supervisor's any stop, the operator's only
  /// the operator's or the gate's; and a stop by a role only from the pad that stopped.
  [[nodiscard]] bool may_reset(StopBy by, input::PadId pad) const;
  /// The pads in each role now (the loop tells the machine each tick, before
  /// its events): a stop is the pad's that pressed it, a reset the pad's that made it.
  void set_pads(input::PadId operator_pad, input::PadId supervisor_pad);
  /// The same machine: what it publishes (the transitions not yet taken, who
  /// an event came from), which decides nothing, aside.
  bool operator==(const OperatingState& other) const;
  /// The neutral frames of a suspend, reload or shutdown are still going out (no kNeutralSent yet).
  [[nodiscard]] bool neutral_due() const { return neutral_due_; }
  /// The event waits to be applied (Act::kWait).
  [[nodiscard]] bool waiting(OpEvent event) const { return (waiting_ & bit(event)) != 0; }

  /// Applies one event, then every waiting event that its row now lets
  /// through (their effects joined). An event with no row for the current
  /// state changes nothing but the conditions it reports: the link, the
  /// controller, and the stop latch (a stop latches it in every state but
  /// kShuttingDown, and makes it the supervisor's if the supervisor's; a gate
  /// trip latches one that is not latched yet). A reset that may not reset
  /// the stop (the operator's of the supervisor's stop) changes nothing.
  Effect on(OpEvent event) { return on(event, who_of(event)); }
  /// The same, from who (a suspend from a request or a script...); refused:
  /// kReloadDone of a reload refused. Published as who's (Transition).
  Effect on(OpEvent event, Who who, bool refused = false);
  /// A tick's facts (mapping::InputFacts) as events, in this order: the
  /// stop buttons (the operator's first: a stop by both is the
  /// supervisor's); then, not enabled, a fresh deadman press enables;
  /// enabled, a deadman not held and fresh ends it (released, the panic,
  /// the enable timeout).
  Effect on(const mapping::InputFacts& facts);
  /// The transitions published since the last call, in order; taken.
  std::vector<Transition> take_transitions() { return std::exchange(published_, {}); }

  /// The whole table, for docs and tests.
  static std::span<const Row> table();
  /// Who an event comes from when nobody says otherwise: a pad's event its
  /// pad's (a controller's up or down: the operator's), a link's the link's,
  /// the enable timeout, the loop's own; a request.
  static Who who_of(OpEvent event);

 private:
  [[nodiscard]] OpState settled() const;
  /// The event through the conditions and its row, published when it changed something.
  void apply(OpEvent event, Who who, bool refused, Effect& effect);
  /// The conditions the event changes, whatever the state; true when one changed.
  bool note(OpEvent event, Who who, Transition& published);
  /// The row for the event in the current state, if any.
  [[nodiscard]] const Row* row_for(OpEvent event) const;
  static constexpr std::uint32_t bit(OpEvent event) { return 1U << static_cast<unsigned>(event); }

  OpState state_;
  bool link_up_;
  bool controller_up_ = false;
  bool neutral_due_ = false;
  std::uint32_t waiting_ = 0;         ///< the events waiting (Act::kWait), one bit each
  std::optional<StopBy> stopped_by_;  ///< a stop is latched, and whose
  std::optional<StopBy> reset_by_;
  /// The events that waited, and who they came from: published as theirs when applied.
  std::array<Who, static_cast<std::size_t>(OpEvent::kNeutralSent) + 1> waiting_who_{};
  /// Who took the controller condition down (the operator's pad or the
  /// supervisor's): the one whose return brings it up again.
  Who controller_lost_by_ = Who::kOperator;
  input::PadId operator_pad_ = input::kNoPad;  ///< the pads in each role now (set_pads)
  input::PadId supervisor_pad_ = input::kNoPad;
  input::PadId stopper_pad_ = input::kNoPad;
  input::PadId reset_pad_ = input::kNoPad;
  std::vector<Transition> published_;  ///< not yet taken (take_transitions)

  /// A stop by `by` from `pad`: latches, or makes the stop the supervisor's,
  /// or is pressed again (published.again); false: the machine keeps nothing of it.
  bool note_stop(StopBy by, input::PadId pad, Transition& published);
};

std::string_view to_string(OpState state);
std::string_view to_string(OpEvent event);
/// A row's target as docs/safety-states.md's table writes it: the state, "settled", "waits", "withdraws EVENT",
/// "again".
std::string to_string(const Row& row);
/// "operator", "supervisor", "frame gate".
std::string_view to_string(StopBy by);

}  // namespace andros::run

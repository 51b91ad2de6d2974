#pragma once
/// The run loop, live and in replay: on every tick of an injected clock, pump
/// the input, answer the requests and fault events through the operating
/// state machine (operating_state.hpp), compute the frame, send it (motion
/// only in "enabled"). A stop sends neutral frames at the normal period,
/// drains and closes the link; a suspend sends the same frames, closes the
/// link and pauses; a reload sends neutral frames while the settings are read
/// off the loop, then starts afresh. Whatever interrupted driving, only a
/// fresh deadman press enables again.

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "andros/base/clock.hpp"
#include "andros/input/input_source.hpp"
#include "andros/input/input_state.hpp"
#include "andros/link/fault_link.hpp"
#include "andros/link/link.hpp"
#include "andros/mapping/engine_status.hpp"
#include "andros/mapping/frame_source.hpp"
#include "andros/protocol/frame.hpp"
#include "andros/run/drive_guard.hpp"
#include "andros/run/frame_gate.hpp"
#include "andros/run/operating_state.hpp"
#include "andros/timing/tick_schedule.hpp"

namespace andros::run {

using mapping::FrameSource;
using mapping::Step;

/// A transition of the machine as a report carries it: with what is known
/// of the physical pad it names (Transition::pad), which a report outlives.
struct ReportedTransition {
  Transition transition;
  input::PadIdentity pad;

  bool operator==(const ReportedTransition&) const = default;
};

/// What one tick did, for the status view and the log. Values only, copied by
/// the loop: whoever reads a report never reaches back into the loop, the
/// engine or the link (docs/architecture.md).
struct TickReport {
  std::int64_t tick = 0;       ///< index on the clock
  std::int64_t t_ms = 0;       ///< the tick's time, ms since start
  std::int64_t skipped = 0;    ///< ticks skipped before this one after a stall
  protocol::DataBytes data{};  ///< the frame offered to the link (result: whether it took it)
  link::SendResult result = link::SendResult::kDown;
  bool sent = true;                  ///< false: nothing was offered this tick (suspended, link closed)
  OpState state = OpState::kNoLink;  ///< after this tick: what the screen, pad, log and service say
  std::optional<StopBy> stopped_by;  ///< a stop latched: whose (OperatingState::stopped_by)
  std::optional<StopBy> reset_by;    ///< who reset the last stop, until the next stop or enabled
  input::PadIdentity stopper_pad;    ///< the physical pad whose stop is latched (OperatingState::stopper_pad)
  input::PadIdentity reset_pad;      ///< the pad that reset the last stop
  /// Stopped: a reset gesture completed now on the operator's pad (the
  /// supervisor's) would reset the stop; false on the operator's when the
  /// stop is the supervisor's, or another pad's (the one that stopped is gone).
  bool operator_may_reset = false;
  bool supervisor_may_reset = false;
  /// What the machine did since the last report, in order: every view of
  /// the run (the pad's feedback, the status board, the recorder) reacts to
  /// these, never to a difference between two reports.
  std::vector<ReportedTransition> transitions;
  bool connected = false;             ///< a controller is connected
  std::string controller;             ///< its name (may be empty)
  bool supervised = false;            ///< a supervisor's controller is configured (InputSource::supervised)
  bool supervisor_connected = false;  ///< and it is connected
  std::string supervisor;             ///< its name (may be empty)
  /// A controller attached but refused (InputSource::refusal): why, and what to do; "" when none is.
  std::string refusal;
  mapping::EngineStatus engine;  ///< after this tick's step (the last step's when none ran)
  link::LinkStatus link;         ///< after this tick's send
  /// The frame the loop chose broke a safety rule: which (data is then the
  /// frame gate's neutral one, and the state stopped). Empty: it passed.
  std::string gate_fault;
  std::int64_t gate_trips = 0;  ///< frames the gate replaced since the start

  [[nodiscard]] bool shutting_down() const { return state == OpState::kShuttingDown; }
  [[nodiscard]] bool reloading() const { return state == OpState::kReloading; }
  [[nodiscard]] bool enabled() const { return state == OpState::kEnabled; }
  /// The link took this tick's frame: the vehicle may act on it.
  [[nodiscard]] bool delivered() const { return sent && result == link::SendResult::kSent; }
};

struct BridgeOptions {
  std::int64_t rate_millihertz = timing::kDefaultRateMillihertz;
  int shutdown_frames = 3;       ///< neutral frames sent at a stop, a suspend and a reload
  int shutdown_extra_ticks = 5;  ///< ticks allowed beyond those for frames the link refused
  int drain_timeout_ms = 300;
  /// The end of the input ends the run on neutral frames (run); false: on
  /// the last frame, as replay has it (docs/event-scripts.md; a script's `stop` still
  /// gives them).
  bool neutral_tail_at_end = true;
  /// What the frame gate holds every frame to (the run's code and weapons setting).
  FrameRules rules;
};

/// What the world around the loop asks of it, read at each tick.
enum class Request : std::uint8_t {
  kNone,
  kShutdown,  ///< end the run (SIGINT, SIGTERM)
  kSuspend,   ///< job control (Ctrl-Z): neutral frames, then pause until the process goes on
  kResumed,   ///< the process was stopped behind the loop's back (SIGSTOP) and goes on
  kReload,    ///< reread the settings (SIGHUP): neutral frames while they are read, then afresh
};

/// How a reload ended.
struct ReloadOutcome {
  bool ok = false;       ///< the new settings are in place; false: the old ones stay
  std::string message;   ///< why not, when not
  bool weapons = false;  ///< ok: whether the settings now in place enable weapons (the frame gate's rule)
  /// ok: the frame source the new settings make, which the loop takes (with
  /// its guards read afresh from its mapping); none: the source stays.
  std::shared_ptr<FrameSource> frames = nullptr;
};

/// How the neutral frames at the end (or before a suspend's pause) went.
struct ShutdownReport {
  int neutral_sent = 0;  ///< neutral frames the link took
  int neutral_wanted = 0;
  bool drained = false;  ///< and the link then had them out before it closed
  [[nodiscard]] bool ok() const { return neutral_sent >= neutral_wanted && drained; }
};

struct RunControl {
  std::function<Request()> poll = [] { return Request::kNone; };
  /// Called after a suspend's neutral frames (link drained and closed), with
  /// how they went; returns when the run goes on.
  std::function<void(const ShutdownReport& neutral)> pause = [](const ShutdownReport&) {};
  /// Starts reading the settings again, off the loop (mapping: an event
  /// script's `reload FILE`, empty for the configured one); returns at once.
  std::function<void(const std::string& mapping)> begin_reload = [](const std::string&) {};
  /// Called on the loop's thread at each tick of a reload once its neutral
  /// frames are out: nullopt while the reading goes on; then the outcome,
  /// with the new settings already swapped in when ok.
  std::function<std::optional<ReloadOutcome>()> finish_reload = [] {
    return std::optional<ReloadOutcome>(ReloadOutcome{false, "no reload here"});
  };
};

class Bridge {
 public:
  using ShutdownCheck = std::function<bool()>;
  using Observer = std::function<void(const TickReport&)>;

  Bridge(Clock& clock, input::InputSource& input, FrameSource& frames, link::Link& link, BridgeOptions options);
  Bridge(const Bridge&) = delete;  // input_ refers to its own pumped_
  Bridge& operator=(const Bridge&) = delete;

  /// Runs until a shutdown request or the end of the input, then shuts down. A
  /// request seen on tick k is answered on tick k: its frame is the first
  /// neutral one. Never throws for a link problem; an InputError from a
  /// script still escapes (after the neutral frames).
  void run(const RunControl& control, const Observer& observe);
  /// The same, with shutdown() as the only request.
  void run(const ShutdownCheck& shutdown, const Observer& observe);

  /// After run() (or a suspend): whether the neutral frames reached the link.
  /// When not, the vehicle may still be acting on the last frame it got: the
  /// caller says so and exits 1.
  [[nodiscard]] const ShutdownReport& shutdown_report() const { return shutdown_report_; }
  [[nodiscard]] const OperatingState& state() const { return machine_; }

 private:
  /// One tick, whatever the state; false once the run has ended.
  bool tick(const RunControl& control, const Observer& observe);
  /// The tick in a driving state: the facts through the machine, then the frame it allows.
  void drive(std::int64_t t_ms, const Observer& observe);
  void on_request(Request request);
  void on_fault(const input::InputEvent& fault);
  /// The event through the machine, from who (the machine's default when
  /// not said), then what its effect asks of the loop.
  Effect apply(OpEvent event) { return apply(event, OperatingState::who_of(event)); }
  Effect apply(OpEvent event, Who who, bool refused = false);
  /// What an effect asks of the loop: a rebase restarts the frame source
  /// from the input as it is; neutral frames are counted afresh; a reload's
  /// reading begins. Then the machine's transitions are kept for the next report.
  Effect act(Effect effect, bool reset);
  /// Stop buttons pressed, through the machine (the operator's first: a stop by both is the supervisor's).
  void answer_stops(mapping::StopPresses pressed);
  /// The frame through the gate, then to the link; answers what the link did, reports.
  link::SendResult send(const protocol::DataBytes& offered, const Observer& observe);
  /// A stop's, suspend's or reload's neutral frames: counted from start_sequence().
  void start_sequence();
  [[nodiscard]] bool sequence_done() const;
  /// One neutral frame of the sequence; true once it is complete.
  bool neutral_frame(const Observer& observe);
  /// After a stop's or suspend's frames: the link drained and closed.
  void close();
  /// Job control: the process stops in control.pause(); afresh after it.
  void pause(const RunControl& control);
  void advance();
  /// The link came up or was lost (told by who: the link, or a script's fault event): the event through the machine.
  void link_changed(bool up, Who who = Who::kLink);
  /// The link carries motion (link::carries_motion): for the state, a stalled link is not up.
  [[nodiscard]] bool link_up() const;
  [[nodiscard]] OpEvent link_lost_event() const;
  /// The tick's report, with the transitions since the last one (taken).
  [[nodiscard]] TickReport report(const protocol::DataBytes& data, link::SendResult result, bool sent);

  Clock& clock_;
  input::InputSource& source_;
  FrameSource* frames_;                    ///< the one given, or a reload's
  std::shared_ptr<FrameSource> reloaded_;  ///< the last reload's, which frames_ points at
  link::FaultLink link_;
  BridgeOptions options_;
  timing::TickSchedule schedule_;
  OperatingState machine_;   ///< every decision whether the vehicle may move, and every deferral
  DriveGuard guard_;         ///< the machine's guards with memory and time: its facts each driving tick
  FrameGate gate_;           ///< the second channel: every frame offered to the link passes it
  input::TickInput pumped_;  ///< what the input source hands over each tick
  input::InputState& input_ = pumped_.state();  ///< its controllers' state: what the guards and the engine read
  mapping::EngineStatus engine_status_;         ///< the last step's
  ShutdownReport shutdown_report_;
  const RunControl* control_ = nullptr;  ///< run()'s, while it runs
  Nanos start_{0};
  std::int64_t tick_ = 0;  ///< the tick to run next
  std::int64_t skipped_ = 0;
  int sequence_sent_ = 0;   ///< neutral frames of the current stop, suspend or reload the link took
  int sequence_ticks_ = 0;  ///< and ticks it has had
  // What the requests asked, for when the machine acts on them (their order is the machine's):
  bool suspend_pauses_ = false;  ///< the last suspend was job control's: the process stops after its frames
  std::string reload_mapping_;   ///< the last reload's mapping ("" for the configured one)
  bool input_failed_ = false;    ///< the input threw: the shutdown's frames go without it
  input::PadRegistry pads_;      ///< the physical pads the machine knows by number
  input::PadId operator_pad_ = input::kNoPad;
  input::PadId supervisor_pad_ = input::kNoPad;
  std::vector<ReportedTransition> transitions_;  ///< the machine's since the last report
};

}  // namespace andros::run

#include "andros/run/operating_state.hpp"

#include <array>
#include <bit>
#include <utility>

namespace andros::run {

std::optional<StopBy> stop_by(OpEvent event) {
  switch (event) {
    case OpEvent::kOperatorStop: return StopBy::kOperator;
    case OpEvent::kSupervisorStop: return StopBy::kSupervisor;
    case OpEvent::kGateTrip: return StopBy::kGate;
    default: return std::nullopt;
  }
}
namespace {

using S = OpState;
using E = OpEvent;

constexpr Row row(S from, E event, S to) { return {from, event, Act::kGo, to, false, false, event}; }
constexpr Row settle(S from, E event, bool rebase) {
  return {from, event, Act::kSettle, S::kNotEnabled, rebase, false, event};
}
/// sending: only while `from`'s neutral frames go out.
constexpr Row wait(S from, E event, bool sending = false) {
  return {from, event, Act::kWait, from, false, sending, event};
}
constexpr Row withdraw(S from, E event, E waiting) {
  return {from, event, Act::kWithdraw, from, false, false, waiting};
}
constexpr Row again(S from, E event) { return {from, event, Act::kAgain, from, false, false, event}; }

// Written out row by row, so that docs/safety-states.md and the tests read the same table.
constexpr auto kTable = std::to_array<Row>({
    // The link.
    row(S::kNoController, E::kLinkDown, S::kNoLink),
    row(S::kNotEnabled, E::kLinkDown, S::kNoLink),
    row(S::kEnabled, E::kLinkDown, S::kNoLink),
    row(S::kNoController, E::kLinkTaken, S::kNoLink),
    row(S::kNotEnabled, E::kLinkTaken, S::kNoLink),
    row(S::kEnabled, E::kLinkTaken, S::kNoLink),
    settle(S::kNoLink, E::kLinkUp, true),  // a link that comes back is a new link
    // The controller.
    row(S::kNotEnabled, E::kControllerDown, S::kNoController),
    row(S::kEnabled, E::kControllerDown, S::kNoController),
    // The engine counts presses per connection: one held at connect is not fresh.
    settle(S::kNoController, E::kControllerUp, false),
    // The deadman.
    row(S::kNotEnabled, E::kFreshPress, S::kEnabled),
    row(S::kEnabled, E::kRelease, S::kNotEnabled),
    row(S::kEnabled, E::kPanic, S::kNotEnabled),
    row(S::kEnabled, E::kEnableTimeout, S::kNotEnabled),
    // A stop button: from any driving state, latched (it outlives the link,
    // the controller, a reload and a suspend); reset only by a reset hold on
    // the pad that stopped (or the supervisor's), and then not enabled, afresh.
    row(S::kNoLink, E::kOperatorStop, S::kStopped),
    row(S::kNoController, E::kOperatorStop, S::kStopped),
    row(S::kNotEnabled, E::kOperatorStop, S::kStopped),
    row(S::kEnabled, E::kOperatorStop, S::kStopped),
    row(S::kNoLink, E::kSupervisorStop, S::kStopped),
    row(S::kNoController, E::kSupervisorStop, S::kStopped),
    row(S::kNotEnabled, E::kSupervisorStop, S::kStopped),
    row(S::kEnabled, E::kSupervisorStop, S::kStopped),
    // The frame gate found a frame breaking a rule (the engine is at fault):
    // stopped as by a stop button, latched, and reset the same way.
    row(S::kNoLink, E::kGateTrip, S::kStopped),
    row(S::kNoController, E::kGateTrip, S::kStopped),
    row(S::kNotEnabled, E::kGateTrip, S::kStopped),
    row(S::kEnabled, E::kGateTrip, S::kStopped),
    settle(S::kStopped, E::kOperatorReset, true),  // the operator's own stop, or the gate's, only
    settle(S::kStopped, E::kSupervisorReset, true),
    // Reload, suspend, shutdown: from any driving state.
    row(S::kNoLink, E::kReloadBegin, S::kReloading),
    row(S::kNoController, E::kReloadBegin, S::kReloading),
    row(S::kNotEnabled, E::kReloadBegin, S::kReloading),
    row(S::kEnabled, E::kReloadBegin, S::kReloading),
    row(S::kStopped, E::kReloadBegin, S::kReloading),
    // A second reload while one is read: the files are read again, its neutral frames count afresh.
    again(S::kReloading, E::kReloadBegin),
    // One while suspended is answered after the resume.
    wait(S::kSuspended, E::kReloadBegin),
    settle(S::kReloading, E::kReloadDone, true),
    row(S::kNoLink, E::kSuspend, S::kSuspended),
    row(S::kNoController, E::kSuspend, S::kSuspended),
    row(S::kNotEnabled, E::kSuspend, S::kSuspended),
    row(S::kEnabled, E::kSuspend, S::kSuspended),
    row(S::kStopped, E::kSuspend, S::kSuspended),
    // A suspend during a reload waits for its outcome; a resume before then answers it.
    wait(S::kReloading, E::kSuspend),
    withdraw(S::kReloading, E::kResume, E::kSuspend),
    // A resume while the suspend's neutral frames go out waits for them (no
    // stop of the process in between); suspend, resume, suspend: the last word counts.
    wait(S::kSuspended, E::kResume, true),
    withdraw(S::kSuspended, E::kSuspend, E::kResume),
    settle(S::kSuspended, E::kResume, true),
    // Stopped behind the loop's back (SIGSTOP) and continued: afresh too.
    settle(S::kNoLink, E::kResume, true),
    settle(S::kNoController, E::kResume, true),
    settle(S::kNotEnabled, E::kResume, true),
    settle(S::kEnabled, E::kResume, true),
    settle(S::kStopped, E::kResume, true),
    row(S::kNoLink, E::kShutdown, S::kShuttingDown),
    row(S::kNoController, E::kShutdown, S::kShuttingDown),
    row(S::kNotEnabled, E::kShutdown, S::kShuttingDown),
    row(S::kEnabled, E::kShutdown, S::kShuttingDown),
    row(S::kStopped, E::kShutdown, S::kShuttingDown),
    row(S::kSuspended, E::kShutdown, S::kShuttingDown),
    row(S::kReloading, E::kShutdown, S::kShuttingDown),
});

}  // namespace

OperatingState::OperatingState(bool link_up) : state_(S::kNoLink), link_up_(link_up) { state_ = settled(); }

std::span<const Row> OperatingState::table() { return kTable; }

Who OperatingState::who_of(OpEvent event) {
  switch (event) {
    case E::kSupervisorStop:
    case E::kSupervisorReset: return Who::kSupervisor;
    case E::kGateTrip: return Who::kGate;
    case E::kLinkUp:
    case E::kLinkDown:
    case E::kLinkTaken: return Who::kLink;
    case E::kEnableTimeout: return Who::kTimeout;
    case E::kReloadBegin:
    case E::kSuspend:
    case E::kResume:
    case E::kShutdown: return Who::kRequest;
    case E::kReloadDone:
    case E::kNeutralSent: return Who::kLoop;
    default: return Who::kOperator;
  }
}

OpState OperatingState::settled() const {
  if (stopped_by_) return S::kStopped;
  if (!link_up_) return S::kNoLink;
  if (!controller_up_) return S::kNoController;
  return S::kNotEnabled;
}

const Row* OperatingState::row_for(OpEvent event) const {
  for (const auto& t : kTable) {
    if (t.from == state_ && t.event == event && (!t.sending || neutral_due_)) return &t;
  }
  return nullptr;
}

Effect OperatingState::on(OpEvent event, Who who, bool refused) {
  Effect effect;
  apply(event, who, refused, effect);
  // The waiting events its row lets through now, in the enum's order, until none is.
  for (bool again = waiting_ != 0; again;) {
    again = false;
    for (std::uint32_t rest = waiting_; rest != 0; rest &= rest - 1) {
      const auto next = static_cast<OpEvent>(std::countr_zero(rest));
      const Row* t = row_for(next);
      if (t != nullptr && t->act == Act::kWait) continue;
      waiting_ &= ~bit(next);
      apply(next, waiting_who_[static_cast<std::size_t>(next)], false, effect);  // no row now (the run ended): dropped
      again = true;
      break;
    }
  }
  return effect;
}

Effect OperatingState::on(const mapping::InputFacts& facts) {
  using mapping::DeadmanState;
  Effect effect;
  if (facts.stops.by_operator) effect |= on(E::kOperatorStop);
  if (facts.stops.by_supervisor) effect |= on(E::kSupervisorStop);
  const bool fresh = facts.deadman == DeadmanState::kFreshHold;
  if (state_ == S::kNotEnabled && fresh) {
    effect |= on(E::kFreshPress);
  } else if (state_ == S::kEnabled && !fresh) {
    effect |= on(facts.deadman == DeadmanState::kPastPanic  ? E::kPanic
                 : facts.deadman == DeadmanState::kTimedOut ? E::kEnableTimeout
                                                            : E::kRelease);
  }
  return effect;
}

Effect& Effect::operator|=(const Effect& other) {
  changed = changed || other.changed;
  rebase = rebase || other.rebase;
  neutral_frames = neutral_frames || other.neutral_frames;
  begin_reload = begin_reload || other.begin_reload;
  return *this;
}

bool OperatingState::note(OpEvent event, Who who, Transition& published) {
  switch (event) {
    case E::kLinkUp: return !std::exchange(link_up_, true);
    case E::kLinkDown:
    case E::kLinkTaken: return std::exchange(link_up_, false);
    case E::kControllerUp:
      published.who = controller_lost_by_;  // the one that comes back is the one that was lost
      return !std::exchange(controller_up_, true);
    case E::kControllerDown:
      if (controller_up_) controller_lost_by_ = who;
      return std::exchange(controller_up_, false);
    case E::kOperatorStop: return note_stop(StopBy::kOperator, operator_pad_, published);
    case E::kSupervisorStop: return note_stop(StopBy::kSupervisor, supervisor_pad_, published);
    case E::kGateTrip: return note_stop(StopBy::kGate, operator_pad_, published);
    case E::kOperatorReset:
    case E::kSupervisorReset: {
      const StopBy by = event == E::kSupervisorReset ? StopBy::kSupervisor : StopBy::kOperator;
      const auto& pad = by == StopBy::kSupervisor ? supervisor_pad_ : operator_pad_;
      published.pad = pad;
      if (!may_reset(by, pad)) return false;
      stopped_by_.reset();
      stopper_pad_ = input::kNoPad;
      reset_by_ = by;
      reset_pad_ = pad;
      return true;
    }
    case E::kFreshPress: reset_by_.reset(); return false;
    case E::kNeutralSent: return std::exchange(neutral_due_, false);
    case E::kShutdown: waiting_ = 0; return false;  // whatever waited, the run ends
    default: return false;
  }
}

void OperatingState::apply(OpEvent event, Who who, bool refused, Effect& effect) {
  Transition published{state_, event, state_, who, input::kNoPad, false, refused};
  // The conditions the settled states read are kept whatever the state.
  const bool noted = note(event, who, published);
  const bool reset_refused = (event == E::kOperatorReset || event == E::kSupervisorReset) && !noted;
  const Row* t = reset_refused ? nullptr : row_for(event);
  if (t == nullptr) {
    if (noted) published_.push_back(published);
    return;
  }
  switch (t->act) {
    case Act::kWait:
      waiting_ |= bit(event);
      waiting_who_[static_cast<std::size_t>(event)] = who;
      break;
    case Act::kWithdraw: waiting_ &= ~bit(t->withdraws); break;
    case Act::kAgain:
      neutral_due_ = effect.neutral_frames = true;
      effect.begin_reload = effect.begin_reload || event == E::kReloadBegin;
      break;
    case Act::kGo:
    case Act::kSettle: {
      const OpState to = t->act == Act::kSettle ? settled() : t->to;
      const bool changed = to != state_;
      state_ = to;
      effect.changed = effect.changed || changed;
      effect.rebase = effect.rebase || t->rebase;
      if (changed && (to == S::kSuspended || to == S::kReloading || to == S::kShuttingDown)) {
        // Each of these begins with its own neutral frames.
        neutral_due_ = effect.neutral_frames = true;
        effect.begin_reload = effect.begin_reload || to == S::kReloading;
      }
      break;
    }
  }
  published.to = state_;
  published_.push_back(published);
}

bool OperatingState::note_stop(StopBy by, input::PadId pad, Transition& published) {
  reset_by_.reset();
  if (state_ == S::kShuttingDown) return false;  // the run ends on neutral frames anyway
  const bool latches = !stopped_by_;
  // A stop by both is the supervisor's: only the supervisor resets it.
  const bool taken = by == StopBy::kSupervisor && stopped_by_ != StopBy::kSupervisor;
  if (latches || taken) {
    stopped_by_ = by;
    stopper_pad_ = pad;
  }
  // Pressed again while stopped: no latch changes, but the press is a fact.
  if (!latches && !taken && state_ != S::kStopped) return false;
  published.pad = pad;
  published.again = !latches && !taken;
  return true;
}

bool OperatingState::may_reset(StopBy by, input::PadId pad) const {
  if (state_ != S::kStopped || !stopped_by_) return false;
  // The supervisor resets any stop; the operator its own or the gate's (an internal error the operator saw).
  if (by == StopBy::kOperator && stopped_by_ == StopBy::kSupervisor) return false;
  // A role's own stop only from the physical pad that stopped: another pad that took the role did not.
  if (by == StopBy::kSupervisor && stopped_by_ != StopBy::kSupervisor) return true;
  return pad == stopper_pad_;
}

bool OperatingState::operator==(const OperatingState& o) const {
  return state_ == o.state_ && link_up_ == o.link_up_ && controller_up_ == o.controller_up_ &&
         neutral_due_ == o.neutral_due_ && waiting_ == o.waiting_ && stopped_by_ == o.stopped_by_ &&
         reset_by_ == o.reset_by_ && operator_pad_ == o.operator_pad_ && supervisor_pad_ == o.supervisor_pad_ &&
         stopper_pad_ == o.stopper_pad_ && reset_pad_ == o.reset_pad_;
}

void OperatingState::set_pads(input::PadId operator_pad, input::PadId supervisor_pad) {
  operator_pad_ = operator_pad;
  supervisor_pad_ = supervisor_pad;
}

std::string_view to_string(OpState state) {
  switch (state) {
    case S::kNoLink: return "no link";
    case S::kNoController: return "no controller";
    case S::kNotEnabled: return "not enabled";
    case S::kEnabled: return "enabled";
    case S::kStopped: return "stopped";
    case S::kSuspended: return "suspended";
    case S::kReloading: return "reloading";
    case S::kShuttingDown:
      return "stopping";  // what the screen says (sessions have words of their own: record::state_word)
  }
  return "?";
}

std::string_view to_string(OpEvent event) {
  switch (event) {
    case E::kLinkUp: return "link up";
    case E::kLinkDown: return "link down";
    case E::kLinkTaken: return "link taken";
    case E::kControllerUp: return "controller up";
    case E::kControllerDown: return "controller down";
    case E::kFreshPress: return "fresh deadman press";
    case E::kRelease: return "deadman released";
    case E::kPanic: return "deadman squeezed past panic";
    case E::kEnableTimeout: return "enable timeout";
    case E::kOperatorStop: return "operator's stop";
    case E::kSupervisorStop: return "supervisor's stop";
    case E::kGateTrip: return "frame gate trip";
    case E::kOperatorReset: return "operator's reset";
    case E::kSupervisorReset: return "supervisor's reset";
    case E::kReloadBegin: return "reload";
    case E::kReloadDone: return "reload done";
    case E::kSuspend: return "suspend";
    case E::kResume: return "resume";
    case E::kShutdown: return "shutdown";
    case E::kNeutralSent: return "neutral frames sent";
  }
  return "?";
}

std::string to_string(const Row& row) {
  switch (row.act) {
    case Act::kGo: return std::string(to_string(row.to));
    case Act::kSettle: return "settled";
    case Act::kWait: return row.sending ? "waits for the neutral frames" : "waits";
    case Act::kWithdraw: return "withdraws the waiting " + std::string(to_string(row.withdraws));
    case Act::kAgain: return "again";
  }
  return "?";
}

std::string_view to_string(StopBy by) {
  switch (by) {
    case StopBy::kOperator: return "operator";
    case StopBy::kSupervisor: return "supervisor";
    case StopBy::kGate: return "frame gate";
  }
  return "?";
}

}  // namespace andros::run

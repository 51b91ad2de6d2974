#pragma once
// The operating-state machine's oracle: the rules of docs/safety-states.md
// ("The rule the table keeps") and docs/mapping.md ("Stop"; "What a mapping cannot change"), kept from
// the events alone. It knows nothing of the machine's table: it follows the
// conditions each event reports (the link, the controller, a stop latched, a
// shutdown asked for) and what each interruption owes (a rebase before
// driving again), and judges each step of the machine by what it then shows
// (its state, its stop latch, the step's Effect).

#include <cstdint>

#include "andros/run/operating_state.hpp"

namespace andros::test {

/// Who latched a stop, as the contract has it: the supervisor may reset any
/// stop, the operator only the operator's (and the frame gate's), and only
/// from the pad that stopped (ISO 13850: no reset by a pad that is not the
/// stopper's or the supervisor's).
enum class Stopper : std::uint8_t { kNone, kOperator, kSupervisor, kGate };

class StateOracle {
 public:
  /// link_up: the machine was made with the link up (a replay's sink).
  explicit StateOracle(bool link_up) : link_(link_up) {}

  /// The operator's pad now (another physical pad took the role, or the first came back).
  void operator_pad(std::uint32_t pad) { operator_pad_ = pad; }

  /// Follows one event the machine was given; `before` and `after` are its
  /// state around it, `effect` what it answered, `latched` its stop latch
  /// after it. Returns the rule broken, "" when none.
  const char* step(run::OpEvent event, run::OpState before, run::OpState after, const run::Effect& effect,
                   bool latched) {
    using E = run::OpEvent;
    using S = run::OpState;
    // The conditions, as the event reports them, and what it owes.
    const bool was_shut = shutdown_;
    switch (event) {
      case E::kLinkUp: link_ = true; break;
      case E::kLinkDown:
      case E::kLinkTaken:
        link_ = false;
        owed_link_ = true;  // a link that comes back is a new link
        break;
      case E::kControllerUp: controller_ = true; break;
      case E::kControllerDown: controller_ = false; break;
      case E::kOperatorStop:
      case E::kGateTrip:  // the frame gate stopped a frame: a stop like the button's
        if (!shutdown_) {
          if (!stop_) {
            stopper_ = event == E::kGateTrip ? Stopper::kGate : Stopper::kOperator;
            stopper_pad_ = operator_pad_;
          }
          stop_ = owed_stop_ = true;
        }
        break;
      case E::kSupervisorStop:  // the stop is the supervisor's from now on
        if (!shutdown_) {
          stopper_ = Stopper::kSupervisor;
          stop_ = owed_stop_ = true;
        }
        break;
      case E::kOperatorReset:  // stopped: the operator's own stop (or the gate's) only, from the pad that stopped
        if (stop_ && before == run::OpState::kStopped && stopper_ != Stopper::kSupervisor &&
            operator_pad_ == stopper_pad_) {
          stop_ = false;
        }
        break;
      case E::kSupervisorReset:  // stopped: any stop
        if (stop_ && before == run::OpState::kStopped) stop_ = false;
        break;
      case E::kReloadBegin:
      case E::kSuspend:
      case E::kResume: owed_other_ = true; break;  // driving was interrupted: afresh
      case E::kShutdown: shutdown_ = true; break;
      default: break;
    }
    // A rebase pays what is owed once its cause is over.
    if (effect.rebase) {
      owed_other_ = false;
      if (link_) owed_link_ = false;
      if (!stop_) owed_stop_ = false;
    }

    const bool enabled = after == S::kEnabled;
    if (was_shut && after != S::kShuttingDown) return "left stopping: a shutdown is for good";
    if (shutdown_ && after != S::kShuttingDown) return "a shutdown did not lead to stopping";
    if (was_shut && effect.changed) return "a change after the shutdown";
    if (enabled && before != S::kEnabled && !(event == E::kFreshPress && before == S::kNotEnabled)) {
      return "enabled other than by a fresh deadman press in not enabled";
    }
    if (enabled && !link_) return "enabled with the link down";
    if (enabled && !controller_) return "enabled with no controller";
    if (enabled && (owed_link_ || owed_stop_ || owed_other_)) return "enabled with no rebase since an interruption";
    if (enabled && effect.rebase) return "a rebase left the machine enabled";
    if (enabled && interrupts(event)) return "still enabled after an event that ends driving";
    if (!shutdown_ && latched != stop_) return stop_ ? "a stop not latched" : "a stop latched with none pressed";
    // A latched stop outlives everything but its reset: while it holds, the
    // machine shows it, or is suspended, reloading or shutting down.
    if (stop_ && after != S::kStopped && after != S::kSuspended && after != S::kReloading &&
        after != S::kShuttingDown) {
      return "a latched stop left other than by its reset";
    }
    return "";
  }

  bool operator==(const StateOracle&) const = default;

 private:
  /// The events after which the machine may not be enabled, whatever it was.
  static bool interrupts(run::OpEvent event) {
    using E = run::OpEvent;
    switch (event) {
      case E::kLinkDown:
      case E::kLinkTaken:
      case E::kControllerDown:
      case E::kRelease:
      case E::kPanic:
      case E::kEnableTimeout:
      case E::kOperatorStop:
      case E::kSupervisorStop:
      case E::kGateTrip:
      case E::kReloadBegin:
      case E::kSuspend:
      case E::kResume:
      case E::kShutdown: return true;
      default: return false;
    }
  }

  bool link_;
  bool controller_ = false;
  bool stop_ = false;
  Stopper stopper_ = Stopper::kNone;
  std::uint32_t operator_pad_ = 1;  // the operator's pad now
  std::uint32_t stopper_pad_ = 0;   // the operator's pad that stopped
  bool shutdown_ = false;
  bool owed_link_ = false;   // a link lost: rebase once it is back
  bool owed_stop_ = false;   // a stop latched: rebase once it is reset
  bool owed_other_ = false;  // a reload, a suspend, a resume: rebase after it
};

}  // namespace andros::test

// The run loop's answers to the world around it: requests (SIGINT, Ctrl-Z,
// SIGCONT, SIGHUP) and an event script's fault events, each an event of the
// operating-state machine, which orders them (suspend, resume and reload:
// docs/safety-states.md, "Orderings"). The loop keeps only what a request
// carries: whether a suspend stops the process, which mapping a reload reads.
#include "andros/run/bridge.hpp"

namespace andros::run {

void Bridge::on_request(Request request) {
  switch (request) {
    case Request::kNone: break;
    case Request::kShutdown: apply(OpEvent::kShutdown); break;
    case Request::kSuspend:
      suspend_pauses_ = true;
      apply(OpEvent::kSuspend);
      break;
    case Request::kResumed: apply(OpEvent::kResume); break;
    case Request::kReload:
      reload_mapping_.clear();
      apply(OpEvent::kReloadBegin);
      break;
  }
}

void Bridge::on_fault(const input::InputEvent& fault) {
  using T = input::InputEvent::Type;
  switch (fault.type) {
    case T::kLinkDown:
    case T::kLinkTaken:
      link_.set_fault(fault.type == T::kLinkTaken ? link::FaultLink::Fault::kTaken : link::FaultLink::Fault::kDown);
      // Answered now: a link back before the next frame is still a new link.
      link_changed(false);
      break;
    case T::kLinkUp: link_.set_fault(link::FaultLink::Fault::kNone); break;
    case T::kLinkStalled:
      // A stalled server gets neutral frames only: the loop sees the link as lost (docs/event-scripts.md).
      link_.set_stalled(true);
      if (machine_.link_up()) link_changed(false);
      break;
    case T::kLinkReading: link_.set_stalled(false); break;  // back like `link up`: a new link
    case T::kSuspend:
      suspend_pauses_ = false;
      apply(OpEvent::kSuspend);
      break;
    case T::kResume: apply(OpEvent::kResume); break;
    case T::kReload:
      reload_mapping_ = fault.name;
      apply(OpEvent::kReloadBegin);
      break;
    case T::kShutdown: apply(OpEvent::kShutdown); break;
    default: break;
  }
}

}  // namespace andros::run

// The run loop's answers to the world around it: requests (SIGINT, Ctrl-Z,
// SIGCONT, SIGHUP) and an event script's fault events, and the orderings of
// suspend, resume and reload (docs/safety-states.md).
#include <utility>

#include "andros/run/bridge.hpp"

namespace andros::run {

void Bridge::on_request(Request request, const RunControl& control) {
  switch (request) {
    case Request::kNone: break;
    case Request::kStop: apply(OpEvent::kShutdown); break;
    case Request::kSuspend:
      pause_after_suspend_ = true;
      begin_suspend();
      break;
    case Request::kResumed: resume(control); break;
    case Request::kReload: begin_reload(control, ""); break;
  }
}

void Bridge::on_fault(const input::InputEvent& fault, const RunControl& control) {
  using T = input::InputEvent::Type;
  switch (fault.type) {
    case T::kLinkDown:
    case T::kLinkTaken:
      link_.set_fault(fault.type == T::kLinkTaken ? link::FaultLink::Fault::kTaken : link::FaultLink::Fault::kDown);
      // Answered now: a link back before the next frame is still a new link.
      apply(link_lost_event());
      break;
    case T::kLinkUp: link_.set_fault(link::FaultLink::Fault::kNone); break;
    case T::kSuspend:
      pause_after_suspend_ = false;
      begin_suspend();
      break;
    case T::kResume: resume(control); break;
    case T::kReload: begin_reload(control, fault.name); break;
    case T::kStop: apply(OpEvent::kShutdown); break;
    default: break;
  }
}

void Bridge::begin_suspend() {
  if (machine_.state() == OpState::kReloading) {
    suspend_pending_ = true;  // after the reload's outcome
    return;
  }
  if (machine_.state() == OpState::kSuspended) {
    resume_pending_ = false;  // suspend, resume, suspend: the last word counts
    return;
  }
  if (apply(OpEvent::kSuspend).changed) suspend_frames_due_ = true;
}

void Bridge::resumed(const RunControl& control) {
  apply(OpEvent::kResume);
  if (auto mapping = std::exchange(reload_pending_, std::nullopt)) begin_reload(control, *mapping);
}

void Bridge::resume(const RunControl& control) {
  if (suspend_pending_) {
    suspend_pending_ = false;  // a suspend still waiting behind a reload: answered by this resume
    return;
  }
  if (machine_.state() == OpState::kSuspended && suspend_frames_due_) {
    resume_pending_ = true;  // answered once the suspend's neutral frames are out
    return;
  }
  resumed(control);
}

void Bridge::begin_reload(const RunControl& control, const std::string& mapping) {
  // A second one while one runs is the control's to queue (the files read
  // again); one while suspended waits for the resume; while stopping it is
  // ignored (no row).
  if (machine_.state() == OpState::kReloading) {
    start_sequence();  // the files read again: neutral frames from now on, as for the first
    control.begin_reload(mapping);
    return;
  }
  if (machine_.state() == OpState::kSuspended) {
    reload_pending_ = mapping;
    return;
  }
  if (!apply(OpEvent::kReloadBegin).changed) return;
  control.begin_reload(mapping);
}

}  // namespace andros::run

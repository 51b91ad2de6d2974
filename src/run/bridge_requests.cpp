// The run loop's answers to the world around it: requests (SIGINT, Ctrl-Z,
// SIGCONT, SIGHUP) and an event script's fault events, each an event of the
// operating-state machine, which orders them (suspend, resume and reload:
// docs/safety-states.md, "Orderings"). The loop keeps only what a request
// carries: whether a suspend stops the process, which mapping a reload reads.
#include <array>

#include "andros/run/bridge.hpp"

namespace andros::run {
namespace {

using T = input::InputEvent::Type;

/// The one table of the words for the machine's events from around the
/// loop: a request (a signal, job control) and an event script's word for
/// the same thing each become the machine's event. (The script's `stop` is
/// the shutdown, T::kShutdown; the link's fault events act on the link, whose
/// change the loop then tells the machine.)
struct Word {
  Request request;
  T script;
  OpEvent event;
};
constexpr std::array<Word, 4> kWords{{
    {Request::kShutdown, T::kShutdown, OpEvent::kShutdown},
    {Request::kSuspend, T::kSuspend, OpEvent::kSuspend},
    {Request::kResumed, T::kResume, OpEvent::kResume},
    {Request::kReload, T::kReload, OpEvent::kReloadBegin},
}};

}  // namespace

void Bridge::on_request(Request request) {
  for (const auto& w : kWords) {
    if (w.request != request) continue;
    // What a request carries: job control's suspend stops the process, a SIGHUP reads the configured mapping.
    if (w.event == OpEvent::kSuspend) suspend_pauses_ = true;
    if (w.event == OpEvent::kReloadBegin) reload_mapping_.clear();
    apply(w.event, Who::kRequest);
  }
}

void Bridge::on_fault(const input::InputEvent& fault) {
  switch (fault.type) {
    case T::kLinkDown:
    case T::kLinkTaken:
      link_.set_fault(fault.type == T::kLinkTaken ? link::FaultLink::Fault::kTaken : link::FaultLink::Fault::kDown);
      // Answered now: a link back before the next frame is still a new link.
      link_changed(false, Who::kScript);
      return;
    case T::kLinkUp: link_.set_fault(link::FaultLink::Fault::kNone); return;
    case T::kLinkStalled:
      // A stalled server gets neutral frames only: the loop sees the link as lost (docs/event-scripts.md).
      link_.set_stalled(true);
      if (machine_.link_up()) link_changed(false, Who::kScript);
      return;
    case T::kLinkReading: link_.set_stalled(false); return;  // back like `link up`: a new link
    default: break;
  }
  for (const auto& w : kWords) {
    if (w.script != fault.type) continue;
    // What a script's event carries: its suspend does not stop the process, its reload names a mapping.
    if (w.event == OpEvent::kSuspend) suspend_pauses_ = false;
    if (w.event == OpEvent::kReloadBegin) reload_mapping_ = fault.name;
    apply(w.event, Who::kScript);
  }
}

}  // namespace andros::run

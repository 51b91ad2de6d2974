// The run loop's answers to the world around it: requests (SIGINT, Ctrl-Z,
// SIGCONT, SIGHUP) and an event script's fault events, each an event of the
// operating-state machine, which orders them (suspend, resume and reload:
// docs/safety-states.md, "Orderings"), or, for the link's faults, a change of
// the link that the loop then tells the machine. The loop keeps only what a
// request carries: whether a suspend stops the process, which mapping a
// reload reads.
#include <array>
#include <optional>

#include "andros/run/bridge.hpp"

namespace andros::run {
namespace {

using T = input::InputEvent::Type;

/// What a script's link fault does to the link (the machine hears of the link's change, not of the word).
enum class OnLink : std::uint8_t { kNothing, kLose, kTake, kRestore, kStall, kRead };

/// The one table of the words for the machine's events from around the
/// loop: a request (a signal, job control) and an event script's word for
/// the same thing each become the machine's event; a script's link fault
/// acts on the link. (The script's `stop` is the shutdown, T::kShutdown.)
/// The input state never sees these: the input hands the script's apart
/// (input::TickInput).
struct Word {
  Request request;  ///< kNone: no request says it
  T script;
  std::optional<OpEvent> event;  ///< none: the word acts on the link alone
  OnLink link = OnLink::kNothing;
};
constexpr std::array<Word, 9> kWords{{
    {Request::kShutdown, T::kShutdown, OpEvent::kShutdown},
    {Request::kSuspend, T::kSuspend, OpEvent::kSuspend},
    {Request::kResumed, T::kResume, OpEvent::kResume},
    {Request::kReload, T::kReload, OpEvent::kReloadBegin},
    {Request::kNone, T::kLinkDown, std::nullopt, OnLink::kLose},
    {Request::kNone, T::kLinkTaken, std::nullopt, OnLink::kTake},
    {Request::kNone, T::kLinkUp, std::nullopt, OnLink::kRestore},
    {Request::kNone, T::kLinkStalled, std::nullopt, OnLink::kStall},
    {Request::kNone, T::kLinkReading, std::nullopt, OnLink::kRead},
}};

/// Every fault word of the script has its one row: none is read and then dropped.
constexpr bool every_fault_once() {
  for (auto t = static_cast<int>(T::kLinkDown); t <= static_cast<int>(T::kShutdown); ++t) {
    int rows = 0;
    for (const auto& w : kWords) rows += static_cast<int>(w.script) == t ? 1 : 0;
    if (rows != 1) return false;
  }
  return true;
}
static_assert(every_fault_once());

}  // namespace

void Bridge::on_request(Request request) {
  if (request == Request::kNone) return;
  for (const auto& w : kWords) {
    if (w.request != request) continue;
    // What a request carries: job control's suspend stops the process, a SIGHUP reads the configured mapping.
    if (w.event == OpEvent::kSuspend) suspend_pauses_ = true;
    if (w.event == OpEvent::kReloadBegin) reload_mapping_.clear();
    apply(*w.event, Who::kRequest);
  }
}

void Bridge::on_fault(const input::InputEvent& fault) {
  for (const auto& w : kWords) {
    if (w.script != fault.type) continue;
    switch (w.link) {
      case OnLink::kLose:
      case OnLink::kTake:
        link_.set_fault(w.link == OnLink::kTake ? link::FaultLink::Fault::kTaken : link::FaultLink::Fault::kDown);
        // Answered now: a link back before the next frame is still a new link.
        link_changed(false, Who::kScript);
        break;
      case OnLink::kRestore: link_.set_fault(link::FaultLink::Fault::kNone); break;
      case OnLink::kStall:
        // A stalled server gets neutral frames only: the loop sees the link as lost (docs/event-scripts.md).
        link_.set_stalled(true);
        if (machine_.link_up()) link_changed(false, Who::kScript);
        break;
      case OnLink::kRead: link_.set_stalled(false); break;  // back like `link up`: a new link
      case OnLink::kNothing: break;
    }
    if (!w.event) return;
    // What a script's event carries: its suspend does not stop the process, its reload names a mapping.
    if (w.event == OpEvent::kSuspend) suspend_pauses_ = false;
    if (w.event == OpEvent::kReloadBegin) reload_mapping_ = fault.name;
    apply(*w.event, Who::kScript);
  }
}

}  // namespace andros::run

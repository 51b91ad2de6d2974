#include "pad_roles.hpp"

#include <spdlog/spdlog.h>

#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"

namespace andros::input {
namespace {

constexpr const char* kWhatToDo =
    "use controllers of different models, or name each by its port "
    "(--controller and --supervisor /dev/input/by-path/...; docs/controllers.md)";
/// What the state line says to do: the log has the whole line.
constexpr const char* kByPort = "name each by its port: --controller and --supervisor /dev/input/by-path/...";

}  // namespace

std::string Slot::role() const {
  return pad == Pad::kSupervisor ? "the supervisor's controller" : "the operator's controller";
}

std::string Slot::describe() const {
  // Once bound, the role waits for its own pad, not for what the selection names.
  if (bound) {
    return std::string(pad == Pad::kSupervisor ? "the supervisor's" : "the operator's") + " own controller, " +
           quote_name(bound->name) + " (GUID " + bound->guid +
           (bound->serial && !bound->serial->empty() ? ", serial " + printable_text(*bound->serial) : "") + ")";
  }
  return pad == Pad::kSupervisor ? "the supervisor's controller (" + selection.describe() + ")" : selection.describe();
}

bool PadRoles::told_apart(const Slot& slot, const Slot& other, PadFacts& a, PadFacts& b) const {
  if (a.guid != b.guid) return true;
  for (const Slot* s : {&slot, &other}) {
    if (s->selection.by_path() && s->selection.matches(a) != s->selection.matches(b)) return true;
  }
  const std::string& serial_a = reader_.serial(a);
  const std::string& serial_b = reader_.serial(b);
  return !serial_a.empty() && !serial_b.empty() && serial_a != serial_b;
}

bool PadRoles::wanted(const Slot& slot, PadFacts& pad) const {
  if (!slot.bound) return slot.selection.matches(pad);
  // The pad it was bound to, wherever SDL now lists it.
  return pad.guid == slot.bound->guid && reader_.serial(pad) == slot.bound->serial;
}

bool PadRoles::may_take(const Slot& slot, const Slot* other, PadFacts& pad, std::vector<PadFacts>& attached,
                        std::string& refused) {
  if (!wanted(slot, pad)) return false;
  if (other == nullptr) return true;
  if (other->device && other->device->instance_id() == pad.instance) return false;
  // "The first controller" is the first that is not the supervisor's; a port
  // named by one role is never the other's.
  if ((slot.selection.is_first() || other->selection.by_path()) && other->selection.matches(pad)) return false;
  if (slot.selection.by_path()) return true;  // the port named is the pad
  // pad and the pads attached that cannot be told from it; twin: the first of those.
  int alike = 1;
  const PadFacts* twin = nullptr;
  for (auto& each : attached) {
    if (each.instance == pad.instance || each.guid != pad.guid || told_apart(slot, *other, pad, each)) continue;
    ++alike;
    if (twin == nullptr) twin = &each;
  }
  if (twin != nullptr) {
    twins_[pad.guid] = describe(*twin);
    spdlog::error("{}: refused {}: it cannot be told from {}, so that the roles could swap: {}", slot.role(),
                  describe(pad), describe(*twin), kWhatToDo);
    refused = std::to_string(alike) + " identical controllers " + quote_name(pad.name) +
              " refused: SDL cannot tell them apart, so the roles could swap; " + kByPort;
    return false;
  }
  if (other->bound) {
    PadFacts theirs = *other->bound;
    if (!told_apart(slot, *other, theirs, pad)) {
      spdlog::error("{}: refused {}: it may be {}, and SDL gives nothing that tells them apart: {}", slot.role(),
                    describe(pad), other->describe(), kWhatToDo);
      refused = slot.role() + ": " + quote_name(pad.name) + " refused: it may be " + other->role() +
                " (SDL cannot tell them apart); " + kByPort;
      return false;
    }
  }
  if (const auto seen = twins_.find(pad.guid); seen != twins_.end()) {
    spdlog::error("{}: refused {}: it cannot be told from {}, seen beside it, so that the roles could swap: {}",
                  slot.role(), describe(pad), seen->second, kWhatToDo);
    refused = slot.role() + ": " + quote_name(pad.name) +
              " refused: SDL cannot tell it from the one seen beside it, so the roles could swap; " + kByPort;
    return false;
  }
  return true;
}

void PadRoles::bind(Slot& slot, PadFacts pad) const {
  reader_.serial(pad);
  slot.bound = std::move(pad);
}

}  // namespace andros::input

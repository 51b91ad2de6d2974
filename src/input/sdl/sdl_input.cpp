// The live controllers' source: SDL's queue, drained once per tick.
#include "andros/input/sdl_input.hpp"

#include <spdlog/spdlog.h>

#include <array>
#include <optional>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "controller_selection.hpp"
#include "feedback_player.hpp"
#include "pad_facts.hpp"
#include "pad_roles.hpp"
#include "sdl_device.hpp"

namespace andros::input {

struct SdlInput::Impl {
  Impl(const SdlInputOptions& options, const StopCheck& stop)
      : roles(PadReader(options.places)), driver(Pad::kOperator, ControllerSelection(options.controller)) {
    if (!options.supervisor.empty()) {
      ControllerSelection chosen(options.supervisor, options.supervisor_pos);
      if (chosen.same_as(driver.selection)) {
        throw InputError(options.supervisor_pos, "the supervisor's controller is " + chosen.describe() +
                                                     ", the operator's too (--controller): name another one");
      }
      supervisor.emplace(Pad::kSupervisor, std::move(chosen));
    }
    if (!options.controller_db.empty()) load_controller_db(options.controller_db, stop);
  }

  void poll(std::int64_t now_ms);
  void drain(std::int64_t now_ms);
  void handle(const SDL_Event& event, std::int64_t now_ms);
  void handle(Slot& slot, const SDL_Event& event, std::int64_t now_ms);
  void connect_chosen(Slot& slot, std::int64_t now_ms);
  /// The other role's slot; nullptr without a supervisor.
  [[nodiscard]] Slot* other_of(const Slot& slot);
  void lose(Slot& slot, std::int64_t now_ms);
  [[nodiscard]] InputEvent event(const Slot& slot, InputEvent::Type type, std::int64_t now_ms) const;

  SdlSession session;  // first member: SDL outlives everything below
  PadRoles roles;
  Slot driver;  // the operator's controller
  std::optional<Slot> supervisor;
  std::vector<InputEvent> events;
  FeedbackPlayer feedback;  // the operator's controller's
  std::int64_t last_poll_ms = 0;
};

void SdlInput::Impl::poll(std::int64_t now_ms) {
  events.clear();
  // SDL 2 stamps a joystick event when SDL_PumpEvents reads it from the
  // driver, i.e. here, so its timestamp says no more than now_ms does: every
  // event of this pump gets now_ms.
  SDL_PumpEvents();
  drain(now_ms);
  for (Slot* slot : {&driver, supervisor ? &*supervisor : nullptr}) {
    if (slot == nullptr) continue;
    if (slot->device && !slot->device->attached()) lose(*slot, now_ms);  // in case the removal event is late
    if (!slot->device && slot->rescan) connect_chosen(*slot, now_ms);
  }
  last_poll_ms = now_ms;
  if (driver.device) feedback.update(driver.device->joystick(), now_ms);
}

void SdlInput::Impl::drain(std::int64_t now_ms) {
  std::array<SDL_Event, 32> batch;
  int got = 0;
  do {
    got = SDL_PeepEvents(batch.data(), static_cast<int>(batch.size()), SDL_GETEVENT, SDL_FIRSTEVENT, SDL_LASTEVENT);
    for (int i = 0; i < got; ++i) handle(batch[static_cast<std::size_t>(i)], now_ms);
  } while (got == static_cast<int>(batch.size()));
}

void SdlInput::Impl::handle(const SDL_Event& event, std::int64_t now_ms) {
  handle(driver, event, now_ms);
  if (supervisor) handle(*supervisor, event, now_ms);
}

void SdlInput::Impl::handle(Slot& slot, const SDL_Event& event, std::int64_t now_ms) {
  if (event.type == SDL_JOYDEVICEADDED) {
    slot.rescan = true;
    return;
  }
  if (!slot.device) {
    // A refusal holds while the pads refused are there: look again.
    if (event.type == SDL_JOYDEVICEREMOVED && !slot.refused.empty()) slot.rescan = true;
    return;
  }
  if (event.type == SDL_JOYDEVICEREMOVED) {
    if (event.jdevice.which == slot.device->instance_id()) lose(slot, now_ms);
    return;
  }
  auto ev = slot.device->translate(event, now_ms);
  if (!ev) return;
  // Events in the connect's own pump are initial state (same stamp). SDL may
  // report a resting trigger's first value as half-pressed: see append_state.
  if (now_ms == slot.connect_t && slot.device->is_game_controller() && is_pad_trigger(ev->key)) return;
  ev->pad = slot.pad;
  events.push_back(std::move(*ev));
}

Slot* SdlInput::Impl::other_of(const Slot& slot) {
  if (&slot != &driver) return &driver;
  return supervisor ? &*supervisor : nullptr;
}

void SdlInput::Impl::connect_chosen(Slot& slot, std::int64_t now_ms) {
  slot.rescan = false;
  slot.refused.clear();
  Slot* other = other_of(slot);
  auto attached = roles.reader().attached();
  for (auto& pad : attached) {
    std::string refused;
    if (!roles.may_take(slot, other, pad, attached, refused)) {
      if (!refused.empty()) slot.refused = std::move(refused);
      continue;
    }
    slot.device = SdlDevice::open(pad.index);
    if (!slot.device) {
      spdlog::warn("cannot open controller {} {}: {}", pad.index, quote_name(pad.name), SDL_GetError());
      continue;
    }
    // With a supervisor, the role is this pad's from now on (a port named is its own binding).
    if (other != nullptr && !slot.selection.by_path()) roles.bind(slot, pad);
    spdlog::info("{} connected: {} ({}, {})", slot.pad == Pad::kSupervisor ? "supervisor's controller" : "controller",
                 printable_text(slot.device->name()), printable_text(slot.device->guid()),
                 slot.device->is_game_controller() ? "game controller" : "joystick");
    slot.waiting_logged = false;
    slot.refused.clear();
    slot.connect_t = now_ms;
    InputEvent connect = event(slot, InputEvent::Type::kConnect, now_ms);
    connect.name = slot.device->name();
    connect.device = slot.device->identity().fields();
    events.push_back(std::move(connect));
    // Some drivers (SDL's virtual one among them) deliver a freshly opened
    // device's state on the next update: take it now, inside this pump, so
    // that a button held at connect is stamped with the connect's time.
    SDL_JoystickUpdate();
    const auto before = events.size();
    slot.device->append_state(now_ms, events);
    for (auto k = before; k < events.size(); ++k) events[k].pad = slot.pad;
    drain(now_ms);
    return;
  }
  if (!slot.waiting_logged) {
    spdlog::info("waiting for {}", slot.describe());
    slot.waiting_logged = true;
  }
}

void SdlInput::Impl::lose(Slot& slot, std::int64_t now_ms) {
  spdlog::warn("{} lost: {}", slot.pad == Pad::kSupervisor ? "supervisor's controller" : "controller",
               printable_text(slot.device->name()));
  slot.device.reset();
  if (slot.pad == Pad::kOperator) feedback.cancel();
  // SDL releases a removed device's buttons and recentres its axes just
  // before reporting the removal. That is not the operator's input, and the
  // disconnect clears the state anyway: keep it out of recordings.
  for (auto k = events.size(); k > 0; --k) {
    const auto& e = events[k - 1];
    if (e.pad != slot.pad) continue;
    if (e.type == InputEvent::Type::kConnect || e.type == InputEvent::Type::kDisconnect) break;
    events.erase(events.begin() + static_cast<std::ptrdiff_t>(k - 1));
  }
  events.push_back(event(slot, InputEvent::Type::kDisconnect, now_ms));
  slot.rescan = true;  // another device matching the selection may be attached
}

InputEvent SdlInput::Impl::event(const Slot& slot, InputEvent::Type type, std::int64_t now_ms) const {
  InputEvent e;
  e.t_ms = now_ms;
  e.type = type;
  e.pad = slot.pad;
  return e;
}

SdlInput::SdlInput(const SdlInputOptions& options, const StopCheck& stop)
    : impl_(std::make_unique<Impl>(options, stop)) {}

SdlInput::~SdlInput() = default;

const std::vector<InputEvent>& SdlInput::poll(std::int64_t now_ms) {
  impl_->poll(now_ms);
  return impl_->events;
}

void SdlInput::pump(TickInput& input, std::int64_t now_ms) {
  for (const auto& event : poll(now_ms)) input.apply(event);
}

bool SdlInput::supervised() const { return impl_->supervisor.has_value(); }

void SdlInput::feedback(const FeedbackPattern& pattern) {
  if (impl_->driver.device) impl_->feedback.play(impl_->driver.device->joystick(), pattern, impl_->last_poll_ms);
}

std::optional<DeviceLayout> SdlInput::device() const {
  if (!impl_->driver.device) return std::nullopt;
  return impl_->driver.device->layout();
}

std::string SdlInput::refusal() const {
  for (const Slot* slot : {&impl_->driver, impl_->supervisor ? &*impl_->supervisor : nullptr}) {
    if (slot != nullptr && !slot->device && !slot->refused.empty()) return slot->refused;
  }
  return {};
}

std::string SdlInput::selection() const { return impl_->driver.selection.describe(); }

std::string SdlInput::supervisor_selection() const {
  return impl_->supervisor ? impl_->supervisor->selection.describe() : std::string();
}

std::unique_ptr<InputSource> make_sdl_input_source(const SdlInputOptions& options, const StopCheck& stop) {
  return std::make_unique<SdlInput>(options, stop);
}

}  // namespace andros::input

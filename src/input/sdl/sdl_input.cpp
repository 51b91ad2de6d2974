// The live controller source: SDL's queue, drained once per tick.
#include "andros/input/sdl_input.hpp"

#include <spdlog/spdlog.h>

#include <array>
#include <optional>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "controller_selection.hpp"
#include "feedback_player.hpp"
#include "sdl_device.hpp"

namespace andros::input {

struct SdlInput::Impl {
  Impl(const SdlInputOptions& options, const StopCheck& stop) : selection(options.controller) {
    if (!options.controller_db.empty()) load_controller_db(options.controller_db, stop);
  }

  void poll(std::int64_t now_ms);
  void drain(std::int64_t now_ms);
  void handle(const SDL_Event& event, std::int64_t now_ms);
  void connect_chosen(std::int64_t now_ms);
  void lose(std::int64_t now_ms);

  SdlSession session;  // first member: SDL outlives everything below
  ControllerSelection selection;
  std::unique_ptr<SdlDevice> device;
  std::int64_t connect_t = -1;
  bool rescan = true;  // a device may have appeared: look for the chosen one
  bool waiting_logged = false;
  std::vector<InputEvent> events;
  FeedbackPlayer feedback;
  std::int64_t last_poll_ms = 0;
};

void SdlInput::Impl::poll(std::int64_t now_ms) {
  events.clear();
  // SDL 2 stamps a joystick event when SDL_PumpEvents reads it from the
  // driver, i.e. here, so its timestamp says no more than now_ms does: every
  // event of this pump gets now_ms.
  SDL_PumpEvents();
  drain(now_ms);
  if (device && !device->attached()) lose(now_ms);  // in case the removal event is late
  if (!device && rescan) connect_chosen(now_ms);
  last_poll_ms = now_ms;
  if (device) feedback.update(device->joystick(), now_ms);
}

void SdlInput::Impl::drain(std::int64_t now_ms) {
  std::array<SDL_Event, 32> batch;
  int got = 0;
  do {
    got = SDL_PeepEvents(batch.data(), static_cast<int>(batch.size()), SDL_GETEVENT, SDL_FIRSTEVENT,
                         SDL_LASTEVENT);
    for (int i = 0; i < got; ++i) handle(batch[static_cast<std::size_t>(i)], now_ms);
  } while (got == static_cast<int>(batch.size()));
}

void SdlInput::Impl::handle(const SDL_Event& event, std::int64_t now_ms) {
  if (event.type == SDL_JOYDEVICEADDED) {
    rescan = true;
    return;
  }
  if (!device) return;
  if (event.type == SDL_JOYDEVICEREMOVED) {
    if (event.jdevice.which == device->instance_id()) lose(now_ms);
    return;
  }
  auto ev = device->translate(event, now_ms);
  if (!ev) return;
  // Events in the connect's own pump are initial state (same stamp). SDL may
  // report a resting trigger's first value as half-pressed: see append_state.
  if (now_ms == connect_t && device->is_game_controller() && is_pad_trigger(ev->key)) return;
  events.push_back(std::move(*ev));
}

void SdlInput::Impl::connect_chosen(std::int64_t now_ms) {
  rescan = false;
  const int count = SDL_NumJoysticks();
  for (int i = 0; i < count; ++i) {
    if (!selection.matches(i)) continue;
    device = SdlDevice::open(i);
    if (!device) {
      spdlog::warn("cannot open controller {} {}: {}", i, quote_name(device_name(i)), SDL_GetError());
      continue;
    }
    spdlog::info("controller connected: {} ({}, {})", printable_text(device->name()), printable_text(device->guid()),
                 device->is_game_controller() ? "game controller" : "joystick");
    waiting_logged = false;
    connect_t = now_ms;
    InputEvent connect;
    connect.t_ms = now_ms;
    connect.type = InputEvent::Type::kConnect;
    connect.name = device->name();
    events.push_back(std::move(connect));
    // Some drivers (SDL's virtual one among them) deliver a freshly opened
    // device's state on the next update: take it now, inside this pump, so
    // that a button held at connect is stamped with the connect's time.
    SDL_JoystickUpdate();
    device->append_state(now_ms, events);
    drain(now_ms);
    return;
  }
  if (!waiting_logged) {
    spdlog::info("waiting for {}", selection.describe());
    waiting_logged = true;
  }
}

void SdlInput::Impl::lose(std::int64_t now_ms) {
  spdlog::warn("controller lost: {}", printable_text(device->name()));
  device.reset();
  feedback.cancel();
  // SDL releases a removed device's buttons and recentres its axes just
  // before reporting the removal. That is not the operator's input, and the
  // disconnect clears the state anyway: keep it out of recordings.
  while (!events.empty() && events.back().type != InputEvent::Type::kConnect &&
         events.back().type != InputEvent::Type::kDisconnect) {
    events.pop_back();
  }
  InputEvent gone;
  gone.t_ms = now_ms;
  gone.type = InputEvent::Type::kDisconnect;
  events.push_back(std::move(gone));
  rescan = true;  // another device matching the selection may be attached
}

SdlInput::SdlInput(const SdlInputOptions& options, const StopCheck& stop)
    : impl_(std::make_unique<Impl>(options, stop)) {}

SdlInput::~SdlInput() = default;

const std::vector<InputEvent>& SdlInput::poll(std::int64_t now_ms) {
  impl_->poll(now_ms);
  return impl_->events;
}

void SdlInput::pump(InputState& state, std::int64_t now_ms) {
  for (const auto& event : poll(now_ms)) state.apply(event);
}

void SdlInput::feedback(const FeedbackPattern& pattern) {
  if (impl_->device) impl_->feedback.play(impl_->device->joystick(), pattern, impl_->last_poll_ms);
}

std::optional<DeviceLayout> SdlInput::device() const {
  if (!impl_->device) return std::nullopt;
  return impl_->device->layout();
}

std::string SdlInput::selection() const { return impl_->selection.describe(); }

std::unique_ptr<InputSource> make_sdl_input_source(const SdlInputOptions& options, const StopCheck& stop) {
  return std::make_unique<SdlInput>(options, stop);
}

}  // namespace andros::input

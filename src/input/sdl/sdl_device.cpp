#include "sdl_device.hpp"

#include <algorithm>

#include "controller_selection.hpp"

namespace andros::input {
namespace {

// input_state.hpp names pad buttons and axes by SDL enum value; keep them in step.
static_assert(SDL_CONTROLLER_BUTTON_MAX == kPadButtonNames.size());
static_assert(SDL_CONTROLLER_BUTTON_A == 0 && SDL_CONTROLLER_BUTTON_GUIDE == 5 &&
              SDL_CONTROLLER_BUTTON_LEFTSHOULDER == 9 && SDL_CONTROLLER_BUTTON_DPAD_UP == 11 &&
              SDL_CONTROLLER_BUTTON_DPAD_RIGHT == 14 && SDL_CONTROLLER_BUTTON_MISC1 == 15 &&
              SDL_CONTROLLER_BUTTON_TOUCHPAD == 20);
static_assert(SDL_CONTROLLER_AXIS_MAX == kPadAxisNames.size());
static_assert(SDL_CONTROLLER_AXIS_LEFTX == 0 && SDL_CONTROLLER_AXIS_RIGHTY == 3 &&
              SDL_CONTROLLER_AXIS_TRIGGERLEFT == 4 && SDL_CONTROLLER_AXIS_TRIGGERRIGHT == 5);
// Hat directions are the bits of SDL_HAT_*, in kHatDirectionNames order.
static_assert(SDL_HAT_UP == 1 && SDL_HAT_RIGHT == 2 && SDL_HAT_DOWN == 4 && SDL_HAT_LEFT == 8);

InputEvent make_event(InputEvent::Type type, InputKey key, int value, std::int64_t t_ms) {
  InputEvent ev;
  ev.t_ms = t_ms;
  ev.type = type;
  ev.key = key;
  ev.value = value;
  return ev;
}

InputKey key(InputKind kind, int index) { return InputKey{kind, static_cast<std::uint16_t>(index)}; }

/// The joystick hats no button or axis of the pad's SDL mapping reads: SDL's
/// game-controller events never report them, so they are read as hats.
std::vector<int> free_hats(SDL_GameController* pad, SDL_Joystick* joystick) {
  std::vector<int> out;
  const int hats = std::min(SDL_JoystickNumHats(joystick), kMaxHatIndex + 1);
  for (int h = 0; h < hats; ++h) {
    bool bound = false;
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX && !bound; ++b) {
      const auto bind = SDL_GameControllerGetBindForButton(pad, static_cast<SDL_GameControllerButton>(b));
      bound = bind.bindType == SDL_CONTROLLER_BINDTYPE_HAT && bind.value.hat.hat == h;
    }
    for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX && !bound; ++a) {
      const auto bind = SDL_GameControllerGetBindForAxis(pad, static_cast<SDL_GameControllerAxis>(a));
      bound = bind.bindType == SDL_CONTROLLER_BINDTYPE_HAT && bind.value.hat.hat == h;
    }
    if (!bound) out.push_back(h);
  }
  return out;
}

}  // namespace

bool is_pad_trigger(InputKey k) {
  return k.kind == InputKind::kPadAxis &&
         (k.index == SDL_CONTROLLER_AXIS_TRIGGERLEFT || k.index == SDL_CONTROLLER_AXIS_TRIGGERRIGHT);
}

std::unique_ptr<SdlDevice> SdlDevice::open(int device_index) {
  auto dev = std::unique_ptr<SdlDevice>(new SdlDevice());
  if (SDL_IsGameController(device_index) == SDL_TRUE) {
    dev->pad_.reset(SDL_GameControllerOpen(device_index));
    if (!dev->pad_) return nullptr;
    dev->joystick_ = SDL_GameControllerGetJoystick(dev->pad_.get());
    dev->free_hats_ = free_hats(dev->pad_.get(), dev->joystick_);
  } else {
    dev->joy_.reset(SDL_JoystickOpen(device_index));
    if (!dev->joy_) return nullptr;
    dev->joystick_ = dev->joy_.get();
  }
  dev->id_ = SDL_JoystickInstanceID(dev->joystick_);
  dev->name_ = device_name(device_index);
  dev->guid_ = device_guid(device_index);
  const char* path = SDL_JoystickPathForIndex(device_index);
  const char* serial = SDL_JoystickGetSerial(dev->joystick_);
  dev->identity_ = PadIdentity{dev->name_, path != nullptr ? path : "", serial != nullptr ? serial : "", dev->guid_};
  return dev;
}

bool SdlDevice::attached() const { return SDL_JoystickGetAttached(joystick_) == SDL_TRUE; }

DeviceLayout SdlDevice::layout() const {
  DeviceLayout out{name_, guid_, pad_ != nullptr, {}, {}, 0, free_hats_};
  if (pad_) {
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b) {
      if (SDL_GameControllerHasButton(pad_.get(), static_cast<SDL_GameControllerButton>(b)) == SDL_TRUE) {
        out.buttons.push_back(key(InputKind::kPadButton, b));
      }
    }
    for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX; ++a) {
      if (SDL_GameControllerHasAxis(pad_.get(), static_cast<SDL_GameControllerAxis>(a)) == SDL_TRUE) {
        out.axes.push_back(key(InputKind::kPadAxis, a));
      }
    }
    return out;
  }
  const int buttons = std::min(SDL_JoystickNumButtons(joystick_), kMaxJoystickIndex + 1);
  for (int b = 0; b < buttons; ++b) out.buttons.push_back(key(InputKind::kJoyButton, b));
  const int axes = std::min(SDL_JoystickNumAxes(joystick_), kMaxJoystickIndex + 1);
  for (int a = 0; a < axes; ++a) out.axes.push_back(key(InputKind::kJoyAxis, a));
  out.hats = std::max(0, std::min(SDL_JoystickNumHats(joystick_), kMaxHatIndex + 1));
  return out;
}

void SdlDevice::append_state(std::int64_t t_ms, std::vector<InputEvent>& out) const {
  using T = InputEvent::Type;
  if (pad_) {
    for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b) {
      if (SDL_GameControllerGetButton(pad_.get(), static_cast<SDL_GameControllerButton>(b)) != 0) {
        out.push_back(make_event(T::kButton, key(InputKind::kPadButton, b), 1, t_ms));
      }
    }
    // Sticks only. A trigger whose raw axis reads 0 until it first moves maps
    // to half-pressed (16384) through a -32768..32767 mapping; at connect we
    // cannot tell that from a real half press, so a trigger starts at rest and
    // reports its true value on its first movement. Resting is the safe side:
    // triggers drive speeds.
    for (int a = SDL_CONTROLLER_AXIS_LEFTX; a <= SDL_CONTROLLER_AXIS_RIGHTY; ++a) {
      const int v = SDL_GameControllerGetAxis(pad_.get(), static_cast<SDL_GameControllerAxis>(a));
      if (v != 0) out.push_back(make_event(T::kAxis, key(InputKind::kPadAxis, a), v, t_ms));
    }
    for (const int h : free_hats_) {
      const int mask = SDL_JoystickGetHat(joystick_, h) & 0x0F;
      if (mask != 0) out.push_back(make_event(T::kHat, key(InputKind::kHat, h * 4), mask, t_ms));
    }
    return;
  }
  const int buttons = std::min(SDL_JoystickNumButtons(joystick_), kMaxJoystickIndex + 1);
  for (int b = 0; b < buttons; ++b) {
    if (SDL_JoystickGetButton(joystick_, b) != 0) {
      out.push_back(make_event(T::kButton, key(InputKind::kJoyButton, b), 1, t_ms));
    }
  }
  const int axes = std::min(SDL_JoystickNumAxes(joystick_), kMaxJoystickIndex + 1);
  for (int a = 0; a < axes; ++a) {
    const int v = SDL_JoystickGetAxis(joystick_, a);
    if (v != 0) out.push_back(make_event(T::kAxis, key(InputKind::kJoyAxis, a), v, t_ms));
  }
  const int hats = std::min(SDL_JoystickNumHats(joystick_), kMaxHatIndex + 1);
  for (int h = 0; h < hats; ++h) {
    const int mask = SDL_JoystickGetHat(joystick_, h) & 0x0F;
    if (mask != 0) out.push_back(make_event(T::kHat, key(InputKind::kHat, h * 4), mask, t_ms));
  }
}

std::optional<InputEvent> SdlDevice::translate(const SDL_Event& e, std::int64_t t_ms) const {
  using T = InputEvent::Type;
  if (pad_) {
    // SDL also sends the raw JOY* events of a game controller: ignore them.
    switch (e.type) {
      case SDL_CONTROLLERBUTTONDOWN:
      case SDL_CONTROLLERBUTTONUP:
        if (e.cbutton.which != id_ || e.cbutton.button >= SDL_CONTROLLER_BUTTON_MAX) return std::nullopt;
        return make_event(T::kButton, key(InputKind::kPadButton, e.cbutton.button), e.cbutton.state, t_ms);
      case SDL_CONTROLLERAXISMOTION:
        if (e.caxis.which != id_ || e.caxis.axis >= SDL_CONTROLLER_AXIS_MAX) return std::nullopt;
        return make_event(T::kAxis, key(InputKind::kPadAxis, e.caxis.axis), e.caxis.value, t_ms);
      case SDL_JOYHATMOTION:  // only a hat the pad's mapping leaves out: a mapped one is the D-pad's buttons
        if (e.jhat.which != id_ || std::find(free_hats_.begin(), free_hats_.end(), e.jhat.hat) == free_hats_.end()) {
          return std::nullopt;
        }
        return make_event(T::kHat, key(InputKind::kHat, e.jhat.hat * 4), e.jhat.value & 0x0F, t_ms);
      default: return std::nullopt;
    }
  }
  switch (e.type) {
    case SDL_JOYBUTTONDOWN:
    case SDL_JOYBUTTONUP:
      if (e.jbutton.which != id_) return std::nullopt;
      return make_event(T::kButton, key(InputKind::kJoyButton, e.jbutton.button), e.jbutton.state, t_ms);
    case SDL_JOYAXISMOTION:
      if (e.jaxis.which != id_) return std::nullopt;
      return make_event(T::kAxis, key(InputKind::kJoyAxis, e.jaxis.axis), e.jaxis.value, t_ms);
    case SDL_JOYHATMOTION:
      if (e.jhat.which != id_ || e.jhat.hat > kMaxHatIndex) return std::nullopt;
      return make_event(T::kHat, key(InputKind::kHat, e.jhat.hat * 4), e.jhat.value & 0x0F, t_ms);
    default: return std::nullopt;
  }
}

}  // namespace andros::input

#pragma once
// SDL's virtual joystick as a test double: a real SDL device, headless.

#include <SDL.h>
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace andros::test {

/// Runs before any SDL_Init: no display is ever needed.
inline void use_dummy_video() { setenv("SDL_VIDEODRIVER", "dummy", 1); }

/// What SDL asked a virtual device's motors and light to do (its Rumble and
/// SetLED callbacks), in order. SDL stops a rumble itself when it is due,
/// with a call of strength 0, 0.
struct FeedbackLog {
  std::vector<std::array<Uint16, 2>> rumbles;  ///< low, high
  std::vector<std::array<Uint8, 3>> leds;
};

class VirtualDevice {
 public:
  /// A game controller: SDL maps virtual button i to SDL_GameControllerButton
  /// i and axis i to SDL_GameControllerAxis i. With a log, it has rumble and
  /// a light, and records what it is asked to do.
  static VirtualDevice pad(const char* name, std::uint16_t product = 1, FeedbackLog* log = nullptr) {
    return VirtualDevice(name, SDL_JOYSTICK_TYPE_GAMECONTROLLER, SDL_CONTROLLER_AXIS_MAX, SDL_CONTROLLER_BUTTON_MAX, 0,
                         product, log);
  }
  /// A flight stick SDL has no mapping for: numbered buttons, axes, a hat.
  static VirtualDevice stick(const char* name, std::uint16_t product = 2) {
    return VirtualDevice(name, SDL_JOYSTICK_TYPE_FLIGHT_STICK, 4, 12, 1, product);
  }

  VirtualDevice(const char* name, SDL_JoystickType type, int axes, int buttons, int hats, std::uint16_t product,
                FeedbackLog* log = nullptr) {
    SDL_VirtualJoystickDesc desc;
    SDL_zero(desc);
    desc.version = SDL_VIRTUAL_JOYSTICK_DESC_VERSION;
    desc.type = static_cast<Uint16>(type);
    desc.naxes = static_cast<Uint16>(axes);
    desc.nbuttons = static_cast<Uint16>(buttons);
    desc.nhats = static_cast<Uint16>(hats);
    desc.vendor_id = 0x1234;
    desc.product_id = product;
    desc.name = name;
    if (log != nullptr) {
      desc.userdata = log;
      desc.Rumble = [](void* data, Uint16 low, Uint16 high) {
        static_cast<FeedbackLog*>(data)->rumbles.push_back({low, high});
        return 0;
      };
      desc.SetLED = [](void* data, Uint8 r, Uint8 g, Uint8 b) {
        static_cast<FeedbackLog*>(data)->leds.push_back({r, g, b});
        return 0;
      };
    }
    const int index = SDL_JoystickAttachVirtualEx(&desc);
    EXPECT_GE(index, 0) << SDL_GetError();
    // The test's own handle, to drive the device: SDL shares one per device.
    joystick_ = SDL_JoystickOpen(index);
    EXPECT_NE(joystick_, nullptr) << SDL_GetError();
    id_ = SDL_JoystickInstanceID(joystick_);
  }
  VirtualDevice(VirtualDevice&& other) noexcept : joystick_(other.joystick_), id_(other.id_) {
    other.joystick_ = nullptr;
  }
  VirtualDevice& operator=(VirtualDevice&&) = delete;
  VirtualDevice(const VirtualDevice&) = delete;
  ~VirtualDevice() { unplug(); }

  void unplug() {
    if (joystick_ == nullptr) return;
    const int index = device_index();
    SDL_JoystickClose(joystick_);
    joystick_ = nullptr;
    EXPECT_EQ(SDL_JoystickDetachVirtual(index), 0) << SDL_GetError();
  }

  void button(int b, bool down) { EXPECT_EQ(SDL_JoystickSetVirtualButton(joystick_, b, down ? 1 : 0), 0); }
  void axis(int a, int value) { EXPECT_EQ(SDL_JoystickSetVirtualAxis(joystick_, a, static_cast<Sint16>(value)), 0); }
  void hat(int h, int mask) { EXPECT_EQ(SDL_JoystickSetVirtualHat(joystick_, h, static_cast<Uint8>(mask)), 0); }
  /// What a real driver does between two pumps: hands SDL what has changed,
  /// so that a press and a release in one tick are two queued events.
  static void deliver() { SDL_JoystickUpdate(); }

  [[nodiscard]] int device_index() const {
    for (int i = 0; i < SDL_NumJoysticks(); ++i) {
      if (SDL_JoystickGetDeviceInstanceID(i) == id_) return i;
    }
    return -1;
  }
  [[nodiscard]] SDL_JoystickID instance_id() const { return id_; }
  [[nodiscard]] std::string guid() const {
    char text[33] = {};
    SDL_JoystickGetGUIDString(SDL_JoystickGetGUID(joystick_), text, sizeof text);
    return text;
  }

 private:
  SDL_Joystick* joystick_ = nullptr;
  SDL_JoystickID id_ = -1;
};

}  // namespace andros::test

#pragma once
// One opened SDL device, game controller or plain joystick, and the
// translation of its SDL events into InputEvents.

#include <SDL.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "andros/input/device_layout.hpp"
#include "andros/input/input_state.hpp"

namespace andros::input {

class SdlDevice {
 public:
  /// Opens the device at this SDL device index through the game-controller
  /// API when SDL has a mapping for it, else as a joystick. nullptr (and
  /// SDL_GetError()) when it cannot be opened.
  static std::unique_ptr<SdlDevice> open(int device_index);

  [[nodiscard]] SDL_JoystickID instance_id() const { return id_; }
  [[nodiscard]] bool is_game_controller() const { return pad_ != nullptr; }
  [[nodiscard]] const std::string& name() const { return name_; }
  [[nodiscard]] const std::string& guid() const { return guid_; }
  /// Which physical controller it is: its name, device path, serial (where SDL gives one) and GUID.
  [[nodiscard]] const PadIdentity& identity() const { return identity_; }
  [[nodiscard]] bool attached() const;
  /// The joystick under it (a game controller's too): rumble and light.
  [[nodiscard]] SDL_Joystick* joystick() const { return joystick_; }
  /// Every input it has, for the input tester.
  [[nodiscard]] DeviceLayout layout() const;

  /// The held buttons, hats and off-centre axes now, as events stamped t_ms.
  /// Game-controller triggers are left at rest (see the .cpp).
  void append_state(std::int64_t t_ms, std::vector<InputEvent>& out) const;

  /// This device's event in our terms; nullopt for other devices' events and
  /// for kinds of event the mapping has no use for.
  [[nodiscard]] std::optional<InputEvent> translate(const SDL_Event& event, std::int64_t t_ms) const;

 private:
  struct CloseController {
    void operator()(SDL_GameController* pad) const { SDL_GameControllerClose(pad); }
  };
  struct CloseJoystick {
    void operator()(SDL_Joystick* joy) const { SDL_JoystickClose(joy); }
  };

  std::unique_ptr<SDL_GameController, CloseController> pad_;
  std::unique_ptr<SDL_Joystick, CloseJoystick> joy_;  // only for a plain joystick
  SDL_Joystick* joystick_ = nullptr;                  // pad's joystick, or joy_
  SDL_JoystickID id_ = -1;
  std::string name_;
  std::string guid_;
  PadIdentity identity_;
  std::vector<int> free_hats_;  // a game controller's hats its SDL mapping leaves out
};

/// A game controller's trigger axis (0..32767 in SDL's terms).
bool is_pad_trigger(InputKey key);

}  // namespace andros::input

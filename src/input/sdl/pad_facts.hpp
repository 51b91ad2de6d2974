#pragma once
// What SDL tells of one attached device: the model (GUID, names) and, where
// SDL gives them, its device node and its serial: what tells one unit of a
// model from another.

#include <SDL.h>

#include <optional>
#include <string>
#include <vector>

#include "andros/input/sdl_input.hpp"

namespace andros::input {

struct PadFacts {
  int index = -1;  ///< SDL's device index, now
  SDL_JoystickID instance = -1;
  std::string name;      ///< as SDL's game-controller API names it, else the joystick name
  std::string raw_name;  ///< the joystick name
  std::string guid;      ///< 32 lower-case hex digits: the model
  std::string path;      ///< the device node; "" where SDL gives none
  /// The unit's serial ("" where SDL gives none); unset until read, which
  /// opens the device: read only where a pad of the same model is in play.
  std::optional<std::string> serial;
};

/// Reads PadFacts through SDL, with PadPlaces standing in for SDL's paths and serials.
class PadReader {
 public:
  explicit PadReader(PadPlaces places);

  /// The device at this index, its serial not yet read.
  [[nodiscard]] PadFacts facts(int device_index) const;
  /// Every device attached now, in index order.
  [[nodiscard]] std::vector<PadFacts> attached() const;
  /// pad's serial, read once (the device opened and closed again).
  const std::string& serial(PadFacts& pad) const;

 private:
  PadPlaces places_;
};

/// "controller 1 'Pad A' (GUID ..., /dev/input/event5, serial ...)": the
/// device for a log line; no path and no serial are said as such.
std::string describe(const PadFacts& pad);

}  // namespace andros::input

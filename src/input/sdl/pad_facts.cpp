#include "pad_facts.hpp"

#include <algorithm>
#include <utility>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "controller_selection.hpp"

namespace andros::input {
namespace {

std::string sdl_path(int device_index) {
  const char* path = SDL_JoystickPathForIndex(device_index);
  return path != nullptr ? path : "";
}

// SDL 2.26 reads a serial only from an opened device. SDL shares one handle
// per device: opening one the bridge holds and closing it again leaves it open.
std::string sdl_serial(int device_index) {
  SDL_Joystick* joystick = SDL_JoystickOpen(device_index);
  if (joystick == nullptr) return "";
  const char* serial = SDL_JoystickGetSerial(joystick);
  std::string out = serial != nullptr ? serial : "";
  SDL_JoystickClose(joystick);
  return out;
}

}  // namespace

PadReader::PadReader(PadPlaces places) : places_(std::move(places)) {
  if (!places_.path) places_.path = &sdl_path;
  if (!places_.serial) places_.serial = &sdl_serial;
}

PadFacts PadReader::facts(int device_index) const {
  PadFacts pad;
  pad.index = device_index;
  pad.instance = SDL_JoystickGetDeviceInstanceID(device_index);
  pad.name = device_name(device_index);
  const char* raw = SDL_JoystickNameForIndex(device_index);
  pad.raw_name = raw != nullptr ? raw : "";
  pad.guid = device_guid(device_index);
  pad.path = places_.path(device_index);
  return pad;
}

std::vector<PadFacts> PadReader::attached() const {
  std::vector<PadFacts> out;
  const int count = SDL_NumJoysticks();  // negative on an error
  out.reserve(static_cast<std::size_t>(std::max(count, 0)));
  for (int i = 0; i < count; ++i) out.push_back(facts(i));
  return out;
}

const std::string& PadReader::serial(PadFacts& pad) const {
  if (!pad.serial) pad.serial = places_.serial(pad.index);
  return *pad.serial;
}

std::string describe(const PadFacts& pad) {
  std::string out = "controller " + std::to_string(pad.index) + " " + quote_name(pad.name) + " (GUID " + pad.guid;
  out += pad.path.empty() ? ", no device path" : ", " + printable_text(pad.path);
  if (pad.serial) out += pad.serial->empty() ? ", no serial" : ", serial " + printable_text(*pad.serial);
  return out + ")";
}

}  // namespace andros::input

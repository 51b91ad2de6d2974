#include "controller_selection.hpp"

#include <SDL.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "andros/base/error.hpp"
#include "andros/base/text.hpp"
#include "andros/input/input_state.hpp"
#include "pad_facts.hpp"

namespace andros::input {
namespace {

bool all_of(const std::string& text, int (*pred)(int)) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [pred](unsigned char c) { return pred(c) != 0; });
}

std::string nonnull(const char* text) { return text != nullptr ? text : ""; }

}  // namespace

ControllerSelection::ControllerSelection(const std::string& text, const SourcePos& where) {
  if (text.empty()) return;
  if (text.front() == '/') {
    by_ = By::kPath;
    text_ = text;
    return;
  }
  if (all_of(text, &isdigit)) {
    by_ = By::kIndex;
    index_ = static_cast<int>(parse_integer(text, 0, kMaxJoystickIndex, "controller index", where));
  } else if (text.size() == 32 && all_of(text, &isxdigit)) {
    by_ = By::kGuid;
  } else {
    by_ = By::kName;
  }
  text_ = to_lower(text);
}

bool ControllerSelection::matches(const PadFacts& pad) const {
  switch (by_) {
    case By::kFirst: return true;
    case By::kIndex: return pad.index == index_;
    case By::kGuid: return pad.guid == text_;
    case By::kName:
      // Both names: a mapping may rename a device SDL also knows by its raw name.
      return to_lower(pad.name).find(text_) != std::string::npos ||
             to_lower(pad.raw_name).find(text_) != std::string::npos;
    case By::kPath: {
      // The same file: a link such as /dev/input/by-path/... follows the port.
      std::error_code error;
      return !pad.path.empty() && std::filesystem::equivalent(text_, pad.path, error) && !error;
    }
  }
  return false;
}

std::string ControllerSelection::describe() const {
  switch (by_) {
    case By::kFirst: return "the first controller";
    case By::kIndex: return "controller " + std::to_string(index_);
    case By::kGuid: return "the controller with GUID " + printable_text(text_);
    case By::kName: return "a controller named like " + quote_name(text_);
    case By::kPath: return "the controller at " + printable_text(text_);
  }
  return {};
}

std::string device_name(int device_index) {
  if (SDL_IsGameController(device_index) == SDL_TRUE) {
    return nonnull(SDL_GameControllerNameForIndex(device_index));
  }
  return nonnull(SDL_JoystickNameForIndex(device_index));
}

std::string device_guid(int device_index) {
  char text[33] = {};
  SDL_JoystickGetGUIDString(SDL_JoystickGetDeviceGUID(device_index), text, sizeof text);
  return to_lower(text);
}

}  // namespace andros::input

#pragma once
// Which attached device is "the controller": --controller INDEX|NAME|GUID|PATH.

#include <string>

#include "andros/base/error.hpp"

namespace andros::input {

struct PadFacts;

class ControllerSelection {
 public:
  /// Empty text: the first device. Throws InputError (at where) for an
  /// index beyond kMaxJoystickIndex.
  explicit ControllerSelection(const std::string& text, const SourcePos& where = SourcePos{"--controller"});

  /// Whether this device is the one chosen.
  [[nodiscard]] bool matches(const PadFacts& pad) const;
  [[nodiscard]] std::string describe() const;
  /// No choice made: the first device found.
  [[nodiscard]] bool is_first() const { return by_ == By::kFirst; }
  /// Chosen by its device node: the pad in one port, whichever unit it is.
  [[nodiscard]] bool by_path() const { return by_ == By::kPath; }
  /// The same choice (index, GUID or name, any case) as other.
  [[nodiscard]] bool same_as(const ControllerSelection& other) const {
    return by_ == other.by_ && (by_ == By::kIndex ? index_ == other.index_ : text_ == other.text_);
  }

 private:
  enum class By { kFirst, kIndex, kGuid, kName, kPath };
  By by_ = By::kFirst;
  int index_ = 0;
  std::string text_;  // lower case, for GUID and name; the path as given
};

/// The device's name as SDL's game-controller API names it (or, for a plain
/// joystick, its joystick name); "" when SDL has none.
std::string device_name(int device_index);
/// The device's GUID as 32 lower-case hex digits.
std::string device_guid(int device_index);

}  // namespace andros::input

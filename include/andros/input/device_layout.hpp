#pragma once
/// The inputs an open controller has, for the input tester.

#include <string>
#include <vector>

#include "andros/input/input_state.hpp"

namespace andros::input {

struct DeviceLayout {
  std::string name;
  std::string guid;               ///< 32 hex digits
  bool game_controller = false;   ///< false: a plain joystick
  std::vector<InputKey> buttons;  ///< the pad buttons its SDL mapping has, or every joystick button
  std::vector<InputKey> axes;     ///< the pad axes (triggers too) its mapping has, or every joystick axis
  int hats = 0;                   ///< a plain joystick's hats (a pad's D-pad is buttons)
  /// A game controller's hats that its SDL mapping leaves out (a second hat,
  /// a mapping without a D-pad): read as hat directions, as a joystick's are.
  std::vector<int> free_hats;
};

}  // namespace andros::input

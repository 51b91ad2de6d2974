// `andros-bridge inputs` on the real SDL path: a virtual pad and a virtual
// stick polled the way the tester's loop does, its lines and its screen.
#include <gtest/gtest.h>

#include <algorithm>

#include "andros/input/sdl_input.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/view/inputs_view.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;

class InputTesterTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }

  /// One poll of the tester's loop: its lines.
  std::vector<std::string> poll(SdlInput& input, view::InputsBoard& board) {
    t_ += 20;
    const auto& events = input.poll(t_);  // first: the device is the one after it
    return board.update(events, input.device());
  }

  SdlSession session_;
  std::int64_t t_ = 0;
};

TEST_F(InputTesterTest, APadShowsEveryNamedInputWithItsNumber) {
  auto pad = VirtualDevice::pad("Tester Pad");
  pad.button(SDL_CONTROLLER_BUTTON_B, true);
  SdlInput input(SdlInputOptions{});
  view::InputsBoard board(view::axis_uses(*mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/core.yaml")), "h");
  auto lines = poll(input, board);
  ASSERT_EQ(lines.size(), 2U);
  EXPECT_EQ(lines[0].rfind("20 connect Tester Pad (game controller, GUID ", 0), 0U) << lines[0];
  EXPECT_EQ(lines[1], "20 button b #1 down");

  const auto layout = input.device();
  ASSERT_TRUE(layout.has_value());
  EXPECT_TRUE(layout->game_controller);
  // a..dpright at least (SDL's mapping of a virtual pad may leave out one of the newer buttons).
  ASSERT_GE(layout->buttons.size(), 15U);
  for (std::uint16_t b = 0; b < 15; ++b) EXPECT_EQ(layout->buttons[b], (InputKey{InputKind::kPadButton, b}));
  EXPECT_EQ(layout->axes.size(), static_cast<std::size_t>(SDL_CONTROLLER_AXIS_MAX));

  pad.button(SDL_CONTROLLER_BUTTON_B, false);
  pad.button(SDL_CONTROLLER_BUTTON_DPAD_UP, true);
  pad.axis(SDL_CONTROLLER_AXIS_LEFTY, -18112);
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERRIGHT, 32767);
  lines = poll(input, board);
  std::sort(lines.begin(), lines.end());  // within a poll, in SDL's order
  EXPECT_EQ(lines, (std::vector<std::string>{"40 axis lefty #1 -18112 -0.553 deadzone 0.10 drive: moves",
                                             "40 button b #1 up", "40 button dpup #11 down",
                                             "40 trigger righttrigger #5 32767 1.000 deadzone 0.00 arm_speed: moves"}));
  for (int i = 0; i < 10; ++i) EXPECT_TRUE(poll(input, board).empty());  // no change, no line

  const auto screen = board.compose();
  EXPECT_NE(screen.find("* 11 dpup"), std::string::npos) << screen;
  EXPECT_NE(screen.find("    1 b "), std::string::npos) << screen;
  EXPECT_NE(screen.find("touchpad"), std::string::npos);
  EXPECT_NE(screen.find("righttrigger  32767  1.000 [|==========] moves   deadzone 0.00 arm_speed\n"),
            std::string::npos)
      << screen;

  pad.unplug();
  EXPECT_EQ(poll(input, board), std::vector<std::string>{"260 disconnect"});
  EXPECT_NE(board.compose().find("none connected"), std::string::npos);
}

TEST_F(InputTesterTest, AJoystickShowsNumberedButtonsAxesAndHats) {
  auto stick = VirtualDevice::stick("Tester Stick");
  SdlInput input(SdlInputOptions{});
  view::InputsBoard board({}, "h");
  ASSERT_EQ(poll(input, board).size(), 1U);  // the connect: nothing held
  const auto layout = input.device();
  ASSERT_TRUE(layout.has_value());
  EXPECT_FALSE(layout->game_controller);
  EXPECT_EQ(layout->buttons.size(), 12U);
  EXPECT_EQ(layout->axes.size(), 4U);
  EXPECT_EQ(layout->hats, 1);

  stick.button(11, true);
  stick.axis(2, -32768);
  stick.hat(0, SDL_HAT_UP | SDL_HAT_LEFT);
  auto lines = poll(input, board);
  std::sort(lines.begin(), lines.end());
  EXPECT_EQ(lines, (std::vector<std::string>{"40 axis 2 -32768 -1.000 deadzone 0.00 (default): moves",
                                             "40 button 11 down", "40 hat 0 up+left"}));
  const auto screen = board.compose();
  EXPECT_NE(screen.find("* 11 11"), std::string::npos) << screen;
  EXPECT_NE(screen.find("    0 hat0         up+left"), std::string::npos) << screen;
}

// Issue 19, finding 8: a hat the pad's SDL mapping leaves out is read as a
// hat (SDL's game-controller events never report it), shown and reported.
TEST_F(InputTesterTest, APadsHatOutsideItsMappingShows) {
  VirtualDevice pad("Hat Pad", SDL_JOYSTICK_TYPE_GAMECONTROLLER, SDL_CONTROLLER_AXIS_MAX, SDL_CONTROLLER_BUTTON_MAX, 1,
                    3);
  SdlInput input(SdlInputOptions{});
  view::InputsBoard board({}, "h");
  ASSERT_EQ(poll(input, board).size(), 1U);
  const auto layout = input.device();
  ASSERT_TRUE(layout.has_value());
  ASSERT_TRUE(layout->game_controller);
  ASSERT_EQ(layout->free_hats, std::vector<int>{0});  // SDL maps a virtual pad's D-pad to buttons
  pad.hat(0, SDL_HAT_DOWN);
  EXPECT_EQ(poll(input, board), std::vector<std::string>{"40 hat 0 down"});
  EXPECT_NE(board.compose().find("hats outside its SDL mapping (bind them as hatNup, ...)\n    0 hat0         down\n"),
            std::string::npos)
      << board.compose();
}

}  // namespace
}  // namespace andros::input

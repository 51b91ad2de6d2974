// The live controller through the real SDL path, with virtual devices.
#include <gtest/gtest.h>

#include <algorithm>

#include "andros/input/sdl_input.hpp"
#include "andros/view/status_board.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;
using T = InputEvent::Type;

constexpr InputKey kDeadman{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_LEFTSHOULDER};
constexpr InputKey kLeftX{InputKind::kPadAxis, SDL_CONTROLLER_AXIS_LEFTX};
constexpr InputKey kLeftTrigger{InputKind::kPadAxis, SDL_CONTROLLER_AXIS_TRIGGERLEFT};

class SdlInputTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }

  /// One tick: the next 40 ms step of the run's clock.
  void tick(SdlInput& input) {
    now_ += 40;
    input.pump(tick_, now_);
  }

  SdlSession session_;  // the test's own reference, so devices outlive inputs
  TickInput tick_;
  InputState& state_ = tick_.state();
  std::int64_t now_ = 0;
};

TEST(SdlNames, PadButtonAndAxisNamesAreSdlsInEnumOrder) {
  for (int b = 0; b < SDL_CONTROLLER_BUTTON_MAX; ++b) {
    EXPECT_EQ(SDL_GameControllerGetStringForButton(static_cast<SDL_GameControllerButton>(b)),
              kPadButtonNames[static_cast<std::size_t>(b)]);
  }
  for (int a = 0; a < SDL_CONTROLLER_AXIS_MAX; ++a) {
    EXPECT_EQ(SDL_GameControllerGetStringForAxis(static_cast<SDL_GameControllerAxis>(a)),
              kPadAxisNames[static_cast<std::size_t>(a)]);
  }
}

TEST_F(SdlInputTest, ConnectCarriesTheStateAtConnectAllStampedWithItsTime) {
  auto pad = VirtualDevice::pad("Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  pad.axis(SDL_CONTROLLER_AXIS_LEFTX, 20000);
  SdlInput input(SdlInputOptions{});
  const auto events = input.poll(40);
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.front().type, T::kConnect);
  EXPECT_EQ(events.front().name, "Test Pad");
  for (const auto& e : events) EXPECT_EQ(e.t_ms, 40);
  for (const auto& e : events) state_.apply(e);
  EXPECT_TRUE(state_.connected());
  EXPECT_TRUE(state_.button(kDeadman).down);
  EXPECT_EQ(state_.axis(kLeftX), 20000);
}

TEST_F(SdlInputTest, DeadmanHeldAtConnectIsNotAPress) {
  auto pad = VirtualDevice::pad("Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  SdlInput input(SdlInputOptions{});
  tick(input);
  tick(input);
  EXPECT_TRUE(state_.button(kDeadman).down);
  EXPECT_EQ(state_.button(kDeadman).presses, 0U);
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, false);
  tick(input);
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  tick(input);
  EXPECT_TRUE(state_.button(kDeadman).down);
  EXPECT_EQ(state_.button(kDeadman).presses, 1U);
}

TEST_F(SdlInputTest, PressInTheConnectsOwnPumpCountsAsInitialState) {
  // Conservative by design: the device appears and its button goes down
  // within one tick; we cannot order the two, so it is not a fresh press.
  SdlInput input(SdlInputOptions{});
  tick(input);
  EXPECT_FALSE(state_.connected());
  auto pad = VirtualDevice::pad("Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  tick(input);
  EXPECT_TRUE(state_.connected());
  EXPECT_TRUE(state_.button(kDeadman).down);
  EXPECT_EQ(state_.button(kDeadman).presses, 0U);
}

TEST_F(SdlInputTest, PressAndReleaseBetweenTwoPumpsStillCountsAsAPress) {
  auto pad = VirtualDevice::pad("Test Pad");
  SdlInput input(SdlInputOptions{});
  tick(input);
  pad.button(SDL_CONTROLLER_BUTTON_A, true);
  VirtualDevice::deliver();
  pad.button(SDL_CONTROLLER_BUTTON_A, false);
  tick(input);
  const auto a = state_.button(InputKey{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_A});
  EXPECT_FALSE(a.down);
  EXPECT_EQ(a.presses, 1U);
}

TEST_F(SdlInputTest, ATriggerAtRestIsNotHalfPressedAndReportsItsFirstMovement) {
  auto pad = VirtualDevice::pad("Test Pad");
  // Some drivers report a trigger's raw axis as 0, mid-range, until it first
  // moves: SDL's game-controller API then reads it as half pressed (16384).
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 0);
  SdlInput input(SdlInputOptions{});
  tick(input);
  tick(input);
  EXPECT_EQ(state_.axis(kLeftTrigger), 0);
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 32767);  // fully pressed, raw
  tick(input);
  EXPECT_EQ(state_.axis(kLeftTrigger), 32767);
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);  // released, raw
  tick(input);
  EXPECT_EQ(state_.axis(kLeftTrigger), 0);
}

TEST_F(SdlInputTest, UnplugDisconnectsOnTheNextPumpAndReplugIsANewConnection) {
  auto pad = std::make_unique<VirtualDevice>(VirtualDevice::pad("Test Pad"));
  SdlInput input(SdlInputOptions{});
  tick(input);
  pad->button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);
  tick(input);
  EXPECT_EQ(state_.button(kDeadman).presses, 1U);
  pad->unplug();
  const auto& lost = input.poll(now_ += 40);
  ASSERT_EQ(lost.size(), 1U);
  EXPECT_EQ(lost[0].type, T::kDisconnect);
  for (const auto& e : lost) state_.apply(e);
  EXPECT_FALSE(state_.connected());
  tick(input);
  EXPECT_FALSE(state_.connected());

  pad = std::make_unique<VirtualDevice>(VirtualDevice::pad("Test Pad"));
  pad->button(SDL_CONTROLLER_BUTTON_LEFTSHOULDER, true);  // still held from before
  tick(input);
  EXPECT_TRUE(state_.connected());
  EXPECT_EQ(state_.connection(), 2U);
  EXPECT_TRUE(state_.button(kDeadman).down);
  EXPECT_EQ(state_.button(kDeadman).presses, 0U);
}

TEST_F(SdlInputTest, APlainJoystickHasNumberedButtonsAxesAndHats) {
  auto stick = VirtualDevice::stick("Test Stick");
  stick.hat(0, SDL_HAT_LEFT);  // held at connect: initial state
  SdlInput input(SdlInputOptions{});
  tick(input);
  ASSERT_TRUE(state_.connected());
  EXPECT_EQ(state_.name(), "Test Stick");
  EXPECT_EQ(state_.hat(0), SDL_HAT_LEFT);
  EXPECT_EQ(state_.button(*parse_button_name("hat0left")).presses, 0U);

  stick.button(7, true);
  stick.axis(3, -32768);
  stick.hat(0, SDL_HAT_RIGHTUP);
  tick(input);
  EXPECT_TRUE(state_.button(InputKey{InputKind::kJoyButton, 7}).down);
  EXPECT_EQ(state_.button(InputKey{InputKind::kJoyButton, 7}).presses, 1U);
  EXPECT_EQ(state_.axis(InputKey{InputKind::kJoyAxis, 3}), -32768);
  EXPECT_EQ(state_.hat(0), SDL_HAT_RIGHTUP);
  EXPECT_EQ(state_.button(*parse_button_name("hat0up")).presses, 1U);
  // Pad names mean nothing on a plain joystick.
  EXPECT_FALSE(state_.button(kDeadman).down);
}

TEST_F(SdlInputTest, PollsAreNonBlockingAndQuietWithoutChanges) {
  auto pad = VirtualDevice::pad("Test Pad");
  SdlInput input(SdlInputOptions{});
  EXPECT_FALSE(input.poll(40).empty());
  EXPECT_TRUE(input.poll(80).empty());
  EXPECT_TRUE(input.poll(120).empty());
  EXPECT_FALSE(input.finished(120));
}

// Issue 19, finding 6: a controller SDL knows only as a plain joystick sends
// numbered inputs, never the game-controller names a mapping reads. The board,
// told by the input on the connect, says so (with the ways out) where it would
// say "deadman released" forever; a game controller keeps the plain words.
TEST_F(SdlInputTest, AJoystickUnderAGameControllerMappingIsSaidWithTheHint) {
  for (const bool pad : {false, true}) {
    auto device = pad ? VirtualDevice::pad("Hint Pad") : VirtualDevice::stick("Hint Stick");
    SdlInput input(SdlInputOptions{});
    tick(input);
    ASSERT_TRUE(state_.connected());
    view::RunStatusBoard board(view::RunStatus{});
    board.set_pad_names(true);  // hd1's: leftshoulder, leftx...
    run::TickReport r;
    r.connected = true;
    r.controller = state_.name();
    r.state = run::OpState::kNotEnabled;
    r.engine.deadman = mapping::DeadmanState::kReleased;
    board.observe(r, input);
    const auto status = board.status();
    EXPECT_EQ(status.game_controller, std::optional<bool>(pad));
    const auto screen = view::render_run_screen(status, {80, 24}).render({80, 24}, false);
    if (pad) {
      EXPECT_EQ(status.enable_text, "press the deadman to enable");
      EXPECT_EQ(screen.find("plain joystick"), std::string::npos) << screen;
    } else {
      EXPECT_NE(status.enable_text.find("not a game controller"), std::string::npos) << status.enable_text;
      EXPECT_NE(status.enable_text.find("--controller-db FILE"), std::string::npos) << status.enable_text;
      EXPECT_NE(status.enable_text.find("andros-bridge learn"), std::string::npos) << status.enable_text;
      EXPECT_NE(screen.find("Hint Stick  (a plain joystick to SDL)"), std::string::npos) << screen;
      EXPECT_NE(screen.find("--controller-db FILE"), std::string::npos) << screen;  // the state wraps, whole
    }
    // A mapping of numbered inputs (learned for this stick) needs no hint.
    board.set_pad_names(false);
    board.observe(r, input);
    EXPECT_EQ(board.status().enable_text, "press the deadman to enable");
    // Unplugged: nothing is said of a device that is not there.
    device.unplug();
    tick(input);
    r.connected = false;
    r.state = run::OpState::kNoController;
    board.observe(r, input);
    EXPECT_EQ(board.status().game_controller, std::nullopt);
    state_ = InputState{};
  }
}

}  // namespace
}  // namespace andros::input

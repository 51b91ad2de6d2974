// The live controller read for deliberate inputs, with SDL's virtual devices.
#include <gtest/gtest.h>

#include "andros/input/live_gestures.hpp"
#include "support/virtual_device.hpp"

namespace andros::input {
namespace {

using test::VirtualDevice;

class LiveGesturesTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { test::use_dummy_video(); }
  SdlSession session_;
};

/// Polls a few times; the first gesture seen.
std::optional<Gesture> read(LiveGestures& live) {
  for (int i = 0; i < 5; ++i) {
    if (auto g = live.poll()) return g;
  }
  return std::nullopt;
}

TEST_F(LiveGesturesTest, APadsButtonAndStickPushAreGesturesWhatIsHeldAtConnectIsNot) {
  auto pad = VirtualDevice::pad("Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_A, true);
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTX, 32767);
  LiveGestures live({});
  EXPECT_FALSE(read(live));
  EXPECT_TRUE(live.connected());
  EXPECT_EQ(live.name(), "Test Pad");
  pad.button(SDL_CONTROLLER_BUTTON_A, false);
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTX, 0);  // back from a push it was never seen starting
  EXPECT_FALSE(read(live));
  pad.button(SDL_CONTROLLER_BUTTON_Y, true);
  EXPECT_EQ(read(live), (Gesture{{InputKind::kPadButton, SDL_CONTROLLER_BUTTON_Y}, false}));
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTY, -32768);
  EXPECT_FALSE(read(live));
  pad.axis(SDL_CONTROLLER_AXIS_RIGHTY, 0);
  EXPECT_EQ(read(live), (Gesture{{InputKind::kPadAxis, SDL_CONTROLLER_AXIS_RIGHTY}, true}));
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, 32767);
  EXPECT_FALSE(read(live));
  pad.axis(SDL_CONTROLLER_AXIS_TRIGGERLEFT, -32768);  // a virtual trigger's raw range maps to 0..32767
  EXPECT_EQ(read(live), (Gesture{{InputKind::kPadAxis, SDL_CONTROLLER_AXIS_TRIGGERLEFT}, false}));
}

TEST_F(LiveGesturesTest, APlainJoysticksHatDirectionIsAButton) {
  auto stick = VirtualDevice::stick("Test Stick");
  LiveGestures live({});
  EXPECT_FALSE(read(live));
  stick.hat(0, SDL_HAT_LEFT);
  EXPECT_EQ(read(live), (Gesture{{InputKind::kHat, 3}, false}));  // hat0left
  stick.hat(0, SDL_HAT_CENTERED);
  stick.button(7, true);
  EXPECT_EQ(read(live), (Gesture{{InputKind::kJoyButton, 7}, false}));
}

TEST_F(LiveGesturesTest, ResetDropsAPushUnderWay) {
  auto pad = VirtualDevice::pad("Test Pad");
  LiveGestures live({});
  EXPECT_FALSE(read(live));
  pad.axis(SDL_CONTROLLER_AXIS_LEFTX, 32767);
  EXPECT_FALSE(read(live));
  live.reset();
  pad.axis(SDL_CONTROLLER_AXIS_LEFTX, 0);
  EXPECT_FALSE(read(live));
}

}  // namespace
}  // namespace andros::input

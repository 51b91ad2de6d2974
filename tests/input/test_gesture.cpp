// Deliberate inputs: what learn takes as "the operator pressed this".
#include <gtest/gtest.h>

#include "andros/input/gesture.hpp"

namespace andros::input {
namespace {

using T = InputEvent::Type;

const InputKey kA{InputKind::kPadButton, 0};
const InputKey kLeftY{InputKind::kPadAxis, 1};
const InputKey kLeftX{InputKind::kPadAxis, 0};

InputEvent key_ev(std::int64_t t, T type, InputKey key = {}, int value = 0) {
  return InputEvent{.t_ms = t, .type = type, .key = key, .value = value, .name = {}, .line = 0};
}

class GestureTest : public ::testing::Test {
 protected:
  void SetUp() override { EXPECT_FALSE(detector_.feed(key_ev(0, T::kConnect))); }
  std::optional<Gesture> feed(T type, InputKey key, int value) {
    return detector_.feed(key_ev(t_ += 10, type, key, value));
  }
  GestureDetector detector_;
  std::int64_t t_ = 0;
};

TEST_F(GestureTest, AButtonCountsWhenPressedNotWhenReleased) {
  EXPECT_EQ(feed(T::kButton, kA, 1), (Gesture{kA, false}));
  EXPECT_FALSE(feed(T::kButton, kA, 0));
  EXPECT_EQ(feed(T::kButton, kA, 1), (Gesture{kA, false}));
}

TEST_F(GestureTest, WhatIsHeldAtConnectIsNotAGesture) {
  EXPECT_FALSE(detector_.feed(key_ev(100, T::kConnect)));
  EXPECT_FALSE(detector_.feed(key_ev(100, T::kButton, kA, 1)));
  EXPECT_FALSE(detector_.feed(key_ev(100, T::kAxis, kLeftY, -32768)));
  t_ = 100;
  EXPECT_FALSE(feed(T::kButton, kA, 0));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, 0));  // back from a push it was never seen starting
  EXPECT_EQ(feed(T::kButton, kA, 1), (Gesture{kA, false}));
}

TEST_F(GestureTest, AnAxisCountsWhenPushedFarThenLetGoWithItsDirection) {
  EXPECT_FALSE(feed(T::kAxis, kLeftY, -12000));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, -30000));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, -20000));
  EXPECT_EQ(feed(T::kAxis, kLeftY, -3000), (Gesture{kLeftY, true}));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, 0));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, 32767));
  EXPECT_EQ(feed(T::kAxis, kLeftY, 100), (Gesture{kLeftY, false}));
}

TEST_F(GestureTest, AStickRestingOffCentreOrNudgedIsNoGesture) {
  for (int i = 0; i < 20; ++i) EXPECT_FALSE(feed(T::kAxis, kLeftX, i % 2 == 0 ? 9000 : -kGesturePushed + 1));
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 0));
}

TEST_F(GestureTest, ADiagonalPushGivesOneGesture) {
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 30000));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, -30000));
  EXPECT_EQ(feed(T::kAxis, kLeftX, 0), (Gesture{kLeftX, false}));
  EXPECT_FALSE(feed(T::kAxis, kLeftY, 0));
}

TEST_F(GestureTest, ResetDropsAPushUnderWayUntilTheAxisIsBackAtRest) {
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 30000));
  detector_.reset();
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 0));
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 30000));
  EXPECT_EQ(feed(T::kAxis, kLeftX, 0), (Gesture{kLeftX, false}));
}

TEST_F(GestureTest, AHatDirectionIsAButton) {
  const InputKey hat1{InputKind::kHat, 4};
  EXPECT_EQ(feed(T::kHat, hat1, 2), (Gesture{InputKey{InputKind::kHat, 5}, false}));      // hat1right
  EXPECT_EQ(feed(T::kHat, hat1, 2 | 4), (Gesture{InputKey{InputKind::kHat, 6}, false}));  // down added
  EXPECT_FALSE(feed(T::kHat, hat1, 0));
}

TEST_F(GestureTest, ALostControllerForgetsEverything) {
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 30000));
  EXPECT_FALSE(feed(T::kDisconnect, {}, 0));
  EXPECT_FALSE(feed(T::kAxis, kLeftX, 0));
}

}  // namespace
}  // namespace andros::input

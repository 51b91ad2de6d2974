// apply_safety(): the safety rules of docs/mapping.md on a state that asks for everything.
#include <gtest/gtest.h>

#include "andros/safety.hpp"

namespace andros {
namespace {

ControlState everything_on() {
  ControlState s;
  for (auto& v : s.values) v = 1;
  s[signal_id("drive")] = 200;
  s[signal_id("pivot")] = 10;
  s[signal_id("arm_speed")] = 77;
  s[signal_id("light")] = 99;
  return s;
}

TEST(Safety, NotEnabledIsNeutralKeepingSelectorsAndLevels) {
  const auto s = apply_safety(everything_on(), SafetyContext{false, true, std::bitset<kSignalCount>().set()});
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    const auto& sig = kSignals[i];
    switch (sig.kind) {
      case SignalKind::kMotion:
      case SignalKind::kWeapon:
      case SignalKind::kInterlock: EXPECT_EQ(s.values[i], 0) << sig.name; break;
      case SignalKind::kCentred: EXPECT_EQ(s.values[i], 128) << sig.name; break;
      case SignalKind::kSelector: EXPECT_EQ(s.values[i], sig.name.starts_with("speed") ? 0 : 1) << sig.name; break;
      default: break;
    }
  }
  EXPECT_EQ(s[signal_id("arm_speed")], 77);
  EXPECT_EQ(s[signal_id("light")], 99);
}

TEST(Safety, EnabledSetsTheInterlocksAndDropsOpposingPairs) {
  auto asked = everything_on();
  asked[signal_id("tool_on")] = 1;
  const auto s = apply_safety(asked, SafetyContext{true, false, {}});
  EXPECT_EQ(s[signal_id("safety")], 1);
  EXPECT_EQ(s[signal_id("drive_brake")], 1);
  EXPECT_EQ(s[signal_id("tool_on")], 1);  // no partner
  EXPECT_EQ(s[signal_id("drive")], 200);
  for (std::size_t i = 0; i < kSignalCount; ++i) {
    if (partner_of(static_cast<SignalId>(i))) {
      EXPECT_EQ(s.values[i], 0) << kSignals[i].name;
    }
    if (kSignals[i].kind == SignalKind::kWeapon) {
      EXPECT_EQ(s.values[i], 0) << "weapons are off";
    }
  }
}

TEST(Safety, WeaponsNeedTheRunFlagAndTheirArm) {
  std::bitset<kSignalCount> armed;
  armed.set(signal_id("weapon_1"));
  const auto s = apply_safety(everything_on(), SafetyContext{true, true, armed});
  EXPECT_EQ(s[signal_id("weapon_1")], 1);
  EXPECT_EQ(s[signal_id("weapon_2")], 0);
  EXPECT_EQ(apply_safety(everything_on(), SafetyContext{true, false, armed})[signal_id("weapon_1")], 0);
}

TEST(Safety, BrakeWhileMovingOnly) {
  ControlState rest;
  rest[signal_id("drive")] = 128;
  rest[signal_id("pivot")] = 128;
  SafetyContext ctx{true, false, {}, 128, BrakeMode::kMoving};
  EXPECT_EQ(apply_safety(rest, ctx)[signal_id("drive_brake")], 0);
  EXPECT_EQ(apply_safety(rest, ctx)[signal_id("safety")], 1);
  rest[signal_id("pivot")] = 129;
  EXPECT_EQ(apply_safety(rest, ctx)[signal_id("drive_brake")], 1);
  ctx.enabled = false;
  EXPECT_EQ(apply_safety(rest, ctx)[signal_id("drive_brake")], 0);
}

}  // namespace
}  // namespace andros

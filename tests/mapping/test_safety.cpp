// apply_safety(): the safety rules of docs/mapping.md on a state that asks for everything.
#include <gtest/gtest.h>

#include "andros/mapping/safety.hpp"

namespace andros::mapping {
namespace {

protocol::ControlState everything_on() {
  protocol::ControlState s;
  for (auto& v : s.values) v = 1;
  s[protocol::signal_id("drive")] = 200;
  s[protocol::signal_id("pivot")] = 10;
  s[protocol::signal_id("arm_speed")] = 77;
  s[protocol::signal_id("light")] = 99;
  return s;
}

TEST(Safety, NotEnabledIsNeutralKeepingSelectorsAndLevels) {
  const auto s = apply_safety(everything_on(), SafetyContext{false, true, std::bitset<protocol::kSignalCount>().set()});
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    const auto& sig = protocol::kSignals[i];
    switch (sig.kind) {
      case protocol::SignalKind::kMotion:
      case protocol::SignalKind::kWeapon:
      case protocol::SignalKind::kInterlock: EXPECT_EQ(s.values[i], 0) << sig.name; break;
      case protocol::SignalKind::kCentred: EXPECT_EQ(s.values[i], 128) << sig.name; break;
      case protocol::SignalKind::kSelector:
        EXPECT_EQ(s.values[i], sig.name.starts_with("speed") ? 0 : 1) << sig.name;
        break;
      default: break;
    }
  }
  EXPECT_EQ(s[protocol::signal_id("arm_speed")], 77);
  EXPECT_EQ(s[protocol::signal_id("light")], 99);
}

TEST(Safety, NotEnabledCentresAt128WhateverTheTrim) {
  for (const int trim : {120, 124, 136}) {
    const auto s = apply_safety(everything_on(), SafetyContext{false, false, {}, trim});
    EXPECT_EQ(s[protocol::signal_id("drive")], 128) << "center " << trim;
    EXPECT_EQ(s[protocol::signal_id("pivot")], 128) << "center " << trim;
  }
}

TEST(Safety, EnabledSetsTheInterlocksAndDropsOpposingPairs) {
  auto asked = everything_on();
  asked[protocol::signal_id("tool_on")] = 1;
  const auto s = apply_safety(asked, SafetyContext{true, false, {}});
  EXPECT_EQ(s[protocol::signal_id("safety")], 1);
  EXPECT_EQ(s[protocol::signal_id("drive_brake")], 1);
  EXPECT_EQ(s[protocol::signal_id("tool_on")], 1);  // no partner
  EXPECT_EQ(s[protocol::signal_id("drive")], 200);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::partner_of(static_cast<protocol::SignalId>(i))) {
      EXPECT_EQ(s.values[i], 0) << protocol::kSignals[i].name;
    }
    if (protocol::kSignals[i].kind == protocol::SignalKind::kWeapon) {
      EXPECT_EQ(s.values[i], 0) << "weapons are off";
    }
  }
}

TEST(Safety, WeaponsNeedTheRunFlagAndTheirArm) {
  std::bitset<protocol::kSignalCount> armed;
  armed.set(protocol::signal_id("weapon_1"));
  const auto s = apply_safety(everything_on(), SafetyContext{true, true, armed});
  EXPECT_EQ(s[protocol::signal_id("weapon_1")], 1);
  EXPECT_EQ(s[protocol::signal_id("weapon_2")], 0);
  EXPECT_EQ(apply_safety(everything_on(), SafetyContext{true, false, armed})[protocol::signal_id("weapon_1")], 0);
}

// The two-person rule: without the supervisor's consent no weapon is sent, armed or not.
TEST(Safety, WeaponsNeedTheSupervisorsConsentWhenAskedFor) {
  std::bitset<protocol::kSignalCount> armed;
  armed.set(protocol::signal_id("weapon_1"));
  SafetyContext ctx{true, true, armed};
  ctx.consent = false;
  const auto s = apply_safety(everything_on(), ctx);
  for (std::size_t i = 0; i < protocol::kSignalCount; ++i) {
    if (protocol::kSignals[i].kind == protocol::SignalKind::kWeapon) {
      EXPECT_EQ(s.values[i], 0) << protocol::kSignals[i].name;
    }
  }
  EXPECT_EQ(s[protocol::signal_id("safety")], 1);  // motion is not the supervisor's to give
}

TEST(Safety, BrakeWhileMovingOnly) {
  protocol::ControlState rest;
  rest[protocol::signal_id("drive")] = 128;
  rest[protocol::signal_id("pivot")] = 128;
  SafetyContext ctx{true, false, {}, 128, BrakeMode::kMoving};
  EXPECT_EQ(apply_safety(rest, ctx)[protocol::signal_id("drive_brake")], 0);
  EXPECT_EQ(apply_safety(rest, ctx)[protocol::signal_id("safety")], 1);
  rest[protocol::signal_id("pivot")] = 129;
  EXPECT_EQ(apply_safety(rest, ctx)[protocol::signal_id("drive_brake")], 1);
  ctx.enabled = false;
  EXPECT_EQ(apply_safety(rest, ctx)[protocol::signal_id("drive_brake")], 0);
}

TEST(Safety, BrakeWhileMovingMeasuresFromTheTrim) {
  // A trim is where the vehicle is still while enabled: 124 holds the brakes, 128 releases them.
  protocol::ControlState s;
  s[protocol::signal_id("drive")] = 124;
  s[protocol::signal_id("pivot")] = 124;
  const SafetyContext ctx{true, false, {}, 124, BrakeMode::kMoving};
  EXPECT_EQ(apply_safety(s, ctx)[protocol::signal_id("drive_brake")], 0);
  s[protocol::signal_id("drive")] = 128;
  EXPECT_EQ(apply_safety(s, ctx)[protocol::signal_id("drive_brake")], 1);
}

}  // namespace
}  // namespace andros::mapping

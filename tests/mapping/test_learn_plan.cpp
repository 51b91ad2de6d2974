// learn's plan: the steps it walks, what each takes, and what it refuses.
#include <gtest/gtest.h>

#include "andros/mapping/learn.hpp"
#include "andros/mapping/loader.hpp"
#include "support/learn_helpers.hpp"

namespace andros::mapping {
namespace {

using test::axis;
using test::button;
using test::step_of;
using Kind = LearnResult::Kind;

Mapping hd1() { return *load_mapping(std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml"); }

TEST(LearnPlan, WalksTheDeadmanThenEachLayersKeyAndEveryInputOfEveryBinding) {
  const auto m = hd1();
  const LearnPlan plan(m);
  std::size_t inputs = 1;  // the deadman
  for (const auto ref : all_bindings(m)) {
    const auto& b = binding_at(m, ref);
    inputs += b.inputs.size() + (b.arm ? 1 : 0);
  }
  inputs += m.layers.size();
  ASSERT_EQ(plan.steps().size(), inputs);
  EXPECT_EQ(plan.prompt(0),
            "[1/" + std::to_string(inputs) +
                "] base layer, the deadman: press a button or pull a trigger (Enter keeps leftshoulder)");
  const auto up = step_of(plan, "base layer, front_art_up");
  EXPECT_NE(plan.prompt(up).find("(Enter keeps dpup)"), std::string::npos);
  EXPECT_EQ(plan.current(step_of(plan, "base layer, drive")), "lefty up");
  EXPECT_EQ(plan.current(step_of(plan, "base layer, pt_left / pt_right")), "rightx left");
  EXPECT_EQ(plan.current(step_of(plan, "layer 'camera', light down")), "x");
  EXPECT_EQ(plan.current(step_of(plan, "layer 'weapons', weapon_1 arming input")), "lefttrigger");
  const auto arm_key = step_of(plan, "layer 'arm', the key of layer 'arm' (toggle)");
  EXPECT_EQ(plan.next_layer(up), arm_key);
  EXPECT_LT(step_of(plan, "layer 'arm', arm_speed"),
            step_of(plan, "layer 'camera', the key of layer 'camera' (toggle)"));
}

TEST(LearnPlan, AFreeButtonIsTakenAndTheSameInputIsKept) {
  LearnPlan plan(hd1());
  const auto up = step_of(plan, "base layer, front_art_up");
  EXPECT_EQ(plan.assign(up, button("dpup")).kind, Kind::kKept);
  EXPECT_FALSE(plan.changed());
  const auto r = plan.assign(up, button("paddle1"));
  EXPECT_EQ(r.kind, Kind::kChanged);
  EXPECT_EQ(r.message, "front_art_up: dpup -> paddle1");
  EXPECT_EQ(plan.current(up), "paddle1");
  EXPECT_TRUE(plan.changed());
}

TEST(LearnPlan, AnInputUsedInTheSameLayerIsRefusedAndNothingChanges) {
  LearnPlan plan(hd1());
  const auto up = step_of(plan, "base layer, front_art_up");
  const auto r = plan.assign(up, button("b"));
  EXPECT_EQ(r.kind, Kind::kRefused);
  EXPECT_EQ(r.message, "'b' is already used for selector inset_video next in the base layer");
  EXPECT_EQ(plan.assign(up, button("leftshoulder")).message, "'leftshoulder' is the deadman");
  EXPECT_EQ(plan.assign(up, button("rightshoulder")).message, "'rightshoulder' is the key of layer 'weapons' (hold)");
  EXPECT_FALSE(plan.changed());
  // Taken once, an input is refused for the next binding of the layer too.
  ASSERT_EQ(plan.assign(up, button("paddle1")).kind, Kind::kChanged);
  EXPECT_EQ(plan.assign(step_of(plan, "base layer, front_art_down"), button("paddle1")).message,
            "'paddle1' is already used for front_art_up in the base layer");
}

TEST(LearnPlan, ALayerBindingMayTakeAnInputOnlyTheBaseLayerUses) {
  LearnPlan plan(hd1());
  EXPECT_EQ(plan.assign(step_of(plan, "layer 'arm', gripper_close"), button("b")).kind, Kind::kChanged);
  // a, which gripper_close no longer reads, is free in the arm layer again.
  EXPECT_EQ(plan.assign(step_of(plan, "layer 'arm', gripper_open"), button("a")).kind, Kind::kChanged);
}

TEST(LearnPlan, TheDeadmanAndLayerKeysAreRefusedAnyInputAnyLayerUses) {
  LearnPlan plan(hd1());
  EXPECT_EQ(plan.assign(0, button("misc1")).kind, Kind::kChanged);
  EXPECT_EQ(plan.assign(0, button("back")).kind, Kind::kRefused);  // bound in the base and camera layers
  const auto camera = step_of(plan, "layer 'camera', the key of layer 'camera' (toggle)");
  EXPECT_EQ(plan.assign(camera, button("misc1")).message, "'misc1' is the deadman");
  EXPECT_EQ(plan.assign(camera, button("paddle4")).kind, Kind::kChanged);
}

TEST(LearnPlan, AnAxisPushSetsTheDirection) {
  LearnPlan plan(hd1());
  const auto pan = step_of(plan, "base layer, pt_left / pt_right");
  EXPECT_EQ(plan.assign(pan, axis("rightx", true)).kind, Kind::kKept);  // pushed left sets pt_left: as it is
  EXPECT_EQ(plan.assign(pan, axis("rightx", false)).message, "pt_left / pt_right: rightx left -> rightx right");
  EXPECT_NE(binding_yaml(plan.learned().bindings[pan - 1], "").find("invert: true"), std::string::npos);
  const auto drive = step_of(plan, "base layer, drive");
  EXPECT_EQ(plan.assign(drive, axis("lefty", true)).kind, Kind::kKept);
  EXPECT_EQ(plan.assign(drive, axis("lefty", false)).kind, Kind::kChanged);
  EXPECT_EQ(binding_yaml(plan.learned().bindings[drive - 1], ""),
            "- analog: drive\n  axis: lefty\n  deadzone: 0.1\n  expo: 0.3\n");
}

TEST(LearnPlan, EachStepTakesItsKindOfInputOnly) {
  LearnPlan plan(hd1());
  EXPECT_EQ(plan.assign(step_of(plan, "base layer, drive"), button("paddle1")).message,
            "drive takes a stick or trigger, not the button paddle1");
  EXPECT_EQ(plan.assign(step_of(plan, "base layer, tool_on (toggle)"), axis("lefty", true)).message,
            "tool_on (toggle) takes a button, not lefty up");
  EXPECT_EQ(plan.assign(step_of(plan, "base layer, pt_left / pt_right"), axis("righttrigger", false)).message,
            "pt_left / pt_right needs a stick: a trigger moves one way only");
  EXPECT_EQ(plan.assign(0, axis("leftx", false)).message, "the deadman takes a button or a trigger, not leftx right");
  EXPECT_EQ(plan.assign(step_of(plan, "layer 'camera', light down"), button("b")).message,
            "'b' is already used for light up in the layer 'camera'");
}

TEST(LearnPlan, WeaponsShareAnArmButAnArmMayFireNothingElse) {
  LearnPlan plan(hd1());
  const auto arm1 = step_of(plan, "layer 'weapons', weapon_1 arming input");
  EXPECT_EQ(plan.assign(arm1, button("b")).message, "'b' is already used for weapon_2 in the layer 'weapons'");
  // RT is fiber_unwind in the base layer: as an arming input in the weapons
  // layer it replaces that binding there, as any layer binding does.
  EXPECT_EQ(plan.assign(arm1, axis("righttrigger", false)).kind, Kind::kChanged);
  EXPECT_EQ(plan.assign(arm1, button("paddle1")).kind, Kind::kChanged);
  EXPECT_EQ(plan.assign(step_of(plan, "layer 'weapons', weapon_2 arming input"), button("paddle1")).kind,
            Kind::kChanged);
  EXPECT_EQ(plan.assign(step_of(plan, "layer 'weapons', weapon_3"), button("paddle1")).message,
            "'paddle1' is already used for weapon_1 arming input in the layer 'weapons'");
}

}  // namespace
}  // namespace andros::mapping

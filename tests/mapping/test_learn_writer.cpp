// The file learn writes: it extends the base with only what changed, and the
// real loader reads it back as exactly what was learned.
#include <gtest/gtest.h>

#include "andros/mapping/learn.hpp"
#include "andros/mapping/loader.hpp"
#include "support/learn_helpers.hpp"
#include "support/temp_dir.hpp"

namespace andros::mapping {
namespace {

using test::axis;
using test::button;
using test::reads;
using test::step_of;
using Kind = LearnResult::Kind;

const std::string kHd1 = std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml";

/// Writes the plan's file beside nothing (extends names the base by its
/// absolute path), loads it with the real loader and checks it reads back.
Mapping write_and_load(const LearnPlan& plan, const testing::TempDir& dir, const std::string& base = kHd1) {
  const auto text = plan.extending_yaml(base);
  const auto file = dir.write("mine.yaml", text);
  auto loaded = *load_mapping(file);
  EXPECT_TRUE(plan.matches(loaded)) << text;
  return loaded;
}

TEST(LearnWriter, AMovedButtonIsWrittenWithAnUnbindOfItsOldInput) {
  LearnPlan plan(*load_mapping(kHd1));
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, front_art_up"), button("paddle1")).kind, Kind::kChanged);
  EXPECT_EQ(plan.extending_yaml("hd1.yaml"),
            "# Written by andros-bridge learn: only what changed from the mapping it extends.\n"
            "robot: HD1\n"
            "extends: \"hd1.yaml\"\n"
            "bindings:\n"
            "  - unbind: dpup\n"
            "  - signal: front_art_up    # was dpup\n"
            "    button: paddle1\n");
  testing::TempDir dir;
  const auto loaded = write_and_load(plan, dir);
  EXPECT_FALSE(reads(loaded.bindings, "dpup"));
  EXPECT_TRUE(reads(loaded.bindings, "paddle1"));
}

TEST(LearnWriter, ABindingThatKeepsAnInputOrItsByteNeedsNoUnbind) {
  LearnPlan plan(*load_mapping(kHd1));
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, drive"), axis("lefty", false)).kind, Kind::kChanged);
  ASSERT_EQ(plan.assign(step_of(plan, "layer 'camera', light up"), button("paddle2")).kind, Kind::kChanged);
  ASSERT_EQ(plan.assign(step_of(plan, "layer 'weapons', weapon_1 arming input"), button("paddle1")).kind,
            Kind::kChanged);
  const auto text = plan.extending_yaml(kHd1);
  EXPECT_EQ(text.find("unbind"), std::string::npos) << text;
  EXPECT_NE(text.find("  \"camera\":\n    toggle: leftstick\n    bindings:\n"
                      "      - analog: light    # was b, x\n        increase: paddle2\n"),
            std::string::npos)
      << text;
  testing::TempDir dir;
  write_and_load(plan, dir);
}

TEST(LearnWriter, TheDeadmanAndALayerKeyAreWrittenWithTheirLayer) {
  LearnPlan plan(*load_mapping(kHd1));
  ASSERT_EQ(plan.assign(0, axis("righttrigger", false)).kind, Kind::kRefused);  // fiber_unwind reads it
  ASSERT_EQ(plan.assign(0, button("misc1")).kind, Kind::kChanged);
  ASSERT_EQ(plan.assign(step_of(plan, "layer 'arm', the key of layer 'arm' (toggle)"), button("paddle3")).kind,
            Kind::kChanged);
  const auto text = plan.extending_yaml(kHd1);
  EXPECT_NE(text.find("deadman: misc1    # was leftshoulder\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  \"arm\":\n    toggle: paddle3    # was rightstick\n    bindings: []\n"), std::string::npos)
      << text;
  testing::TempDir dir;
  const auto loaded = write_and_load(plan, dir);
  EXPECT_EQ(input::input_name(loaded.deadman->key), "misc1");
}

TEST(LearnWriter, ASwapThroughAFreeInputReadsBack) {
  LearnPlan plan(*load_mapping(kHd1));
  const auto up = step_of(plan, "base layer, rear_art_up");
  ASSERT_EQ(plan.assign(up, button("paddle1")).kind, Kind::kChanged);
  ASSERT_EQ(plan.assign(step_of(plan, "base layer, rear_art_down"), button("y")).kind, Kind::kChanged);
  ASSERT_EQ(plan.assign(up, button("a")).kind, Kind::kChanged);
  const auto text = plan.extending_yaml(kHd1);
  EXPECT_EQ(text.find("unbind"), std::string::npos) << text;  // each new binding replaces the other's old one
  testing::TempDir dir;
  const auto loaded = write_and_load(plan, dir);
  EXPECT_FALSE(reads(loaded.bindings, "paddle1"));
}

TEST(LearnWriter, EveryBindingKindOfEveryShippedMappingRoundTrips) {
  for (const char* robot : {"f6a", "va1", "wolverine", "hd1", "prowler", "rav", "rons"}) {
    const auto file = std::string(ANDROS_MAPPINGS_DIR) + "/" + robot + ".yaml";
    const LearnPlan plan(*load_mapping(file));
    for (const auto ref : all_bindings(plan.base())) {
      const auto& b = binding_at(plan.base(), ref);
      testing::TempDir dir;
      const auto base = dir.write("base.yaml", "deadman: leftshoulder\nbindings:\n" + binding_yaml(b, "  "));
      const auto again = load_mapping_file(base);
      ASSERT_EQ(again.bindings.size(), 1U);
      EXPECT_EQ(binding_yaml(again.bindings[0], ""), binding_yaml(b, "")) << robot;
    }
  }
}

TEST(LearnWriter, AnUnbindOfANumberWritesTheOtherBindingOfThatNumberAgain) {
  testing::TempDir dir;
  const auto base = dir.write("stick.yaml",
                              "robot: HD1\ndeadman: 0\nbindings:\n"
                              "  - signal: zoom_up\n    button: 3\n"
                              "  - signal: [pt_left, pt_right]\n    axis: 3\n    threshold: 0.25\n");
  LearnPlan plan(*load_mapping(base));
  ASSERT_EQ(plan.assign(1, button("4")).kind, Kind::kChanged);
  const auto text = plan.extending_yaml("stick.yaml");
  EXPECT_NE(text.find("  - unbind: 3\n"), std::string::npos) << text;
  EXPECT_NE(text.find("  - signal: [pt_left, pt_right]    # unchanged\n    axis: 3\n    threshold: 0.25\n"),
            std::string::npos)
      << text;
  write_and_load(plan, dir, "stick.yaml");
}

}  // namespace
}  // namespace andros::mapping

// The mapping's `scale:` (speed levels, docs/mapping.md): its form, its
// default, and every bad file at its FILE:LINE:COL.
#include <gtest/gtest.h>

#include "andros/mapping/loader.hpp"
#include "support/input_error.hpp"
#include "support/temp_dir.hpp"

namespace andros::mapping {
namespace {

// `scale:` on line 3, the bindings from line 5.
const std::string kScaleHead = "robot: HD1\ndeadman: leftshoulder\n";
const std::string kBindings = "bindings:\n  - analog: drive\n    axis: lefty\n  - signal: tool_on\n    button: x\n";

ValidMapping load_text(const std::string& text) {
  const testing::TempDir dir;
  return load_mapping(dir.write("m.yaml", text));
}

TEST(MappingScale, AbsentIsOneLevelOfFullSpeed) {
  const auto m = load_text(kScaleHead + kBindings);
  EXPECT_EQ(m->scale.levels, std::vector{1.0});
  EXPECT_EQ(m->scale.initial, 0U);
  EXPECT_FALSE(m->scale.up);
  EXPECT_FALSE(m->scale.down);
}

TEST(MappingScale, ButtonLevelsDownAndInitial) {
  const auto m = load_text(kScaleHead + "scale: {button: guide, down: back, levels: [0.25, 0.5, 1.0], initial: 0.5}\n" +
                           kBindings);
  EXPECT_EQ(m->scale.levels, (std::vector{0.25, 0.5, 1.0}));
  EXPECT_EQ(m->scale.initial, 1U);
  ASSERT_TRUE(m->scale.up);
  EXPECT_EQ(m->scale.up->key, *input::parse_button_name("guide"));
  EXPECT_EQ(m->scale.up->pos.line, 3);
  ASSERT_TRUE(m->scale.down);
  EXPECT_EQ(m->scale.down->key, *input::parse_button_name("back"));
}

TEST(MappingScale, StartsAtTheSlowestUnlessToldAndOneLevelNeedsNoButton) {
  EXPECT_EQ(load_text(kScaleHead + "scale: {button: guide, levels: [0.3, 0.6, 1]}\n")->scale.initial, 0U);
  const auto capped = load_text(kScaleHead + "scale: {levels: [0.5]}\n");
  EXPECT_EQ(capped->scale.levels, std::vector{0.5});
  EXPECT_FALSE(capped->scale.up);
}

TEST(MappingScale, ABaseFilesScaleCarriesOverUnlessSetAgain) {
  const testing::TempDir dir;
  dir.write("base.yaml", "deadman: leftshoulder\nscale: {button: guide, levels: [0.5, 1]}\n");
  EXPECT_EQ(load_mapping(dir.write("a.yaml", "robot: HD1\nextends: base.yaml\n"))->scale.levels,
            (std::vector{0.5, 1.0}));
  const auto b = load_mapping(dir.write("b.yaml", "robot: HD1\nextends: base.yaml\nscale: {levels: [0.75]}\n"));
  EXPECT_EQ(b->scale.levels, std::vector{0.75});
  EXPECT_FALSE(b->scale.up);
}

struct BadScale {
  const char* what;
  std::string text;
  int line;
  int column;
  const char* message;
};

void PrintTo(const BadScale& c, std::ostream* os) { *os << c.what; }

class MappingScaleErrors : public ::testing::TestWithParam<BadScale> {};

TEST_P(MappingScaleErrors, NameFileLineAndColumn) {
  const auto& c = GetParam();
  testing::expect_input_error([&] { load_text(c.text); }, "m.yaml", c.line, c.column, c.message, c.text);
}

const std::string kLayer =
    "layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n      - signal: gripper_open\n        button: a\n";

INSTANTIATE_TEST_SUITE_P(
    Catalogue, MappingScaleErrors,
    ::testing::Values(
        BadScale{"not a map", kScaleHead + "scale: 0.5\n", 3, 8, "scale"},
        BadScale{"unknown key", kScaleHead + "scale: {button: guide, level: [0.5, 1]}\n", 3, 24,
                 "unknown key 'level' in scale (expected button, down, levels, initial)"},
        BadScale{"no levels", kScaleHead + "scale: {button: guide}\n", 3, 8, "scale needs 'levels'"},
        BadScale{"levels not a list", kScaleHead + "scale: {button: guide, levels: 0.5}\n", 3, 32, "levels"},
        BadScale{"no level", kScaleHead + "scale: {levels: []}\n", 3, 17,
                 "levels lists at least one fraction of full speed"},
        BadScale{"six levels", kScaleHead + "scale: {button: y, levels: [0.1, 0.2, 0.3, 0.4, 0.5, 0.6]}\n", 3, 28,
                 "at most 5 levels (a change is counted out in as many rumble pulses)"},
        BadScale{"level 0", kScaleHead + "scale: {button: y, levels: [0, 1]}\n", 3, 29,
                 "a level is a fraction of full speed above 0, not 0"},
        BadScale{"level above 1", kScaleHead + "scale: {button: y, levels: [0.5, 1.5]}\n", 3, 34,
                 "a level 1.5 is out of range 0..1"},
        BadScale{"level negative", kScaleHead + "scale: {button: y, levels: [-0.5, 1]}\n", 3, 29,
                 "a level -0.5 is out of range 0..1"},
        BadScale{"level not a number", kScaleHead + "scale: {button: y, levels: [half, 1]}\n", 3, 29,
                 "a level 'half' is not a number"},
        BadScale{"level as a percentage", kScaleHead + "scale: {button: y, levels: [25%, 100%]}\n", 3, 29,
                 "a level '25%' is not a number"},
        BadScale{"levels not increasing", kScaleHead + "scale: {button: y, levels: [0.5, 0.25, 1]}\n", 3, 34,
                 "levels go from the slowest to the fastest: 0.25 is not above the one before it"},
        BadScale{"level twice", kScaleHead + "scale: {button: y, levels: [0.5, 0.5]}\n", 3, 34,
                 "0.5 is not above the one before it"},
        BadScale{"several levels, no button", kScaleHead + "scale: {levels: [0.5, 1]}\n", 3, 8,
                 "scale with more than one level needs 'button'"},
        BadScale{"one level and a button", kScaleHead + "scale: {button: y, levels: [0.5]}\n", 3, 17,
                 "scale has one level: there is nothing for 'button' to step to"},
        BadScale{"down without button", kScaleHead + "scale: {down: y, levels: [0.5]}\n", 3, 8,
                 "scale has 'down' but no 'button' to step up"},
        BadScale{"unknown button", kScaleHead + "scale: {button: guid, levels: [0.5, 1]}\n", 3, 17,
                 "unknown button 'guid'"},
        BadScale{"a stick as button", kScaleHead + "scale: {button: lefty, levels: [0.5, 1]}\n", 3, 17,
                 "unknown button 'lefty'"},
        BadScale{"initial not a level", kScaleHead + "scale: {button: y, levels: [0.5, 1], initial: 0.75}\n", 3, 47,
                 "initial 0.75 is not one of the levels"},
        BadScale{"initial as an index", kScaleHead + "scale: {button: y, levels: [0.5, 1], initial: 2}\n", 3, 47,
                 "initial 2 is out of range 0..1"},
        BadScale{"down is button", kScaleHead + "scale: {button: y, down: y, levels: [0.5, 1]}\n", 3, 26,
                 "'down' must be a different button from 'button'"},
        BadScale{"button is the deadman", kScaleHead + "scale: {button: leftshoulder, levels: [0.5, 1]}\n", 3, 17,
                 "'leftshoulder' is the deadman or switches a layer (line 2); it cannot also step the speed level"},
        BadScale{"button is a layer key", kScaleHead + "scale: {button: rightshoulder, levels: [0.5, 1]}\n" + kLayer, 3,
                 17, "'rightshoulder' is the deadman or switches a layer (line 6)"},
        BadScale{"button bound in the base layer", kScaleHead + "scale: {button: x, levels: [0.5, 1]}\n" + kBindings, 3,
                 17, "'x' steps the speed level in every layer; it is also bound at line 8"},
        BadScale{"down bound in a layer", kScaleHead + "scale: {button: y, down: a, levels: [0.5, 1]}\n" + kLayer, 3,
                 26, "'a' steps the speed level in every layer; it is also bound at line 9"},
        BadScale{
            "button arms a weapon",
            kScaleHead +
                "scale: {button: y, levels: [0.5, 1]}\nbindings:\n  - signal: weapon_1\n    button: b\n    arm: y\n",
            3, 17, "'y' steps the speed level in every layer; it also arms a weapon at line 7"},
        BadScale{"feedback pulses for a speed level", kScaleHead + "feedback:\n  speed_level: {pulses: 2}\n", 4, 25,
                 "speed_level plays one pulse per level (level 3: three pulses); it takes no 'pulses'"}),
    [](const auto& param_info) {
      std::string name = param_info.param.what;
      for (auto& ch : name) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      return name;
    });

TEST(MappingScale, FeedbackForASpeedLevelIsOverridable) {
  const auto m = load_text(kScaleHead + "feedback:\n  speed_level: {high: 0.2, ms: 50, led: [0, 0, 255]}\n");
  const auto& p = m->feedback[FeedbackEvent::kSpeedLevel];
  ASSERT_TRUE(p);
  EXPECT_EQ(p->high, 0.2);
  EXPECT_EQ(p->ms, 50);
  EXPECT_EQ(p->low, default_feedback_pattern(FeedbackEvent::kSpeedLevel).low);
  EXPECT_FALSE(load_text(kScaleHead + "feedback:\n  speed_level: off\n")->feedback[FeedbackEvent::kSpeedLevel]);
}

TEST(MappingScale, ValidateChecksAHandBuiltScaleToo) {
  Mapping m;
  m.robot = "HD1";
  m.deadman = InputUse{*input::parse_button_name("leftshoulder"), {}};
  m.scale.levels = {0.5, 0.25};
  m.scale.up = InputUse{*input::parse_button_name("y"), {}};
  EXPECT_NE(testing::input_error_text([&] { validate(m); }).find("speed levels go from the slowest to the fastest"),
            std::string::npos);
  m.scale.levels = {0.25, 0.5};
  m.scale.initial = 2;
  EXPECT_NE(testing::input_error_text([&] { validate(m); }).find("initial speed level is out of range"),
            std::string::npos);
  m.scale.initial = 1;
  m.scale.up.reset();
  EXPECT_NE(testing::input_error_text([&] { validate(m); }).find("exactly when it has more than one level"),
            std::string::npos);
}

}  // namespace
}  // namespace andros::mapping

// A mapping's `feedback:` section: defaults, overrides, off, extends, errors.
#include <gtest/gtest.h>

#include "andros/mapping/loader.hpp"
#include "support/input_error.hpp"
#include "support/temp_dir.hpp"

namespace andros::mapping {
namespace {

using E = FeedbackEvent;
using Rgb = std::array<std::uint8_t, 3>;

const std::string kFeedbackHead = "robot: HD1\ndeadman: leftshoulder\n";  // feedback starts on line 3

Mapping load_feedback_text(const std::string& text, const std::string& base = "") {
  testing::TempDir dir;
  if (!base.empty()) dir.write("base.yaml", base);
  return *load_mapping(dir.write("m.yaml", text));
}

TEST(FeedbackLoader, WithoutTheSectionEveryEventHasItsDefaultPattern) {
  const auto m = load_feedback_text(kFeedbackHead);
  for (std::size_t i = 0; i < kFeedbackEventCount; ++i) {
    const auto e = static_cast<E>(i);
    ASSERT_TRUE(m.feedback[e].has_value()) << feedback_event_name(e);
    EXPECT_EQ(*m.feedback[e], default_feedback_pattern(e));
  }
}

TEST(FeedbackLoader, TheDefaultsAreDistinctAndShort) {
  for (std::size_t i = 0; i < kFeedbackEventCount; ++i) {
    const auto e = static_cast<E>(i);
    const auto a = default_feedback_pattern(e);
    // A speed level plays one pulse per level, up to the most levels a mapping may have.
    const int pulses = e == E::kSpeedLevel ? static_cast<int>(kMaxSpeedLevels) : a.pulses;
    EXPECT_LE(a.ms * (2 * pulses - 1), 600) << feedback_event_name(e);
    // Each light says a state; a speed level changes none (the light stays as the state set it).
    EXPECT_EQ(a.led.has_value(), e != E::kSpeedLevel) << feedback_event_name(e);
    for (std::size_t j = i + 1; j < kFeedbackEventCount; ++j) {
      const auto b = default_feedback_pattern(static_cast<E>(j));
      EXPECT_NE(a.led, b.led) << i << " " << j;
      EXPECT_FALSE(a.low == b.low && a.high == b.high && a.pulses == b.pulses) << i << " " << j;
    }
  }
}

TEST(FeedbackLoader, OffSwitchesEveryEventOff) {
  const auto m = load_feedback_text(kFeedbackHead + "feedback: off\n");
  for (const auto& p : m.feedback.patterns) EXPECT_FALSE(p.has_value());
}

TEST(FeedbackLoader, KeysGivenReplaceTheDefaultsAndTheRestStay) {
  const auto m = load_feedback_text(kFeedbackHead +
                                    "feedback:\n"
                                    "  enabled: {high: 0.25, ms: 50, led: [1, 2, 3]}\n"
                                    "  link_lost: off\n"
                                    "  disabled: {pulses: 2, led: off}\n"
                                    "  weapons_on: {ms: 300}\n"
                                    "  weapons_off: off\n");
  auto enabled = default_feedback_pattern(E::kEnabled);
  enabled.high = 0.25;
  enabled.ms = 50;
  enabled.led = Rgb{1, 2, 3};
  EXPECT_EQ(m.feedback[E::kEnabled], enabled);
  EXPECT_FALSE(m.feedback[E::kLinkLost].has_value());
  auto disabled = default_feedback_pattern(E::kDisabled);
  disabled.pulses = 2;
  disabled.led.reset();
  EXPECT_EQ(m.feedback[E::kDisabled], disabled);
  EXPECT_EQ(m.feedback[E::kDeadmanRefused], default_feedback_pattern(E::kDeadmanRefused));
  auto weapons_on = default_feedback_pattern(E::kWeaponsOn);
  weapons_on.ms = 300;
  EXPECT_EQ(m.feedback[E::kWeaponsOn], weapons_on);
  EXPECT_FALSE(m.feedback[E::kWeaponsOff].has_value());
}

TEST(FeedbackLoader, AFileThatExtendsKeepsTheBasesFeedbackAndMayChangeIt) {
  const std::string base = "feedback:\n  enabled: {low: 0.5}\n  link_lost: off\n";
  const auto kept = load_feedback_text(kFeedbackHead + "extends: base.yaml\n", base);
  EXPECT_EQ(kept.feedback[E::kEnabled]->low, 0.5);
  EXPECT_FALSE(kept.feedback[E::kLinkLost].has_value());
  // An event the base switched off comes back from its default.
  const auto changed =
      load_feedback_text(kFeedbackHead + "extends: base.yaml\nfeedback:\n  link_lost: {ms: 300}\n", base);
  auto link_lost = default_feedback_pattern(E::kLinkLost);
  link_lost.ms = 300;
  EXPECT_EQ(changed.feedback[E::kLinkLost], link_lost);
  EXPECT_EQ(changed.feedback[E::kEnabled]->low, 0.5);
  const auto off = load_feedback_text(kFeedbackHead + "extends: base.yaml\nfeedback: off\n", base);
  for (const auto& p : off.feedback.patterns) EXPECT_FALSE(p.has_value());
}

struct BadFeedback {
  const char* what;
  std::string section;  // from line 3
  int line;
  int column;
  const char* message;
};

void PrintTo(const BadFeedback& c, std::ostream* os) { *os << c.what; }

class FeedbackErrors : public ::testing::TestWithParam<BadFeedback> {};

TEST_P(FeedbackErrors, NameFileLineAndColumn) {
  const auto& c = GetParam();
  testing::expect_input_error([&] { load_feedback_text(kFeedbackHead + c.section); }, "m.yaml", c.line, c.column,
                              c.message, c.section);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, FeedbackErrors,
    ::testing::Values(
        BadFeedback{"unknown event", "feedback:\n  enabeld: off\n", 4, 3, "unknown key 'enabeld' in feedback"},
        BadFeedback{"unknown pattern key", "feedback:\n  enabled: {rumble: 1}\n", 4, 13,
                    "unknown key 'rumble' in a feedback pattern (expected low, high, ms, pulses, led)"},
        BadFeedback{"on is not a value", "feedback: on\n", 3, 11, "feedback is 'off' or a map"},
        BadFeedback{"strength above 1", "feedback:\n  enabled: {low: 1.5}\n", 4, 18, "out of range"},
        BadFeedback{"pulse too long", "feedback:\n  enabled: {ms: 1001}\n", 4, 17, "out of range 1..1000"},
        BadFeedback{"too many pulses", "feedback:\n  enabled: {pulses: 6}\n", 4, 21, "out of range 1..5"},
        BadFeedback{"led of two", "feedback:\n  enabled: {led: [1, 2]}\n", 4, 18, "led is [RED, GREEN, BLUE]"},
        BadFeedback{"led channel", "feedback:\n  enabled: {led: [1, 2, 256]}\n", 4, 25, "out of range 0..255"},
        BadFeedback{"event given twice", "feedback:\n  enabled: off\n  enabled: off\n", 5, 3, "given twice"}));

}  // namespace
}  // namespace andros::mapping

// Which feedback events two successive statuses show, and which one plays.
#include <gtest/gtest.h>

#include "andros/run/feedback.hpp"

namespace andros::run {
namespace {

using mapping::DeadmanState;
using E = mapping::FeedbackEvent;
using Events = std::vector<E>;

constexpr FeedbackStatus kIdle{false, DeadmanState::kNoPad, false, true};
constexpr FeedbackStatus kConnected{true, DeadmanState::kReleased, false, true};
constexpr FeedbackStatus kRefused{true, DeadmanState::kHeldNotFresh, false, true};
constexpr FeedbackStatus kEnabled{true, DeadmanState::kFreshHold, true, true};

FeedbackStatus link_down(FeedbackStatus s) {
  s.link_up = false;
  return s;
}

FeedbackStatus weapons(FeedbackStatus s) {
  s.weapons_mode = true;
  return s;
}

FeedbackStatus level(FeedbackStatus s, std::size_t index) {
  s.speed_level = index;
  return s;
}

TEST(FeedbackEvents, EachChangeGivesItsEvent) {
  EXPECT_EQ(feedback_events(kIdle, kConnected), Events{E::kControllerBack});
  EXPECT_EQ(feedback_events(kConnected, kEnabled), Events{E::kEnabled});
  EXPECT_EQ(feedback_events(kEnabled, kConnected), Events{E::kDisabled});
  EXPECT_EQ(feedback_events(kConnected, kRefused), Events{E::kDeadmanRefused});
  EXPECT_EQ(feedback_events(kEnabled, link_down(kEnabled)), Events{E::kLinkLost});
}

TEST(FeedbackEvents, AStopAndATimeoutHaveTheirOwn) {
  // Stopped by the operator from driving: the stop first, before "disabled".
  TickReport r;
  r.connected = true;
  r.link.state = link::LinkState::kUp;
  r.link.far_end_reading = true;
  r.engine.deadman = DeadmanState::kFreshHold;
  r.state = OpState::kStopped;
  const auto stopped = feedback_status(r);
  EXPECT_TRUE(stopped.stopped);
  EXPECT_EQ(feedback_events(kEnabled, stopped).front(), E::kStopped);
  EXPECT_TRUE(feedback_events(stopped, stopped).empty());
  // The timeout: its own event, before "disabled".
  r.state = OpState::kNotEnabled;
  r.engine.deadman = DeadmanState::kTimedOut;
  EXPECT_EQ(feedback_events(kEnabled, feedback_status(r)), (Events{E::kTimedOut, E::kDisabled}));
  // Their patterns are the stop's red and a light of their own.
  EXPECT_EQ(mapping::default_feedback_pattern(E::kStopped).led, (std::array<std::uint8_t, 3>{255, 0, 0}));
  // A reset: a rumble of its own, once, when the stop ends by it (not by a suspend).
  r.engine.deadman = DeadmanState::kReleased;
  r.reset_by = StopBy::kSupervisor;
  const auto reset = feedback_status(r);
  EXPECT_EQ(feedback_events(stopped, reset), Events{E::kStopReset});
  EXPECT_TRUE(feedback_events(reset, reset).empty());
  r.reset_by.reset();
  r.state = OpState::kSuspended;
  EXPECT_TRUE(feedback_events(stopped, feedback_status(r)).empty());
}

TEST(FeedbackStatus, EnabledIsTheOperatingStatesNotTheEngines) {
  // The engine saw a fresh press, but nothing reaches the vehicle: the light stays off.
  TickReport r;
  r.connected = true;
  r.engine.deadman = DeadmanState::kFreshHold;
  r.state = OpState::kNoLink;
  EXPECT_FALSE(feedback_status(r).enabled);
  EXPECT_EQ(feedback_events(kConnected, feedback_status(r)), Events{E::kLinkLost});  // no kEnabled
  r.state = OpState::kEnabled;
  EXPECT_TRUE(feedback_status(r).enabled);
}

TEST(FeedbackEvents, NoChangeNoEvent) {
  for (const auto& s : {kIdle, kConnected, kRefused, kEnabled, link_down(kEnabled)}) {
    EXPECT_TRUE(feedback_events(s, s).empty());
  }
  // The link coming back, and a controller lost, tell nothing (a lost one cannot be told).
  EXPECT_TRUE(feedback_events(link_down(kConnected), kConnected).empty());
  EXPECT_TRUE(feedback_events(kConnected, kIdle).empty());
  EXPECT_TRUE(feedback_events(kEnabled, kIdle).empty());
  EXPECT_TRUE(feedback_events(kRefused, kConnected).empty());
}

TEST(FeedbackEvents, SeveralAtOnceComeMostImportantFirst) {
  // Plugged in with the deadman held (or held since start-up: stuck).
  EXPECT_EQ(feedback_events(kIdle, kRefused), (Events{E::kDeadmanRefused, E::kControllerBack}));
  // Resumed after a pause with the deadman still held.
  EXPECT_EQ(feedback_events(kEnabled, kRefused), (Events{E::kDeadmanRefused, E::kDisabled}));
  EXPECT_EQ(feedback_events(kEnabled, link_down(kConnected)), (Events{E::kLinkLost, E::kDisabled}));
  EXPECT_EQ(feedback_events(link_down(kIdle), kEnabled), (Events{E::kEnabled, E::kControllerBack}));
}

TEST(FeedbackEvents, AWeaponsModeIsToldWhenItBeginsAndEnds) {
  EXPECT_EQ(feedback_events(kEnabled, weapons(kEnabled)), Events{E::kWeaponsOn});
  EXPECT_EQ(feedback_events(weapons(kEnabled), kEnabled), Events{E::kWeaponsOff});
  EXPECT_TRUE(feedback_events(weapons(kEnabled), weapons(kEnabled)).empty());
  // Enabled straight into a weapons layer: the weapons pattern, not the plain one.
  EXPECT_EQ(feedback_events(kConnected, weapons(kEnabled)), (Events{E::kWeaponsOn, E::kEnabled}));
  // The deadman released in one: "disabled" says it all; a lost controller cannot be told.
  EXPECT_EQ(feedback_events(weapons(kEnabled), kConnected), (Events{E::kDisabled, E::kWeaponsOff}));
  EXPECT_TRUE(feedback_events(weapons(kEnabled), kIdle).empty());
}

class RecordingInput final : public input::InputSource {
 public:
  void pump(input::TickInput& /*input*/, std::int64_t /*now_ms*/) override {}
  [[nodiscard]] bool finished(std::int64_t /*now_ms*/) const override { return false; }
  void feedback(const input::FeedbackPattern& pattern) override { played.push_back(pattern); }
  std::vector<input::FeedbackPattern> played;
};

TEST(FeedbackNotifier, PlaysTheFirstEventThatHasAPattern) {
  RecordingInput input;
  auto table = mapping::default_feedback();
  FeedbackNotifier notifier(table, input);
  EXPECT_EQ(notifier.observe(kRefused), E::kDeadmanRefused);
  ASSERT_EQ(input.played.size(), 1U);
  EXPECT_EQ(input.played[0], *table[E::kDeadmanRefused]);
  EXPECT_EQ(notifier.observe(kRefused), std::nullopt);
  EXPECT_EQ(input.played.size(), 1U);

  table[E::kDeadmanRefused].reset();
  FeedbackNotifier without_refused(table, input);
  EXPECT_EQ(without_refused.observe(kRefused), E::kControllerBack);
  EXPECT_EQ(input.played.back(), *table[E::kControllerBack]);
}

TEST(FeedbackNotifier, AWeaponsModePlaysItsOwnPatterns) {
  RecordingInput input;
  const auto table = mapping::default_feedback();
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled);
  EXPECT_EQ(notifier.observe(weapons(kEnabled)), E::kWeaponsOn);
  EXPECT_EQ(input.played.back(), *table[E::kWeaponsOn]);
  EXPECT_EQ(notifier.observe(kEnabled), E::kWeaponsOff);
  EXPECT_EQ(input.played.back(), *table[E::kWeaponsOff]);
  EXPECT_NE(*table[E::kWeaponsOn], *table[E::kEnabled]);
  EXPECT_NE(*table[E::kWeaponsOff], *table[E::kEnabled]);
}

TEST(FeedbackEvents, ASpeedLevelChangeIsToldWhileThePadStays) {
  EXPECT_EQ(feedback_events(kEnabled, level(kEnabled, 1)), Events{E::kSpeedLevel});
  EXPECT_EQ(feedback_events(level(kEnabled, 2), kEnabled),
            Events{E::kSpeedLevel});  // up past the fastest, or a restart
  EXPECT_EQ(feedback_events(level(kEnabled, 2), level(kConnected, 0)), (Events{E::kDisabled, E::kSpeedLevel}));
  EXPECT_TRUE(feedback_events(level(kEnabled, 2), kIdle).empty());                      // a lost pad: told nothing
  EXPECT_EQ(feedback_events(level(kIdle, 2), kConnected), Events{E::kControllerBack});  // a new pad: its own event
}

TEST(FeedbackNotifier, ASpeedLevelIsCountedOutInPulses) {
  RecordingInput input;
  auto table = mapping::default_feedback();
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled);
  for (const std::size_t index : {1U, 2U, 0U}) {
    EXPECT_EQ(notifier.observe(level(kEnabled, index)), E::kSpeedLevel);
    auto expected = *table[E::kSpeedLevel];
    expected.pulses = static_cast<int>(index) + 1;  // level n: n pulses
    EXPECT_EQ(input.played.back(), expected);
  }
  EXPECT_FALSE(table[E::kSpeedLevel]->led);  // the light keeps saying "enabled"
  table[E::kSpeedLevel].reset();
  FeedbackNotifier off(table, input);
  off.observe(kEnabled);
  EXPECT_EQ(off.observe(level(kEnabled, 1)), std::nullopt);
}

// Issue 19, finding 7: after a stop the pad's light is not green, whatever the
// mapping says of the event that ends the enabled state.
TEST(FeedbackNotifier, TheLightOfTheEnabledStateEndsWithIt) {
  const auto orange = mapping::default_feedback_pattern(E::kDisabled).led;
  for (const auto& why : {"disabled: {led: off}", "disabled: off", "link_lost: {led: off}"}) {
    SCOPED_TRACE(why);
    auto table = mapping::default_feedback();
    if (why == std::string("disabled: {led: off}")) table[E::kDisabled]->led.reset();
    if (why == std::string("disabled: off")) table[E::kDisabled].reset();
    if (why == std::string("link_lost: {led: off}")) table[E::kLinkLost]->led.reset();
    RecordingInput input;
    FeedbackNotifier notifier(table, input);
    notifier.observe(kConnected);
    notifier.observe(kEnabled);
    ASSERT_EQ(input.played.back().led, table[E::kEnabled]->led);  // green
    notifier.observe(why == std::string("link_lost: {led: off}") ? link_down(kConnected) : kConnected);
    ASSERT_FALSE(input.played.empty());
    EXPECT_EQ(input.played.back().led, orange);
    // Stopped already: nothing more to say while it stays so.
    const auto count = input.played.size();
    notifier.observe(kConnected);
    EXPECT_EQ(input.played.size(), count);
  }
  // A stop from a weapons mode (its yellow) too.
  auto table = mapping::default_feedback();
  table[E::kDisabled].reset();
  RecordingInput input;
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled);
  notifier.observe(weapons(kEnabled));
  notifier.observe(kConnected);
  EXPECT_EQ(input.played.back().led, orange);
}

TEST(FeedbackNotifier, AllOffPlaysNothing) {
  RecordingInput input;
  FeedbackNotifier notifier(mapping::FeedbackTable{}, input);
  for (const auto& s : {kRefused, kConnected, kEnabled, link_down(kEnabled), kConnected, kIdle}) {
    EXPECT_EQ(notifier.observe(s), std::nullopt);
  }
  EXPECT_TRUE(input.played.empty());
}

}  // namespace
}  // namespace andros::run

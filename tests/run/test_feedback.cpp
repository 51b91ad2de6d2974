// Which feedback events a tick brings (the machine's transitions, the pad's
// and the engine's facts that changed), and which one plays.
#include <gtest/gtest.h>

#include "andros/base/text_file.hpp"
#include "andros/input/script_player.hpp"
#include "andros/mapping/loader.hpp"
#include "andros/run/feedback.hpp"
#include "andros/run/replay.hpp"

namespace andros::run {
namespace {

using mapping::DeadmanState;
using E = mapping::FeedbackEvent;
using S = OpState;
using Events = std::vector<E>;
using Steps = std::vector<ReportedTransition>;

constexpr FeedbackStatus kIdle{false, DeadmanState::kNoPad, false};
constexpr FeedbackStatus kConnected{true, DeadmanState::kReleased, false};
constexpr FeedbackStatus kRefused{true, DeadmanState::kHeldNotFresh, false};
constexpr FeedbackStatus kEnabled{true, DeadmanState::kFreshHold, true};

ReportedTransition step(S from, OpEvent event, S to, Who who = Who::kOperator) {
  return {Transition{.from = from, .event = event, .to = to, .who = who}, {}};
}
const auto kEnable = step(S::kNotEnabled, OpEvent::kFreshPress, S::kEnabled);
const auto kRelease = step(S::kEnabled, OpEvent::kRelease, S::kNotEnabled);
const auto kLost = step(S::kEnabled, OpEvent::kControllerDown, S::kNoController);
ReportedTransition link_lost(S from) { return step(from, OpEvent::kLinkDown, S::kNoLink, Who::kLink); }

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
  EXPECT_EQ(feedback_events(kConnected, kEnabled, {kEnable}), Events{E::kEnabled});
  EXPECT_EQ(feedback_events(kEnabled, kConnected, {kRelease}), Events{E::kDisabled});
  EXPECT_EQ(feedback_events(kConnected, kRefused), Events{E::kDeadmanRefused});
  EXPECT_EQ(feedback_events(kConnected, kConnected, {link_lost(S::kNotEnabled)}), Events{E::kLinkLost});
}

TEST(FeedbackEvents, AStopAndATimeoutHaveTheirOwn) {
  // Stopped by the operator from driving: the stop first, before "disabled".
  const FeedbackStatus stopped{true, DeadmanState::kFreshHold, false};
  const auto stop = step(S::kEnabled, OpEvent::kOperatorStop, S::kStopped);
  EXPECT_EQ(feedback_events(kEnabled, stopped, {stop}), (Events{E::kStopped, E::kDisabled}));
  EXPECT_TRUE(feedback_events(stopped, stopped).empty());
  // Pressed again while stopped: no second "stopped".
  auto again = step(S::kStopped, OpEvent::kOperatorStop, S::kStopped);
  again.transition.again = true;
  EXPECT_TRUE(feedback_events(stopped, stopped, {again}).empty());
  // The timeout: its own event, before "disabled".
  const FeedbackStatus timed_out{true, DeadmanState::kTimedOut, false};
  EXPECT_EQ(
      feedback_events(kEnabled, timed_out, {step(S::kEnabled, OpEvent::kEnableTimeout, S::kNotEnabled, Who::kTimeout)}),
      (Events{E::kTimedOut, E::kDisabled}));
  // Their patterns are the stop's red and a light of their own.
  EXPECT_EQ(mapping::default_feedback_pattern(E::kStopped).led, (std::array<std::uint8_t, 3>{255, 0, 0}));
  // A reset: a rumble of its own, once, when the stop ends by it (not by a suspend).
  const auto reset = step(S::kStopped, OpEvent::kSupervisorReset, S::kNotEnabled, Who::kSupervisor);
  EXPECT_EQ(feedback_events(stopped, kConnected, {reset}), Events{E::kStopReset});
  EXPECT_TRUE(feedback_events(kConnected, kConnected).empty());
  EXPECT_TRUE(feedback_events(stopped, kConnected, {step(S::kStopped, OpEvent::kSuspend, S::kSuspended, Who::kRequest)})
                  .empty());
}

TEST(FeedbackStatus, EnabledIsTheOperatingStatesNotTheEngines) {
  // The engine saw a fresh press, but nothing reaches the vehicle: the light stays off.
  TickReport r;
  r.connected = true;
  r.engine.deadman = DeadmanState::kFreshHold;
  r.state = OpState::kNoLink;
  EXPECT_FALSE(feedback_status(r).enabled);
  EXPECT_EQ(feedback_events(kConnected, feedback_status(r), {link_lost(S::kNotEnabled)}), Events{E::kLinkLost});
  r.state = OpState::kEnabled;
  EXPECT_TRUE(feedback_status(r).enabled);
}

TEST(FeedbackEvents, NoChangeNoEvent) {
  for (const auto& s : {kIdle, kConnected, kRefused, kEnabled}) {
    EXPECT_TRUE(feedback_events(s, s).empty());
  }
  // The link coming back, and a controller lost, tell nothing (a lost one cannot be told).
  EXPECT_TRUE(feedback_events(kConnected, kConnected, {step(S::kNoLink, OpEvent::kLinkUp, S::kNotEnabled, Who::kLink)})
                  .empty());
  EXPECT_TRUE(feedback_events(kConnected, kIdle).empty());
  EXPECT_TRUE(feedback_events(kEnabled, kIdle, {kLost}).empty());
  EXPECT_TRUE(feedback_events(kRefused, kConnected).empty());
}

TEST(FeedbackEvents, SeveralAtOnceComeMostImportantFirst) {
  // Plugged in with the deadman held (or held since start-up: stuck).
  EXPECT_EQ(feedback_events(kIdle, kRefused), (Events{E::kDeadmanRefused, E::kControllerBack}));
  // Resumed after a pause with the deadman still held.
  EXPECT_EQ(feedback_events(kEnabled, kRefused, {step(S::kEnabled, OpEvent::kSuspend, S::kSuspended, Who::kRequest)}),
            (Events{E::kDeadmanRefused, E::kDisabled}));
  EXPECT_EQ(feedback_events(kEnabled, kConnected, {link_lost(S::kEnabled)}), (Events{E::kLinkLost, E::kDisabled}));
  EXPECT_EQ(feedback_events(kIdle, kEnabled, {kEnable}), (Events{E::kEnabled, E::kControllerBack}));
}

// Issue 36, item 4: the feedback reacts to what the machine did, not to two
// reports: a link lost and back within one tick (a cable pulled out and in
// between two frames) ends driving, and the pad says why (before: "disabled").
TEST(FeedbackEvents, ALinkLostAndBackWithinATickIsTold) {
  TextReader in("0 connect Pad\n80 button leftshoulder 1\n200 link down\n200 link up\n400 end\n", "s.events",
                kEventScriptLimits);
  input::ScriptPlayer player(in);
  std::vector<TickReport> reports;
  ReplayOptions options;
  options.observe = [&reports](const TickReport& r) { reports.push_back(r); };
  replay(player, mapping::Engine(mapping::load_mapping(ANDROS_TEST_DATA_DIR "/mappings/core.yaml"), options.engine),
         options, [](std::int64_t, const protocol::DataBytes&) {});
  std::vector<E> played;
  class Pad final : public input::InputSource {
   public:
    void pump(input::TickInput& /*input*/, std::int64_t /*now_ms*/) override {}
    [[nodiscard]] bool finished(std::int64_t /*now_ms*/) const override { return false; }
  } pad;
  FeedbackNotifier notifier(mapping::default_feedback(), pad);
  for (const auto& r : reports) {
    if (const auto e = notifier.observe(r)) played.push_back(*e);
  }
  // Then the deadman, held through it, is refused: a new link needs a fresh press.
  EXPECT_EQ(played, (Events{E::kControllerBack, E::kEnabled, E::kLinkLost, E::kDeadmanRefused}));
}

TEST(FeedbackEvents, AWeaponsModeIsToldWhenItBeginsAndEnds) {
  EXPECT_EQ(feedback_events(kEnabled, weapons(kEnabled)), Events{E::kWeaponsOn});
  EXPECT_EQ(feedback_events(weapons(kEnabled), kEnabled), Events{E::kWeaponsOff});
  EXPECT_TRUE(feedback_events(weapons(kEnabled), weapons(kEnabled)).empty());
  // Enabled straight into a weapons layer: the weapons pattern, not the plain one.
  EXPECT_EQ(feedback_events(kConnected, weapons(kEnabled), {kEnable}), (Events{E::kWeaponsOn, E::kEnabled}));
  // The deadman released in one: "disabled" says it all; a lost controller cannot be told.
  EXPECT_EQ(feedback_events(weapons(kEnabled), kConnected, {kRelease}), (Events{E::kDisabled, E::kWeaponsOff}));
  EXPECT_TRUE(feedback_events(weapons(kEnabled), kIdle, {kLost}).empty());
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
  EXPECT_EQ(notifier.observe(kRefused, {}), E::kDeadmanRefused);
  ASSERT_EQ(input.played.size(), 1U);
  EXPECT_EQ(input.played[0], *table[E::kDeadmanRefused]);
  EXPECT_EQ(notifier.observe(kRefused, {}), std::nullopt);
  EXPECT_EQ(input.played.size(), 1U);

  table[E::kDeadmanRefused].reset();
  FeedbackNotifier without_refused(table, input);
  EXPECT_EQ(without_refused.observe(kRefused, {}), E::kControllerBack);
  EXPECT_EQ(input.played.back(), *table[E::kControllerBack]);
}

TEST(FeedbackNotifier, AWeaponsModePlaysItsOwnPatterns) {
  RecordingInput input;
  const auto table = mapping::default_feedback();
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled, {kEnable});
  EXPECT_EQ(notifier.observe(weapons(kEnabled), {}), E::kWeaponsOn);
  EXPECT_EQ(input.played.back(), *table[E::kWeaponsOn]);
  EXPECT_EQ(notifier.observe(kEnabled, {}), E::kWeaponsOff);
  EXPECT_EQ(input.played.back(), *table[E::kWeaponsOff]);
  EXPECT_NE(*table[E::kWeaponsOn], *table[E::kEnabled]);
  EXPECT_NE(*table[E::kWeaponsOff], *table[E::kEnabled]);
}

TEST(FeedbackEvents, ASpeedLevelChangeIsToldWhileThePadStays) {
  EXPECT_EQ(feedback_events(kEnabled, level(kEnabled, 1)), Events{E::kSpeedLevel});
  EXPECT_EQ(feedback_events(level(kEnabled, 2), kEnabled),
            Events{E::kSpeedLevel});  // up past the fastest, or a restart
  EXPECT_EQ(feedback_events(level(kEnabled, 2), level(kConnected, 0), {kRelease}),
            (Events{E::kDisabled, E::kSpeedLevel}));
  EXPECT_TRUE(feedback_events(level(kEnabled, 2), kIdle, {kLost}).empty());             // a lost pad: told nothing
  EXPECT_EQ(feedback_events(level(kIdle, 2), kConnected), Events{E::kControllerBack});  // a new pad: its own event
}

TEST(FeedbackNotifier, ASpeedLevelIsCountedOutInPulses) {
  RecordingInput input;
  auto table = mapping::default_feedback();
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled, {kEnable});
  for (const std::size_t index : {1U, 2U, 0U}) {
    EXPECT_EQ(notifier.observe(level(kEnabled, index), {}), E::kSpeedLevel);
    auto expected = *table[E::kSpeedLevel];
    expected.pulses = static_cast<int>(index) + 1;  // level n: n pulses
    EXPECT_EQ(input.played.back(), expected);
  }
  EXPECT_FALSE(table[E::kSpeedLevel]->led);  // the light keeps saying "enabled"
  table[E::kSpeedLevel].reset();
  FeedbackNotifier off(table, input);
  off.observe(kEnabled, {kEnable});
  EXPECT_EQ(off.observe(level(kEnabled, 1), {}), std::nullopt);
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
    notifier.observe(kConnected, {});
    notifier.observe(kEnabled, {kEnable});
    ASSERT_EQ(input.played.back().led, table[E::kEnabled]->led);  // green
    notifier.observe(kConnected, {why == std::string("link_lost: {led: off}") ? link_lost(S::kEnabled) : kRelease});
    ASSERT_FALSE(input.played.empty());
    EXPECT_EQ(input.played.back().led, orange);
    // Stopped already: nothing more to say while it stays so.
    const auto count = input.played.size();
    notifier.observe(kConnected, {});
    EXPECT_EQ(input.played.size(), count);
  }
  // A stop from a weapons mode (its yellow) too.
  auto table = mapping::default_feedback();
  table[E::kDisabled].reset();
  RecordingInput input;
  FeedbackNotifier notifier(table, input);
  notifier.observe(kEnabled, {kEnable});
  notifier.observe(weapons(kEnabled), {});
  notifier.observe(kConnected, {kRelease});
  EXPECT_EQ(input.played.back().led, orange);
}

TEST(FeedbackNotifier, AllOffPlaysNothing) {
  RecordingInput input;
  FeedbackNotifier notifier(mapping::FeedbackTable{}, input);
  const std::vector<std::pair<FeedbackStatus, Steps>> ticks{
      {kRefused, {}},   {kConnected, {}}, {kEnabled, {kEnable}}, {kConnected, {link_lost(S::kEnabled)}},
      {kConnected, {}}, {kIdle, {}}};
  for (const auto& [s, steps] : ticks) EXPECT_EQ(notifier.observe(s, steps), std::nullopt);
  EXPECT_TRUE(input.played.empty());
}

}  // namespace
}  // namespace andros::run

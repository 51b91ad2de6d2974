// The stop buttons and the reset gestures as facts (StopButtons through the
// engine; docs/safety-states.md, docs/mapping.md "Stop buttons"), written
// from ISO 13850's words: a stop button only ever stops, pressed or held, at
// any time; the reset is a gesture of its own (`stop_reset`, the
// supervisor's `reset`), made afresh while stopped and held stop_reset_hold
// with the deadman and every stop button on every pad released throughout,
// on the pad that makes it. Who may reset whose stop is the operating state's (tested there).
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

// The operator's stop on guide and its reset Back + Start; the supervisor's stop on x, its reset on y.
const std::string kStops =
    "robot: HD1\ndeadman: leftshoulder\nestop: guide\nstop_reset: [back, start]\n"
    "supervisor: {stop: x, reset: y}\nbindings:\n"
    "  - analog: drive\n    axis: lefty\n    invert: true\n";

/// Both controllers, enabled at 40, then the operator's stop at 50 (seen at 80), let go at 60, and the deadman at 90.
DrivenEngine stopped_at_80(input::InputState& in, const std::string& mapping = kStops) {
  DrivenEngine engine(mapping_from_yaml(mapping), EngineOptions{});
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 supervisor connect\n10 button leftshoulder 1\n");
  engine.step(in, 40);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  apply_script(in, "50 button guide 1\n60 button guide 0\n");
  engine.step(in, 80);
  EXPECT_TRUE(engine.status().stop_pressed.by_operator);
  EXPECT_FALSE(engine.status().stop_pressed.by_supervisor);
  apply_script(in, "90 button leftshoulder 0\n");
  return engine;
}

/// Every tick from `from` to `to` (both included) resets nothing.
void no_reset(DrivenEngine& engine, input::InputState& in, std::int64_t from, std::int64_t to) {
  for (std::int64_t t = from; t <= to; t += 40) ASSERT_FALSE(engine.stopped(in, t).reset) << t;
}

TEST(EngineStops, TheResetChordHeldForTheHoldResetsOnce) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  EXPECT_FALSE(engine.stopped(in, 120).reset);
  apply_script(in, "130 button back 1\n150 button start 1\n");
  const auto begun = engine.stopped(in, 160);  // the hold begins at this tick
  EXPECT_FALSE(begun.reset);
  ASSERT_TRUE(begun.hold);
  EXPECT_EQ(begun.hold->pad, input::Pad::kOperator);
  EXPECT_EQ(begun.hold->held_ms, 0);
  EXPECT_EQ(begun.hold->hold_ms, 2000);
  for (std::int64_t t = 200; t < 2160; t += 40) {
    const auto tick = engine.stopped(in, t);
    ASSERT_FALSE(tick.reset) << t;
    ASSERT_EQ(tick.hold->held_ms, t - 160) << t;  // the screen's progress
  }
  EXPECT_EQ(engine.stopped(in, 2160).reset, input::Pad::kOperator);  // 2 s after 160
  EXPECT_FALSE(engine.stopped(in, 2200).reset);                      // once: held on, it is not made afresh
  no_reset(engine, in, 2240, 6000);
}

TEST(EngineStops, HalfTheChordOrAStopButtonHeldNeverResets) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button back 1\n");  // one of the two
  no_reset(engine, in, 120, 3000);
  // The stop button itself, let go and held (the old gesture, issue 33): a stop, never a reset.
  apply_script(in, "3010 button back 0\n3020 button guide 1\n");
  const auto pressed = engine.stopped(in, 3040);
  EXPECT_TRUE(pressed.pressed.by_operator);
  EXPECT_FALSE(pressed.reset);
  no_reset(engine, in, 3080, 8000);
}

TEST(EngineStops, AnyStopButtonHeldOnAnyPadHoldsOffTheReset) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  // The supervisor holds its stop down: the operator's chord never completes.
  apply_script(in, "100 supervisor button x 1\n");
  const auto tick = engine.stopped(in, 120);
  EXPECT_TRUE(tick.pressed.by_supervisor);
  apply_script(in, "130 button back 1\n130 button start 1\n");
  no_reset(engine, in, 160, 6000);
  EXPECT_FALSE(engine.stopped(in, 6040).hold);
  // Nor the supervisor's own reset while its stop is held.
  apply_script(in, "6050 supervisor button y 1\n");
  no_reset(engine, in, 6080, 9000);
  // Its stop let go: the gestures held through it are not made afresh; let go and made again, they count.
  apply_script(in, "9010 supervisor button x 0\n");
  no_reset(engine, in, 9040, 12000);
  apply_script(in, "12010 supervisor button y 0\n12020 supervisor button y 1\n");
  EXPECT_FALSE(engine.stopped(in, 12040).reset);
  no_reset(engine, in, 12080, 14000);
  EXPECT_EQ(engine.stopped(in, 14040).reset, input::Pad::kSupervisor);
}

TEST(EngineStops, AStopPressedDuringTheHoldEndsItAndIsAStop) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button back 1\n130 button start 1\n");
  engine.stopped(in, 160);
  // A tap of the stop between two ticks: recorded as a press, and the hold is over.
  apply_script(in, "1000 button guide 1\n1010 button guide 0\n");
  const auto tapped = engine.stopped(in, 1040);
  EXPECT_TRUE(tapped.pressed.by_operator);
  EXPECT_FALSE(tapped.hold);
  no_reset(engine, in, 1080, 5000);  // the chord held through it must be let go and made again
  apply_script(in, "5010 button start 0\n5020 button start 1\n");
  engine.stopped(in, 5040);
  no_reset(engine, in, 5080, 7000);
  EXPECT_EQ(engine.stopped(in, 7040).reset, input::Pad::kOperator);
}

TEST(EngineStops, TheHoldTimeIsTheMappings) {
  input::InputState in;
  auto engine = stopped_at_80(in, kStops + "stop_reset_hold: 1\n");
  apply_script(in, "130 button back 1\n130 button start 1\n");
  engine.stopped(in, 160);
  EXPECT_FALSE(engine.stopped(in, 1120).reset);
  EXPECT_EQ(engine.stopped(in, 1160).reset, input::Pad::kOperator);
}

TEST(EngineStops, TheDeadmanOrALetGoDuringTheHoldEndsIt) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button back 1\n130 button start 1\n");
  engine.stopped(in, 160);
  // The deadman pressed and let go between two ticks: the hold is over.
  apply_script(in, "1000 button leftshoulder 1\n1010 button leftshoulder 0\n");
  EXPECT_FALSE(engine.stopped(in, 1040).reset);
  no_reset(engine, in, 1080, 4000);
  // Made with the deadman held: no hold begins.
  apply_script(in, "4010 button back 0\n4020 button leftshoulder 1\n4030 button back 1\n");
  no_reset(engine, in, 4040, 7000);
  // A button of it let go and pressed again between two ticks: the hold begins again there.
  apply_script(in, "7010 button leftshoulder 0\n7020 button back 0\n7030 button back 1\n");
  EXPECT_FALSE(engine.stopped(in, 7040).reset);                    // begun here
  apply_script(in, "8000 button start 0\n8010 button start 1\n");  // let go within the hold: again from 8040
  engine.stopped(in, 8040);
  EXPECT_FALSE(engine.stopped(in, 9080).reset);
  EXPECT_FALSE(engine.stopped(in, 10000).reset);
  EXPECT_EQ(engine.stopped(in, 10040).reset, input::Pad::kOperator);
}

TEST(EngineStops, TheSupervisorsStopAndResetAreTheSupervisors) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "100 supervisor button x 1\n110 supervisor button x 0\n");  // the supervisor presses its stop too
  const auto tick = engine.stopped(in, 120);
  EXPECT_TRUE(tick.pressed.by_supervisor);
  EXPECT_FALSE(tick.pressed.by_operator);
  apply_script(in, "130 supervisor button y 1\n");
  EXPECT_EQ(engine.stopped(in, 160).hold->pad, input::Pad::kSupervisor);
  EXPECT_FALSE(engine.stopped(in, 2120).reset);
  EXPECT_EQ(engine.stopped(in, 2160).reset, input::Pad::kSupervisor);
}

TEST(EngineStops, AStopButtonHeldIsAStopWheneverItIsRead) {
  input::InputState in;
  DrivenEngine engine(mapping_from_yaml(kStops), EngineOptions{});
  engine.step(in, 0);
  // Held since before start-up, never pressed in the run: still a stop.
  apply_script(in, "0 connect\n0 button guide 1\n0 supervisor connect\n");
  EXPECT_TRUE(engine.take_stop(in).by_operator);
  EXPECT_TRUE(engine.take_stop(in).by_operator);  // and again, while held
  apply_script(in, "50 button guide 0\n");
  EXPECT_FALSE(engine.take_stop(in));
  apply_script(in, "60 supervisor button x 1\n");
  EXPECT_TRUE(engine.take_stop(in).by_supervisor);
}

TEST(EngineStops, AControllerLostEndsItsHoldAndItsNewSessionCountsAfresh) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button back 1\n130 button start 1\n");
  engine.stopped(in, 160);
  apply_script(in, "300 disconnect\n");
  engine.stopped(in, 320);
  apply_script(in, "330 connect\n330 button back 1\n330 button start 1\n");  // held at connect: not made afresh
  no_reset(engine, in, 360, 3000);
  apply_script(in, "3010 button back 0\n3020 button back 1\n");
  engine.stopped(in, 3040);
  EXPECT_EQ(engine.stopped(in, 5040).reset, input::Pad::kOperator);
}

}  // namespace
}  // namespace andros::mapping

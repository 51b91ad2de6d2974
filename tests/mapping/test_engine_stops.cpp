// The stop buttons as facts (StopButtons through the engine): a stop pressed
// on either pad, and the reset hold (docs/safety-states.md, docs/mapping.md
// "Stop buttons"): the stop button released after the stop, then held for
// stop_reset_hold with the deadman released throughout, on the pad that
// holds it. Who may reset whose stop is the operating state's (tested there).
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

// The operator's stop on guide, the supervisor's on x of its own controller.
const std::string kStops =
    "robot: HD1\ndeadman: leftshoulder\nestop: guide\nsupervisor: {stop: x}\nbindings:\n"
    "  - analog: drive\n    axis: lefty\n    invert: true\n";

/// Both controllers, enabled at 40, then the operator's stop at 50 (seen at 80) and the deadman let go at 90.
DrivenEngine stopped_at_80(input::InputState& in, const std::string& mapping = kStops) {
  DrivenEngine engine(mapping_from_yaml(mapping), EngineOptions{});
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 supervisor connect\n10 button leftshoulder 1\n");
  engine.step(in, 40);
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  apply_script(in, "50 button guide 1\n");
  engine.step(in, 80);
  EXPECT_TRUE(engine.status().stop_pressed.by_operator);
  EXPECT_FALSE(engine.status().stop_pressed.by_supervisor);
  apply_script(in, "90 button leftshoulder 0\n");
  return engine;
}

TEST(EngineStops, AStopButtonHeldFromTheStopNeverResets) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  for (std::int64_t t = 120; t <= 6000; t += 40) {
    const auto tick = engine.stopped(in, t);
    ASSERT_FALSE(tick.reset) << t;
    ASSERT_FALSE(tick.pressed) << t;
  }
}

TEST(EngineStops, ReleasedAfterTheStopThenHeldForTheHoldResets) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  EXPECT_FALSE(engine.stopped(in, 120).reset);
  apply_script(in, "130 button guide 0\n");
  EXPECT_FALSE(engine.stopped(in, 160).reset);
  apply_script(in, "170 button guide 1\n");
  const auto begun = engine.stopped(in, 200);  // the hold begins at this tick
  EXPECT_TRUE(begun.pressed.by_operator);
  EXPECT_FALSE(begun.reset);
  for (std::int64_t t = 240; t < 2200; t += 40) ASSERT_FALSE(engine.stopped(in, t).reset) << t;
  EXPECT_EQ(engine.stopped(in, 2200).reset, input::Pad::kOperator);  // 2 s after 200
  EXPECT_FALSE(engine.stopped(in, 2240).reset);                      // once
  // Held on after the reset, it stops nothing until let go; pressed again, it stops.
  engine.restart(in);
  EXPECT_FALSE(engine.take_stop(in));
  apply_script(in, "2250 button guide 0\n2260 button guide 1\n");
  EXPECT_TRUE(engine.take_stop(in).by_operator);
}

TEST(EngineStops, TheHoldTimeIsTheMappings) {
  input::InputState in;
  auto engine = stopped_at_80(in, kStops + "stop_reset_hold: 1\n");
  apply_script(in, "130 button guide 0\n170 button guide 1\n");
  engine.stopped(in, 200);
  EXPECT_FALSE(engine.stopped(in, 1160).reset);
  EXPECT_EQ(engine.stopped(in, 1200).reset, input::Pad::kOperator);
}

TEST(EngineStops, TheDeadmanOrALetGoDuringTheHoldEndsIt) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button guide 0\n170 button guide 1\n");
  engine.stopped(in, 200);
  // The deadman pressed and let go between two ticks: the hold is over.
  apply_script(in, "1000 button leftshoulder 1\n1010 button leftshoulder 0\n");
  EXPECT_FALSE(engine.stopped(in, 1040).reset);
  for (std::int64_t t = 1080; t <= 4000; t += 40) ASSERT_FALSE(engine.stopped(in, t).reset) << t;
  // Pressed with the deadman held: no hold begins.
  apply_script(in, "4010 button guide 0\n4020 button leftshoulder 1\n4030 button guide 1\n");
  for (std::int64_t t = 4040; t <= 7000; t += 40) ASSERT_FALSE(engine.stopped(in, t).reset) << t;
  // Let go and pressed again between two ticks: the hold begins again there.
  apply_script(in, "7010 button leftshoulder 0\n7020 button guide 0\n7030 button guide 1\n");
  EXPECT_FALSE(engine.stopped(in, 7040).reset);  // begun here: the deadman let go is no press
  apply_script(in, "7050 button guide 0\n7060 button guide 1\n");
  engine.stopped(in, 7080);
  apply_script(in, "8000 button guide 0\n8010 button guide 1\n");  // let go within the hold: again from 8040
  engine.stopped(in, 8040);
  EXPECT_FALSE(engine.stopped(in, 9080).reset);
  EXPECT_EQ(engine.stopped(in, 10040).reset, input::Pad::kOperator);
}

TEST(EngineStops, TheSupervisorsHoldAndPressesAreTheSupervisors) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "100 supervisor button x 1\n");  // the supervisor presses its stop too
  const auto tick = engine.stopped(in, 120);
  EXPECT_TRUE(tick.pressed.by_supervisor);
  EXPECT_FALSE(tick.pressed.by_operator);
  EXPECT_FALSE(tick.reset);  // a press while stopped, held: the supervisor's hold begins
  EXPECT_FALSE(engine.stopped(in, 2080).reset);
  EXPECT_EQ(engine.stopped(in, 2120).reset, input::Pad::kSupervisor);
}

TEST(EngineStops, AControllerLostEndsItsHoldAndItsNewSessionCountsAfresh) {
  input::InputState in;
  auto engine = stopped_at_80(in);
  apply_script(in, "130 button guide 0\n170 button guide 1\n");
  engine.stopped(in, 200);
  apply_script(in, "300 disconnect\n");
  engine.stopped(in, 320);
  apply_script(in, "330 connect\n330 button guide 1\n");  // held at connect: not a press
  for (std::int64_t t = 360; t <= 3000; t += 40) ASSERT_FALSE(engine.stopped(in, t).reset) << t;
}

}  // namespace
}  // namespace andros::mapping

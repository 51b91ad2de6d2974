// A settled engine (docs/testing.md, "Idle cost"): while the controllers stay
// as they were at a step that changed nothing, a step reuses that step's
// frame. Each test runs an engine that reuses beside one that computes every
// step afresh (EngineOptions::reuse_settled false), and holds every frame and
// status to be the same; and checks that the reuse happens, and stops where
// the clock or the input still changes something.
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

// A knob (light, 1000/s from 40), a toggle and a 1 s enable timeout.
const std::string kKnobAndTimeout =
    "robot: HD1\ndeadman: leftshoulder\nenable_timeout: 1\nbindings:\n"
    "  - analog: drive\n    axis: lefty\n    invert: true\n"
    "  - signal: tool_on\n    button: x\n    toggle: true\n"
    "  - analog: light\n    increase: dpright\n    decrease: dpleft\n    rate: 1000\n    initial: 40\n";

/// Two engines on one input: `reused` as the run has it, `fresh` computing every step.
class Twin {
 public:
  explicit Twin(const std::string& yaml)
      : reused_(mapping_from_yaml(yaml), EngineOptions{}),
        fresh_(mapping_from_yaml(yaml), EngineOptions{.reuse_settled = false}) {}

  /// One step of each at t; the frames and statuses must be the same. Returns
  /// whether the reusing engine is settled after it: a step from the same
  /// controllers (the same for it, or the same again) is not computed.
  bool step(std::int64_t t) {
    const auto frame = reused_.step(in, t);
    EXPECT_EQ(frame, fresh_.step(in, t)) << "t=" << t;
    EXPECT_EQ(reused_.status(), fresh_.status()) << "t=" << t;
    EXPECT_FALSE(fresh_.settled());
    last = protocol::read_signals(frame);
    return reused_.settled();
  }
  /// Steps every 40 ms over [from, to); after how many the engine was settled.
  int steps(std::int64_t from, std::int64_t to) {
    int settled = 0;
    for (auto t = from; t < to; t += 40) settled += step(t) ? 1 : 0;
    return settled;
  }
  [[nodiscard]] const EngineStatus& status() const { return reused_.status(); }
  [[nodiscard]] bool settled() const { return reused_.settled(); }
  void restart() {
    reused_.restart(in);
    fresh_.restart(in);
  }

  input::InputState in;
  protocol::ControlState last;

 private:
  DrivenEngine reused_;
  DrivenEngine fresh_;
};

TEST(EngineSettled, AStepFromUnchangedControllersReusesTheFrameComputingWouldGive) {
  Twin twin(kKnobAndTimeout);
  EXPECT_FALSE(twin.step(0));  // start-up
  EXPECT_TRUE(twin.step(40));  // no controller, nothing changing: settled
  EXPECT_TRUE(twin.step(80));
  apply_script(twin.in, "100 connect\n110 button leftshoulder 1\n120 axis lefty -16384\n");
  EXPECT_FALSE(twin.step(120));  // the controller changed
  EXPECT_EQ(twin.status().deadman, DeadmanState::kFreshHold);
  EXPECT_TRUE(twin.step(160));  // the same controller: computed once more, and nothing changed
  EXPECT_EQ(twin.steps(200, 600), 10);
  EXPECT_EQ(twin.last[protocol::signal_id("drive")], 128);  // pushed through the deadman press: held back
  // Let go and pushed again between two steps: the same controller state, so
  // the step is the same too (computing it afresh, the stick was never seen at rest either).
  apply_script(twin.in, "585 axis lefty 0\n586 axis lefty -16384\n");
  EXPECT_TRUE(twin.step(600));
  EXPECT_EQ(twin.last[protocol::signal_id("drive")], 128);
  apply_script(twin.in, "610 axis lefty 0\n");
  EXPECT_FALSE(twin.step(640));
  apply_script(twin.in, "650 axis lefty -16384\n");
  EXPECT_FALSE(twin.step(680));
  EXPECT_GT(twin.last[protocol::signal_id("drive")], 128);
  EXPECT_GT(twin.steps(720, 900), 3);
  // A tap between two steps changes the press count, though every button is where it was.
  apply_script(twin.in, "905 button x 1\n906 button x 0\n");
  EXPECT_FALSE(twin.step(920));
  EXPECT_EQ(twin.last[protocol::signal_id("tool_on")], 1);
  EXPECT_FALSE(twin.settled());
  twin.steps(960, 1200);
  EXPECT_TRUE(twin.settled());
  twin.restart();  // the loop's rebase: every press history, the deadman pressed afresh
  EXPECT_FALSE(twin.settled());
  EXPECT_FALSE(twin.step(1200));
  EXPECT_EQ(twin.status().deadman, DeadmanState::kHeldNotFresh);
  EXPECT_EQ(twin.last[protocol::signal_id("tool_on")], 0);
}

TEST(EngineSettled, AKnobRampingIsComputedEveryStepUntilItsEndStop) {
  Twin twin(kKnobAndTimeout);
  twin.step(0);
  apply_script(twin.in, "0 connect\n10 button leftshoulder 1\n20 axis lefty -16384\n");
  twin.step(40);
  apply_script(twin.in, "50 button dpright 1\n");
  twin.step(80);
  // Held, the light ramps by 40 a step (1000/s): no step is the same as the last.
  EXPECT_EQ(twin.steps(120, 280), 0);
  EXPECT_EQ(twin.last[protocol::signal_id("light")], 240);
  // Still held, but at its end stop from 280: nothing changes any more.
  EXPECT_EQ(twin.steps(280, 600), 7);
  EXPECT_EQ(twin.last[protocol::signal_id("light")], 255);
}

TEST(EngineSettled, TheEnableTimeoutEndsASettledStretchOnItsTick) {
  Twin twin(kKnobAndTimeout);
  twin.step(0);
  apply_script(twin.in, "0 connect\n10 button leftshoulder 1\n");
  twin.step(40);  // enabled at 40: the timeout runs from there
  EXPECT_EQ(twin.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(twin.steps(80, 1040), 24);
  EXPECT_EQ(twin.status().deadman, DeadmanState::kFreshHold);
  EXPECT_FALSE(twin.step(1040));  // 1 s with no input change: computed, and timed out
  EXPECT_EQ(twin.status().deadman, DeadmanState::kTimedOut);
  EXPECT_EQ(twin.last[protocol::signal_id("safety")], 0);
  EXPECT_EQ(twin.steps(1080, 1400), 8);
  EXPECT_EQ(twin.status().deadman, DeadmanState::kTimedOut);
}

TEST(EngineSettled, TheNeutralFrameKeepsUpWithTheLevels) {
  DrivenEngine engine(mapping_from_yaml(kKnobAndTimeout), EngineOptions{});
  input::InputState in;
  const auto light = [&engine] { return protocol::read_signals(engine.neutral())[protocol::signal_id("light")]; };
  EXPECT_EQ(light(), 40);
  start_enabled(engine, in);
  apply_script(in, "50 button dpright 1\n");
  engine.step(in, 80);
  EXPECT_EQ(light(), 80);  // asked for once more after a step that moved the light: not the one kept from before
  engine.step(in, 120);
  EXPECT_EQ(light(), 120);
  apply_script(in, "130 button dpright 0\n");
  engine.step(in, 160);
  engine.step(in, 200);
  EXPECT_TRUE(engine.settled());
  EXPECT_EQ(light(), 120);
  EXPECT_EQ(protocol::read_signals(engine.neutral())[protocol::signal_id("safety")], 0);
}

TEST(EngineSettled, TheSupervisorsControllerCountsAsInput) {
  Twin twin(kKnobAndTimeout);
  twin.step(0);
  EXPECT_TRUE(twin.step(40));
  apply_script(twin.in, "90 supervisor connect\n");
  EXPECT_FALSE(twin.step(120));
  EXPECT_TRUE(twin.in.supervisor().connected());
}

}  // namespace
}  // namespace andros::mapping

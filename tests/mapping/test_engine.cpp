// The engine's enabling rule (docs/mapping.md): neutral frames until the
// deadman is pressed afresh, after start-up, a restart or a new pad; and what
// an Engine accepts as a mapping.
#include <gtest/gtest.h>

#include <type_traits>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

TEST(Engine, NeutralUntilFreshDeadmanThenDrives) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  auto f = protocol::read_signals(engine.step(in, 0));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kNoPad);
  EXPECT_EQ(f[protocol::signal_id("safety")], 0);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
  EXPECT_TRUE(protocol::validation_errors(engine.step(in, 40)).empty());

  apply_script(in, "80 connect pad\n80 button leftshoulder 1\n80 axis lefty -32768\n");
  f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kHeldNotFresh);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);

  apply_script(in, "90 button leftshoulder 0\n");
  engine.step(in, 100);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  apply_script(in, "110 button leftshoulder 1\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("safety")], 1);
  EXPECT_EQ(f[protocol::signal_id("drive_brake")], 1);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);  // pushed since before the press: at rest first
  EXPECT_EQ(engine.status().held_back, std::vector{*input::parse_axis_name("lefty")});
  EXPECT_EQ(f[protocol::signal_id("code")], 0x01);

  apply_script(in, "125 axis lefty 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 160))[protocol::signal_id("drive")], 128);
  EXPECT_TRUE(engine.status().held_back.empty());
  apply_script(in, "165 axis lefty -32768\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 200))[protocol::signal_id("drive")],
            255);  // full forward: 128 + round(1 * 127)

  apply_script(in, "210 disconnect\n");
  f = protocol::read_signals(engine.step(in, 240));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kNoPad);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
  EXPECT_EQ(f[protocol::signal_id("safety")], 0);
  EXPECT_EQ(protocol::read_signals(engine.neutral())[protocol::signal_id("drive")], 128);
}

// docs/mapping.md's pivot example: deadzone 0.1, expo 0.5, half right gives 162.
TEST(Engine, PivotGivesTheDocumentedValue) {
  Mapping m = *hd1_mapping();
  for (auto& b : m.bindings) {
    if (auto* a = std::get_if<AxisBinding>(&b.rule); a && a->analog == protocol::signal_id("pivot"))
      a->shape = {false, 0.1, 0.5};
  }
  DrivenEngine engine(validate(std::move(m)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);                  // the start-up tick first: presses before it would not count
  apply_script(in, "50 axis leftx 16384\n");  // after the enabling frame: not held back
  const auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(f[protocol::signal_id("pivot")], 162);
}

TEST(Engine, PressesBeforeStartUpAreNotFresh) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  apply_script(in, "0 connect\n5 button leftshoulder 1\n");  // pressed before the engine's first tick
  engine.step(in, 10);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kHeldNotFresh);
  EXPECT_NE(describe(engine.status().deadman).find("press it again"), std::string_view::npos);
  apply_script(in, "20 button leftshoulder 0\n");
  engine.step(in, 30);
  apply_script(in, "40 button leftshoulder 1\n");
  engine.step(in, 50);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(describe(DeadmanState::kFreshHold), "enabled");
}

TEST(Engine, AfterARestartTheHeldDeadmanIsNotFreshAndTogglesAreOff) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button leftshoulder 1\n");
  engine.step(in, 20);  // enabled; the stick and x act from the next frame (the rest rule)
  apply_script(in, "30 axis lefty -32768\n30 button x 1\n35 button x 0\n");
  auto f = protocol::read_signals(engine.step(in, 40));
  ASSERT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  ASSERT_EQ(f[protocol::signal_id("drive")], 255);
  ASSERT_EQ(f[protocol::signal_id("tool_on")], 1);
  apply_script(in, "50 button y 1\n");  // a press while stopped is history too
  engine.restart(in);                   // the process was stopped (Ctrl-Z) and continued, the deadman held throughout
  f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kHeldNotFresh);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 0);
  apply_script(in, "90 button leftshoulder 0\n95 axis lefty 0\n");
  engine.step(in, 100);
  apply_script(in, "110 button leftshoulder 1\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 0);  // the toggle did not come back
  apply_script(in, "130 axis lefty -32768\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 160))[protocol::signal_id("drive")], 255);
}

TEST(Engine, TriggerDeadmanMustBeSeenReleased) {
  DrivenEngine engine(
      mapping_from_yaml("robot: HD1\ndeadman: lefttrigger\nbindings:\n  - signal: tool_on\n    button: a\n"),
      EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 axis lefttrigger 32767\n0 button a 1\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 40))[protocol::signal_id("tool_on")], 0);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kHeldNotFresh);
  apply_script(in, "50 axis lefttrigger 16383\n");  // below half way: released
  engine.step(in, 80);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  apply_script(in, "90 axis lefttrigger 16384\n");
  auto f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 0);  // a held since the connect: released first
  apply_script(in, "130 button a 0\n140 button a 1\n");
  f = protocol::read_signals(engine.step(in, 160));
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 1);
}

// Every change between two frames counts: a deadman released and pressed
// again within one tick is a release at that tick, and the press after it is
// fresh (the stick held through it waits for rest).
TEST(Engine, ADeadmanLetGoAndPressedWithinOneTickIsARelease) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 axis lefty -32768\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 80))[protocol::signal_id("drive")], 255);
  apply_script(in, "90 button leftshoulder 0\n110 button leftshoulder 1\n");
  auto f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  EXPECT_EQ(f[protocol::signal_id("safety")], 0);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
  f = protocol::read_signals(engine.step(in, 160));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);                // held through the press: at rest first
  apply_script(in, "170 axis lefty 0\n180 axis lefty -32768\n");  // at rest and back between two ticks: not seen
  EXPECT_EQ(protocol::read_signals(engine.step(in, 200))[protocol::signal_id("drive")], 128);
}

TEST(Engine, APanicSqueezeWithinOneTickLatches) {
  DrivenEngine engine(mapping_from_yaml("robot: HD1\ndeadman: lefttrigger\ndeadman_panic: 0.9\nbindings:\n"
                                        "  - analog: drive\n    axis: lefty\n    invert: true\n"),
                      EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n");
  engine.step(in, 20);  // the trigger seen released
  apply_script(in, "30 axis lefttrigger 24000\n");
  engine.step(in, 40);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  apply_script(in, "90 axis lefttrigger 32767\n110 axis lefttrigger 24000\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kPastPanic);
  in.begin_tick();
  engine.step(in, 160);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kPastPanic);  // latched until fully released
  // Fully released and squeezed again within one tick: the latch ends, and the squeeze after it is fresh.
  apply_script(in, "170 axis lefttrigger 0\n180 axis lefttrigger 24000\n");
  engine.step(in, 200);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  in.begin_tick();
  engine.step(in, 240);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  apply_script(in, "250 axis lefttrigger 32767\n260 axis lefttrigger 0\n");  // past it and fully back: released
  engine.step(in, 280);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  // Which came first within a tick is not known: a squeeze with a full release and back keeps the latch.
  apply_script(in, "290 axis lefttrigger 24000\n");
  engine.step(in, 320);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  apply_script(in, "330 axis lefttrigger 0\n340 axis lefttrigger 32767\n350 axis lefttrigger 24000\n");
  engine.step(in, 360);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kPastPanic);
  in.begin_tick();
  engine.step(in, 400);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kPastPanic);
}

TEST(Engine, ANewPadBetweenTwoEnabledFramesIsAChangeOfMeaning) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  // Lost, back with the stick pushed, and the deadman pressed afresh, all in one frame.
  apply_script(in, "50 disconnect\n60 connect\n60 axis lefty -32768\n70 button leftshoulder 1\n");
  const auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
}

// Neutral is the protocol's (docs/mapping.md, "`center`: a trim, never the
// neutral"). A `center:` trim moves only
// where drive and pivot rest while enabled; every frame that is not enabled,
// and neutral(), carries 128.
TEST(Engine, ACenterTrimMovesOnlyTheEnabledRest) {
  DrivenEngine engine(mapping_from_yaml("robot: HD1\nextends: " ANDROS_MAPPINGS_DIR "/hd1.yaml\ncenter: 124\n"),
                      EngineOptions{});
  const auto drive = protocol::signal_id("drive");
  const auto pivot = protocol::signal_id("pivot");
  input::InputState in;
  const auto expect_neutral = [&](const protocol::DataBytes& frame, const char* when) {
    const auto f = protocol::read_signals(frame);
    EXPECT_EQ(f[protocol::signal_id("safety")], 0) << when;
    EXPECT_EQ(f[drive], 128) << when;
    EXPECT_EQ(f[pivot], 128) << when;
  };
  expect_neutral(engine.step(in, 0), "no controller");
  expect_neutral(engine.neutral(), "neutral()");
  apply_script(in, "0 connect\n0 button leftshoulder 1\n");
  expect_neutral(engine.step(in, 40), "deadman held at connect");
  apply_script(in, "50 button leftshoulder 0\n");
  expect_neutral(engine.step(in, 80), "deadman released");

  apply_script(in, "90 button leftshoulder 1\n90 axis lefty -32768\n");
  auto f = protocol::read_signals(engine.step(in, 120));
  ASSERT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(f[drive], 124) << "enabled, the stick held back until at rest: the trimmed rest";
  apply_script(in, "130 axis lefty 0\n");
  f = protocol::read_signals(engine.step(in, 160));
  EXPECT_EQ(f[drive], 124) << "enabled, stick at rest";
  EXPECT_EQ(f[pivot], 124) << "enabled, stick at rest";
  apply_script(in, "170 axis lefty -32768\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 200))[drive], 255);  // 124 + round(1 * 131)
  apply_script(in, "210 axis lefty 32767\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 240))[drive], 0);  // 124 + round(-1 * 124)
  expect_neutral(engine.neutral(), "neutral() while driving (a stop, a loss, a reload)");

  apply_script(in, "250 button leftshoulder 0\n");
  expect_neutral(engine.step(in, 280), "deadman released, stick full back");
  apply_script(in, "290 button leftshoulder 1\n295 axis lefty 0\n300 disconnect\n");
  expect_neutral(engine.step(in, 320), "controller lost");
}

// An Engine runs only a ValidMapping, and validate() is the one way to make one.
static_assert(!std::is_constructible_v<Engine, Mapping, EngineOptions>);

TEST(Engine, RefusesAnInvalidMappingBuiltByHand) {
  Mapping m;
  SelectorBinding s;
  s.positions = {{}, {protocol::signal_id("main_video_2")}};
  s.initial = 2;  // no such position
  m.bindings.push_back(Binding{s, {}, {}, {}, {}});
  EXPECT_THROW(validate(m, false), InputError);
  m.bindings[0].rule = ButtonBinding{protocol::signal_id("safety"), {}, false, false, 0.5};
  EXPECT_THROW(validate(m, false), InputError);
}

TEST(Engine, WithoutADeadmanOnlyNeutralFrames) {
  Mapping m;
  m.bindings.push_back(
      Binding{ButtonBinding{protocol::signal_id("tool_on"), *input::parse_button_name("a")}, {}, {}, {}, {}});
  DrivenEngine engine(validate(m, false), EngineOptions{});
  input::InputState in;
  apply_script(in, "0 connect\n10 button a 1\n");
  EXPECT_EQ(engine.step(in, 40), engine.neutral());
}

}  // namespace
}  // namespace andros::mapping

#include <gtest/gtest.h>

#include "andros/engine.hpp"
#include "andros/events.hpp"
#include "andros/mapping_loader.hpp"
#include "temp_dir.hpp"

namespace andros {
namespace {

using T = InputEvent::Type;

Mapping hd1() { return load_mapping(std::string(ANDROS_MAPPINGS_DIR) + "/hd1.yaml"); }

void apply_script(InputState& s, const std::string& text) {
  for (const auto& e : parse_event_script(text, "t.events")) s.apply(e);
}

TEST(Engine, NeutralUntilFreshDeadmanThenDrives) {
  Engine engine(hd1(), EngineOptions{});
  InputState in;
  auto f = read_signals(engine.step(in, 0));
  EXPECT_EQ(engine.status().enable, EnableState::kNoController);
  EXPECT_EQ(f[signal_id("safety")], 0);
  EXPECT_EQ(f[signal_id("drive")], 128);
  EXPECT_TRUE(validation_errors(engine.step(in, 40)).empty());

  apply_script(in, "80 connect pad\n80 button leftshoulder 1\n80 axis lefty -32768\n");
  f = read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanNotFresh);
  EXPECT_EQ(f[signal_id("drive")], 128);

  apply_script(in, "90 button leftshoulder 0\n100 button leftshoulder 1\n");
  f = read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  EXPECT_EQ(f[signal_id("safety")], 1);
  EXPECT_EQ(f[signal_id("drive_brake")], 1);
  EXPECT_EQ(f[signal_id("drive")], 255);  // full forward: 128 + round(1 * 127)
  EXPECT_EQ(f[signal_id("code")], 0x01);

  apply_script(in, "130 disconnect\n");
  f = read_signals(engine.step(in, 160));
  EXPECT_EQ(engine.status().enable, EnableState::kNoController);
  EXPECT_EQ(f[signal_id("drive")], 128);
  EXPECT_EQ(f[signal_id("safety")], 0);
  EXPECT_EQ(read_signals(engine.neutral())[signal_id("drive")], 128);
}

TEST(Engine, PivotContractValue) {
  Mapping m = hd1();
  for (auto& b : m.bindings) {
    if (auto* a = std::get_if<AxisBinding>(&b.rule); a && a->analog == signal_id("pivot")) a->shape = {false, 0.1, 0.5};
  }
  Engine engine(std::move(m), EngineOptions{});
  InputState in;
  engine.step(in, 0);  // start-up: presses before the first tick would not count
  apply_script(in, "0 connect\n10 button leftshoulder 1\n10 axis leftx 16384\n");
  const auto f = read_signals(engine.step(in, 40));
  EXPECT_EQ(f[signal_id("pivot")], 162);
}


Mapping from_yaml(const std::string& text) {
  testing::TempDir dir;
  return load_mapping(dir.write("m.yaml", text));
}

const std::string kLayered =
    "robot: HD1\ndeadman: leftshoulder\nbindings:\n"
    "  - signal: tool_on\n    button: x\n    toggle: true\n"
    "  - selector: video\n    next: y\n    positions: [[], [main_video_2]]\n"
    "  - analog: light\n    increase: dpright\n    decrease: dpleft\n    rate: 1000\n    initial: 40\n"
    "layers:\n"
    "  arm:\n    hold: rightshoulder\n    bindings:\n      - signal: elbow_cw\n        button: a\n"
    "  cam:\n    toggle: back\n    bindings:\n      - signal: focus_up\n        button: a\n";

TEST(Engine, PressesBeforeStartUpAreNotFresh) {
  Engine engine(hd1(), EngineOptions{});
  InputState in;
  apply_script(in, "0 connect\n5 button leftshoulder 1\n");  // pressed before the engine's first tick
  engine.step(in, 10);
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanNotFresh);
  EXPECT_NE(describe(engine.status().enable).find("press it again"), std::string_view::npos);
  apply_script(in, "20 button leftshoulder 0\n30 button leftshoulder 1\n");
  engine.step(in, 50);
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  EXPECT_EQ(describe(EnableState::kEnabled), "enabled");
}

TEST(Engine, AfterARestartTheHeldDeadmanIsNotFreshAndTogglesAreOff) {
  Engine engine(hd1(), EngineOptions{});
  InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button leftshoulder 1\n10 axis lefty -32768\n10 button x 1\n20 button x 0\n");
  auto f = read_signals(engine.step(in, 40));
  ASSERT_EQ(engine.status().enable, EnableState::kEnabled);
  ASSERT_EQ(f[signal_id("drive")], 255);
  ASSERT_EQ(f[signal_id("tool_on")], 1);
  engine.restart();  // the process was stopped (Ctrl-Z) and continued, the deadman held throughout
  apply_script(in, "50 button y 1\n");  // a press while stopped is history too
  f = read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanNotFresh);
  EXPECT_EQ(f[signal_id("drive")], 128);
  EXPECT_EQ(f[signal_id("tool_on")], 0);
  apply_script(in, "90 button leftshoulder 0\n95 axis lefty 0\n100 button leftshoulder 1\n");
  f = read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  EXPECT_EQ(f[signal_id("tool_on")], 0);  // the toggle did not come back
  apply_script(in, "130 axis lefty -32768\n");
  EXPECT_EQ(read_signals(engine.step(in, 160))[signal_id("drive")], 255);
}

TEST(Engine, TriggerDeadmanMustBeSeenReleased) {
  Engine engine(from_yaml("robot: HD1\ndeadman: lefttrigger\nbindings:\n  - signal: tool_on\n    button: a\n"),
                EngineOptions{});
  InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n0 axis lefttrigger 32767\n0 button a 1\n");
  EXPECT_EQ(read_signals(engine.step(in, 40))[signal_id("tool_on")], 0);
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanNotFresh);
  apply_script(in, "50 axis lefttrigger 16383\n");  // below half way: released
  engine.step(in, 80);
  EXPECT_EQ(engine.status().enable, EnableState::kDeadmanReleased);
  apply_script(in, "90 axis lefttrigger 16384\n");
  const auto f = read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().enable, EnableState::kEnabled);
  EXPECT_EQ(f[signal_id("tool_on")], 1);
}

TEST(Engine, LayersHoldBeatsToggleAndLossClearsTheToggle) {
  Engine engine(from_yaml(kLayered), EngineOptions{});
  InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button leftshoulder 1\n20 button back 1\n25 button back 0\n30 button a 1\n");
  auto f = read_signals(engine.step(in, 40));
  EXPECT_EQ(engine.status().layer, "cam");
  EXPECT_EQ(f[signal_id("focus_up")], 1);
  apply_script(in, "50 button rightshoulder 1\n");
  f = read_signals(engine.step(in, 80));
  EXPECT_EQ(engine.status().layer, "arm");
  EXPECT_EQ(f[signal_id("elbow_cw")], 1);
  EXPECT_EQ(f[signal_id("focus_up")], 0);
  apply_script(in, "90 button rightshoulder 0\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().layer, "cam");
  apply_script(in, "130 disconnect\n140 connect\n150 button leftshoulder 1\n");
  engine.step(in, 160);
  EXPECT_EQ(engine.status().layer, "");
}

TEST(Engine, DeadmanReleaseClearsTogglesButSelectorsAndKnobsStay) {
  Engine engine(from_yaml(kLayered), EngineOptions{});
  InputState in;
  EXPECT_EQ(read_signals(engine.neutral())[signal_id("light")], 40);  // the knob's initial value
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button leftshoulder 1\n20 button x 1\n21 button x 0\n22 button y 1\n"
                   "23 button y 0\n30 button dpright 1\n");
  auto f = read_signals(engine.step(in, 40));
  EXPECT_EQ(f[signal_id("tool_on")], 1);
  EXPECT_EQ(f[signal_id("main_video_2")], 1);
  EXPECT_EQ(f[signal_id("light")], 80);  // 40 + 1000/s x 40 ms
  apply_script(in, "50 button leftshoulder 0\n");
  f = read_signals(engine.step(in, 80));
  EXPECT_EQ(f[signal_id("tool_on")], 0);
  EXPECT_EQ(f[signal_id("main_video_2")], 1);
  EXPECT_EQ(f[signal_id("light")], 80);
  EXPECT_EQ(engine.neutral(), engine.step(in, 120));
  apply_script(in, "130 button leftshoulder 1\n");
  f = read_signals(engine.step(in, 160));
  EXPECT_EQ(f[signal_id("tool_on")], 0);  // stays off until pressed again
  EXPECT_EQ(f[signal_id("light")], 120);
}

TEST(Engine, MovedEngineKeepsWorking) {
  Engine first(from_yaml(kLayered), EngineOptions{true, 0x3C});
  Engine engine = std::move(first);
  InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button leftshoulder 1\n20 button rightshoulder 1\n20 button a 1\n");
  const auto data = engine.step(in, 40);
  EXPECT_EQ(read_signals(data)[signal_id("elbow_cw")], 1);
  EXPECT_EQ(data[kCodeByte], 0x3C);
  EXPECT_EQ(engine.mapping().robot, "HD1");
}

TEST(Engine, RefusesAnInvalidMappingBuiltByHand) {
  Mapping m;
  SelectorBinding s;
  s.positions = {{}, {signal_id("main_video_2")}};
  s.initial = 2;  // no such position
  m.bindings.push_back(Binding{s, {}, {}, {}, {}});
  EXPECT_THROW(Engine(m, EngineOptions{}), InputError);
  m.bindings[0].rule = ButtonBinding{signal_id("safety"), {}, false, false, 0.5};
  EXPECT_THROW(Engine(m, EngineOptions{}), InputError);
}

TEST(Engine, WithoutADeadmanOnlyNeutralFrames) {
  Mapping m;
  m.bindings.push_back(Binding{ButtonBinding{signal_id("tool_on"), *parse_button_name("a")}, {}, {}, {}, {}});
  Engine engine(m, EngineOptions{});
  InputState in;
  apply_script(in, "0 connect\n10 button a 1\n");
  EXPECT_EQ(engine.step(in, 40), engine.neutral());
}
}  // namespace
}  // namespace andros

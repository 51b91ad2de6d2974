// The engine's layers, toggles, selectors and knobs (docs/mapping.md), and
// what a change of layer holds back.
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

const std::string kLayered =
    "robot: HD1\ndeadman: leftshoulder\nbindings:\n"
    "  - signal: tool_on\n    button: x\n    toggle: true\n"
    "  - selector: video\n    next: y\n    positions: [[], [main_video_2]]\n"
    "  - analog: light\n    increase: dpright\n    decrease: dpleft\n    rate: 1000\n    initial: 40\n"
    "layers:\n"
    "  arm:\n    hold: rightshoulder\n    bindings:\n      - signal: elbow_cw\n        button: a\n"
    "  cam:\n    toggle: back\n    bindings:\n      - signal: focus_up\n        button: a\n";

TEST(Engine, LayersHoldBeatsToggleAndLossClearsTheToggle) {
  DrivenEngine engine(mapping_from_yaml(kLayered), EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  // A layer toggle pressed in the enabling frame counts: layer buttons are not held back.
  apply_script(in, "0 connect\n10 button leftshoulder 1\n20 button back 1\n25 button back 0\n");
  engine.step(in, 40);
  EXPECT_EQ(engine.status().layer, "cam");
  apply_script(in, "50 button a 1\n");
  auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(f[protocol::signal_id("focus_up")], 1);
  apply_script(in, "90 button rightshoulder 1\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().layer, "arm");
  EXPECT_EQ(f[protocol::signal_id("elbow_cw")], 0);  // a, held across the change: released first
  EXPECT_EQ(f[protocol::signal_id("focus_up")], 0);
  apply_script(in, "130 button a 0\n135 button a 1\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 160))[protocol::signal_id("elbow_cw")], 1);
  apply_script(in, "170 button rightshoulder 0\n");
  f = protocol::read_signals(engine.step(in, 200));
  EXPECT_EQ(engine.status().layer, "cam");
  EXPECT_EQ(f[protocol::signal_id("focus_up")], 0);
  apply_script(in, "210 disconnect\n220 connect\n230 button leftshoulder 1\n");
  engine.step(in, 240);
  EXPECT_EQ(engine.status().layer, "");
}

TEST(Engine, DeadmanReleaseClearsTogglesButSelectorsAndKnobsStay) {
  DrivenEngine engine(mapping_from_yaml(kLayered), EngineOptions{});
  input::InputState in;
  EXPECT_EQ(protocol::read_signals(engine.neutral())[protocol::signal_id("light")], 40);  // the knob's initial value
  start_enabled(engine, in);
  apply_script(in, "50 button x 1\n51 button x 0\n52 button y 1\n53 button y 0\n60 button dpright 1\n");
  auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 1);
  EXPECT_EQ(f[protocol::signal_id("main_video_2")], 1);
  EXPECT_EQ(f[protocol::signal_id("light")], 80);  // 40 + 1000/s x 40 ms
  apply_script(in, "90 button leftshoulder 0\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 0);
  EXPECT_EQ(f[protocol::signal_id("main_video_2")], 1);
  EXPECT_EQ(f[protocol::signal_id("light")], 80);
  EXPECT_EQ(engine.neutral(), engine.step(in, 160));
  apply_script(in, "170 button leftshoulder 1\n");
  f = protocol::read_signals(engine.step(in, 200));
  EXPECT_EQ(f[protocol::signal_id("tool_on")], 0);  // stays off until pressed again
  EXPECT_EQ(f[protocol::signal_id("light")], 80);   // dpright held across the enable: the knob waits for a release
  apply_script(in, "210 button dpright 0\n215 button dpright 1\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 240))[protocol::signal_id("light")], 120);
}

TEST(Engine, MovedEngineKeepsWorking) {
  DrivenEngine first(mapping_from_yaml(kLayered), EngineOptions{true, 0x3C});
  DrivenEngine engine = std::move(first);
  input::InputState in;
  start_enabled(engine, in, "20 button rightshoulder 1\n");
  apply_script(in, "50 button a 1\n");
  const auto data = engine.step(in, 80);
  EXPECT_EQ(protocol::read_signals(data)[protocol::signal_id("elbow_cw")], 1);
  EXPECT_EQ(data[protocol::kCodeByte], 0x3C);
  EXPECT_EQ(engine.mapping().robot, "HD1");
}

// The issue's own case on the shipped layout: the arm layer on (right stick
// click), push the left stick full and squeeze RT, the arm layer off. Drive and
// fiber_unwind wait.
TEST(Engine, LeavingALayerWithTheStickHeldDoesNotMove) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in, "20 button rightstick 1\n25 button rightstick 0\n");
  apply_script(in, "50 axis lefty -32768\n50 axis righttrigger 32767\n");
  auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(f[protocol::signal_id("shoulder_ccw")], 1);
  apply_script(in, "90 button rightstick 1\n95 button rightstick 0\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().layer, "");
  EXPECT_EQ(f[protocol::signal_id("drive")], 128);
  EXPECT_EQ(f[protocol::signal_id("fiber_unwind")], 0);
  EXPECT_EQ(engine.status().held_back.size(), 2U);
  apply_script(in, "130 axis lefty -3000\n130 axis righttrigger 16383\n");  // inside deadzone 0.1, below 0.5
  engine.step(in, 160);
  apply_script(in, "170 axis lefty -32768\n170 axis righttrigger 32767\n");
  f = protocol::read_signals(engine.step(in, 200));
  EXPECT_EQ(f[protocol::signal_id("drive")], 255);
  EXPECT_EQ(f[protocol::signal_id("fiber_unwind")], 1);
}

TEST(Engine, PressesInTheFrameOfAChangeAreDroppedButLaterTapsAct) {
  DrivenEngine engine(hd1_mapping(), EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  // dpup pressed while the deadman is pressed (one frame): held back, then a tap counts.
  apply_script(in, "0 connect\n10 button leftshoulder 1\n20 button dpup 1\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 40))[protocol::signal_id("front_art_up")], 0);
  apply_script(in, "50 button dpup 0\n55 button dpup 1\n60 button dpup 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 80))[protocol::signal_id("front_art_up")], 1);
  // b tapped in the frame that switches the camera layer on (b: the light knob there): dropped.
  apply_script(in, "90 button leftstick 1\n95 button leftstick 0\n100 button b 1\n105 button b 0\n");
  auto f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(engine.status().layer, "camera");
  EXPECT_EQ(f[protocol::signal_id("light")], 0);
  apply_script(in, "130 button leftstick 1\n135 button leftstick 0\n");
  engine.step(in, 160);
  // A tap of an input the change leaves alone (start: the speed selector in both layers) still counts.
  apply_script(in, "170 button rightstick 1\n175 button rightstick 0\n180 button start 1\n185 button start 0\n");
  f = protocol::read_signals(engine.step(in, 200));
  EXPECT_EQ(engine.status().layer, "arm");
  EXPECT_EQ(f[protocol::signal_id("speed_low")], 0);  // low -> medium
}

TEST(Engine, OneToggleStatePerSignal) {
  DrivenEngine engine(mapping_from_yaml("robot: HD1\ndeadman: leftshoulder\nbindings:\n"
                                        "  - signal: tool_on\n    button: x\n    toggle: true\n"
                                        "layers:\n  cam:\n    toggle: back\n    bindings:\n"
                                        "      - signal: tool_on\n        button: y\n        toggle: true\n"),
                      EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 button x 1\n55 button x 0\n60 button back 1\n65 button back 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 80))[protocol::signal_id("tool_on")], 1);
  apply_script(in, "90 button y 1\n95 button y 0\n");  // the camera layer's y flips the same state
  EXPECT_EQ(protocol::read_signals(engine.step(in, 120))[protocol::signal_id("tool_on")], 0);
  apply_script(in, "130 button y 1\n135 button y 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 160))[protocol::signal_id("tool_on")], 1);
  apply_script(in, "170 button back 1\n175 button back 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 200))[protocol::signal_id("tool_on")],
            1);  // stays on in the base layer
  apply_script(in, "210 button x 1\n215 button x 0\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 240))[protocol::signal_id("tool_on")], 0);
}

}  // namespace
}  // namespace andros::mapping

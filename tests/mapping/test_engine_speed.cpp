// Speed levels (docs/mapping.md, `scale`): the level scales drive and pivot's
// distance from rest exactly; a change of level holds a held stick back until
// it is seen at rest; the level's life across a deadman release, a new pad and
// a restart.
#include <gtest/gtest.h>

#include "andros/mapping/engine.hpp"
#include "support/engine_steps.hpp"

namespace andros::mapping {
namespace {

using namespace testing;  // engine_steps.hpp

// Drive on lefty (up = forward), pivot on leftx, neither with a deadzone or
// expo, so that the bytes follow from the arithmetic alone; Y steps up, A down.
std::string speed_yaml(const std::string& extra = "") {
  return "robot: HD1\ndeadman: leftshoulder\n" + extra +
         "bindings:\n"
         "  - analog: drive\n    axis: lefty\n    invert: true\n"
         "  - analog: pivot\n    axis: leftx\n"
         "  - signal: [pt_left, pt_right]\n    axis: rightx\n"
         "layers:\n  arm:\n    hold: rightshoulder\n    bindings:\n"
         "      - signal: [shoulder_ccw, shoulder_cw]\n        axis: lefty\n";
}

const std::string kScale = "scale: {button: y, down: a, levels: [0.25, 0.5, 1.0]}\n";

std::uint8_t drive(const protocol::DataBytes& data) {
  return protocol::read_signals(data)[protocol::signal_id("drive")];
}
std::uint8_t pivot(const protocol::DataBytes& data) {
  return protocol::read_signals(data)[protocol::signal_id("pivot")];
}

struct Scaled {
  int center;
  const char* axis;
  int raw;
  std::array<int, 3> bytes;  ///< at 0.25, 0.5, 1.0
};

// centre + round(level z (255 - centre)) for z >= 0, centre + round(level z centre) below, halves away from 0.
TEST(EngineSpeed, EachLevelScalesTheDistanceFromRestExactly) {
  const std::vector<Scaled> cases = {
      {128, "lefty", -32768, {160, 192, 255}},  // z = 1: 128 + round(31.75), round(63.5) = 64, 127
      {128, "lefty", 32767, {96, 64, 0}},       // z = -1: 128 - 32, - 64, - 128
      {128, "lefty", -8000, {136, 144, 159}},   // z = 0.244141: round(7.75) = 8, round(15.50) = 16, round(31.006) = 31
      {128, "leftx", 16384, {144, 160, 192}},   // z = 0.500015: round(15.88), round(31.75), round(63.50)
      {128, "leftx", -16384, {112, 96, 64}},    // z = -0.5: -16, -32, -64
      {124, "lefty", -32768, {157, 190, 255}},  // trimmed: 124 + round(32.75), round(65.5) = 66, 131
      {124, "lefty", 32767, {93, 62, 0}},       // 124 - 31, - 62, - 124
      {124, "leftx", 16384, {140, 157, 190}},   // 124 + round(16.38), round(32.75), round(65.50)
  };
  const std::array<const char*, 3> levels = {"0.25", "0.5", "1.0"};
  for (const auto& c : cases) {
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const auto extra = "center: " + std::to_string(c.center) +
                         "\nscale: {button: y, levels: [0.25, 0.5, 1.0], initial: " + levels[i] + "}\n";
      DrivenEngine engine(mapping_from_yaml(speed_yaml(extra)), EngineOptions{});
      input::InputState in;
      start_enabled(engine, in);
      EXPECT_EQ(engine.status().speed, (SpeedLevel{i, 3, std::stod(levels[i])}));
      EXPECT_EQ(drive(engine.step(in, 80)), c.center);  // at rest: the trim whatever the level
      apply_script(in, std::string("90 axis ") + c.axis + " " + std::to_string(c.raw) + "\n");
      const auto data = engine.step(in, 120);
      const auto byte = std::string(c.axis) == "lefty" ? drive(data) : pivot(data);
      EXPECT_EQ(byte, c.bytes[i]) << "centre " << c.center << ", " << c.axis << " " << c.raw << " at level "
                                  << levels[i];
      EXPECT_EQ(drive(engine.neutral()), 128);
    }
  }
}

TEST(EngineSpeed, NoScaleIsOneLevelOfFullSpeed) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml()), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  EXPECT_EQ(engine.status().speed, (SpeedLevel{0, 1, 1.0}));
  apply_script(in, "50 axis lefty -32768\n60 button y 1\n");  // y steps nothing here
  EXPECT_EQ(drive(engine.step(in, 80)), 255);
  EXPECT_EQ(engine.status().speed, (SpeedLevel{0, 1, 1.0}));
}

TEST(EngineSpeed, UpWrapsToTheSlowestDownStopsThere) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  const auto press = [&](const char* button, std::int64_t t) {
    apply_script(
        in, std::to_string(t) + " button " + button + " 1\n" + std::to_string(t + 5) + " button " + button + " 0\n");
    engine.step(in, t + 30);
    return engine.status().speed.index;
  };
  EXPECT_EQ(engine.status().speed.index, 0U);
  EXPECT_EQ(press("y", 50), 1U);
  EXPECT_EQ(press("y", 90), 2U);
  EXPECT_EQ(press("y", 130), 0U);  // past the fastest: back to the slowest, never up
  EXPECT_EQ(press("a", 170), 0U);  // down at the slowest: stays
  EXPECT_EQ(press("y", 210), 1U);
  EXPECT_EQ(press("a", 250), 0U);
  // Two taps between two frames: two steps.
  apply_script(in, "290 button y 1\n292 button y 0\n294 button y 1\n296 button y 0\n");
  engine.step(in, 320);
  EXPECT_EQ(engine.status().speed, (SpeedLevel{2, 3, 1.0}));
}

TEST(EngineSpeed, AStickHeldAtAChangeOfLevelWaitsUntilSeenAtRest) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 axis lefty -32768\n");
  EXPECT_EQ(drive(engine.step(in, 80)), 160);          // 0.25
  apply_script(in, "90 button y 1\n95 button y 0\n");  // the stick still full forward
  auto data = engine.step(in, 120);
  EXPECT_EQ(engine.status().speed.index, 1U);
  EXPECT_EQ(drive(data), 128);  // held back: not a jump from 160 to 192
  EXPECT_EQ(pivot(data), 128);
  EXPECT_EQ(engine.status().held_back, std::vector{*input::parse_axis_name("lefty")});  // leftx was at rest
  EXPECT_EQ(drive(engine.step(in, 160)), 128);                                          // still held
  apply_script(in, "170 axis lefty -16000\n");
  EXPECT_EQ(drive(engine.step(in, 200)), 128);  // moved, not at rest: still held
  apply_script(in, "210 axis leftx 16384\n");   // the pivot stick was at rest at the change: it acts
  EXPECT_EQ(pivot(engine.step(in, 240)), 160);
  apply_script(in, "250 axis lefty 0\n");
  EXPECT_EQ(drive(engine.step(in, 280)), 128);
  EXPECT_TRUE(engine.status().held_back.empty());
  apply_script(in, "290 axis lefty -32768\n");
  EXPECT_EQ(drive(engine.step(in, 320)), 192);  // 0.5, after rest
}

TEST(EngineSpeed, AChangeOfLevelHoldsBackOnlyDriveAndPivotSticks) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 axis rightx 32767\n50 axis leftx -32768\n");
  auto f = protocol::read_signals(engine.step(in, 80));
  EXPECT_EQ(f[protocol::signal_id("pt_right")], 1);
  apply_script(in, "90 button y 1\n");
  f = protocol::read_signals(engine.step(in, 120));
  EXPECT_EQ(f[protocol::signal_id("pt_right")], 1);  // a camera pair means the same at any level
  EXPECT_EQ(f[protocol::signal_id("pivot")], 128);
  EXPECT_EQ(engine.status().held_back, std::vector{*input::parse_axis_name("leftx")});
}

TEST(EngineSpeed, AChangeInALayerWithoutDriveHoldsNothingBack) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  apply_script(in, "50 button rightshoulder 1\n");  // the arm layer: lefty moves the shoulder
  engine.step(in, 80);
  apply_script(in, "90 axis lefty -32768\n");
  EXPECT_EQ(protocol::read_signals(engine.step(in, 120))[protocol::signal_id("shoulder_ccw")], 1);
  apply_script(in, "130 button y 1\n135 button y 0\n");
  auto f = protocol::read_signals(engine.step(in, 160));
  EXPECT_EQ(engine.status().speed.index, 1U);  // the level steps in every layer
  EXPECT_EQ(f[protocol::signal_id("shoulder_ccw")], 1);
  EXPECT_TRUE(engine.status().held_back.empty());
}

TEST(EngineSpeed, PressesWhileNotEnabledOrInTheEnablingFrameDoNothing) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  engine.step(in, 0);
  apply_script(in, "0 connect\n10 button y 1\n15 button y 0\n");
  engine.step(in, 40);  // connected, not enabled
  EXPECT_EQ(engine.status().speed.index, 0U);
  apply_script(in, "50 button y 1\n55 button y 0\n60 button leftshoulder 1\n");
  engine.step(in, 80);  // the enabling frame: its presses meant nothing yet
  EXPECT_EQ(engine.status().deadman, DeadmanState::kFreshHold);
  EXPECT_EQ(engine.status().speed.index, 0U);
  apply_script(in, "90 button y 1\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().speed.index, 1U);
}

TEST(EngineSpeed, AButtonHeldWhenEnabledWaitsForItsRelease) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml(kScale)), EngineOptions{});
  input::InputState in;
  start_enabled(engine, in, "15 button y 1\n");
  EXPECT_EQ(engine.status().held_back, std::vector{*input::parse_button_name("y")});
  engine.step(in, 80);
  EXPECT_EQ(engine.status().speed.index, 0U);
  apply_script(in, "90 button y 0\n100 button y 1\n");
  engine.step(in, 120);
  EXPECT_EQ(engine.status().speed.index, 1U);
}

TEST(EngineSpeed, KeptAcrossADeadmanReleaseBackToInitialOnANewPadAndARestart) {
  DrivenEngine engine(mapping_from_yaml(speed_yaml("scale: {button: y, levels: [0.25, 0.5, 1.0], initial: 0.5}\n")),
                      EngineOptions{});
  input::InputState in;
  start_enabled(engine, in);
  EXPECT_EQ(engine.status().speed.index, 1U);
  apply_script(in, "50 button y 1\n55 button y 0\n");
  engine.step(in, 80);
  EXPECT_EQ(engine.status().speed.index, 2U);

  apply_script(in, "90 button leftshoulder 0\n");  // released: not enabled, the level kept
  engine.step(in, 120);
  EXPECT_EQ(engine.status().deadman, DeadmanState::kReleased);
  EXPECT_EQ(engine.status().speed.index, 2U);
  apply_script(in, "130 button leftshoulder 1\n140 axis lefty -32768\n");
  engine.step(in, 160);  // enabled again: the stick pushed in the enabling frame waits
  apply_script(in, "170 axis lefty 0\n");
  engine.step(in, 200);
  apply_script(in, "210 axis lefty -32768\n");
  EXPECT_EQ(drive(engine.step(in, 240)), 255);  // still the fastest

  apply_script(in, "250 disconnect\n260 connect\n");  // another pad, between two frames
  engine.step(in, 280);
  EXPECT_EQ(engine.status().speed, (SpeedLevel{1, 3, 0.5}));  // the initial level, not the one chosen before

  apply_script(in, "290 button leftshoulder 0\n300 button leftshoulder 1\n310 button y 1\n315 button y 0\n");
  engine.step(in, 320);
  apply_script(in, "330 button y 1\n335 button y 0\n");
  engine.step(in, 360);
  EXPECT_EQ(engine.status().speed.index, 2U);
  engine.restart(in);  // the run loop's rebase (link regained, reload, resume)
  EXPECT_EQ(engine.status().speed.index, 1U);
}

}  // namespace
}  // namespace andros::mapping
